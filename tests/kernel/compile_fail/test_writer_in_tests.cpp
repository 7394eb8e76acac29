// SPDX-License-Identifier: GPL-3.0-or-later
// Must compile: the control case of test_writer_outside_tests.cpp, with the tests' header.
#include "kernel/blackboard.hpp"
#include "tests/support/test_writer.hpp"

struct Posture {
  int x = 0;  // 0.1 mm
};
class Executor;  // the owner
using PostureTopic = robuter::Topic<Posture, Executor>;

int main() {
  PostureTopic t;
  robuter::Writer<Posture> w = robuter::TestWriterAccess<PostureTopic>::writer(t);
  w.publish(Posture{1});
  robuter::Writer<Posture> again = robuter::test_writer(t);  // a second claim: empty, counted
  return t.reader().peek().x == 1 && !again.valid() && t.claims() == 2 ? 0 : 1;
}
