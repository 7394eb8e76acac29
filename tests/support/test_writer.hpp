// SPDX-License-Identifier: GPL-3.0-or-later
// Tests only: a topic's writer without being its owner, for tests that stand in for a module.
// kernel/blackboard.hpp declares TestWriterAccess and never defines it; this header, included by
// test targets only, does (tests/kernel/compile_fail/ shows the firmware cannot name it).
#pragma once

#include "kernel/blackboard.hpp"

namespace robuter {

template <typename T, typename Owner>
struct TestWriterAccess<Topic<T, Owner>> {
  static Writer<T> writer(Topic<T, Owner>& t) { return t.writer(); }
};

// The writer of `t`, claimed for the test (the one claim the topic allows).
template <typename T, typename Owner>
Writer<T> test_writer(Topic<T, Owner>& t) {
  return TestWriterAccess<Topic<T, Owner>>::writer(t);
}

}  // namespace robuter
