// SPDX-License-Identifier: GPL-3.0-or-later
// A mode's motion requests (modules/emergency/mode_requests.hpp): each request (or each with new speeds) wakes the emergency module in its tick, a run's end sends one zero, nothing before a run.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "kernel/clock.hpp"
#include "kernel/kernel.hpp"
#include "modules/emergency/mode_requests.hpp"
#include "tests/support/test_writer.hpp"

namespace robuter {
namespace {

// Counts its runs: it is only ever run when triggered (its row is never due in the test).
struct Woken final : Process {
  int runs = 0;
  void run(Kernel&) override { ++runs; }
};

// Runs one scripted step of the mode per tick.
struct Mode final : Process {
  std::function<void(Kernel&)> step;
  void run(Kernel& k) override {
    if (step) step(k);
  }
};

struct Rig {
  explicit Rig(ModeRequests::Wake wake = ModeRequests::Wake::every_request) : requests(test_writer(topic), wake) {
    requests.set_emergency(&woken);
    const ProcessRow rows[] = {{"mode", &mode, 1, 0, 2, 1000}, {"emergency", &woken, 1000, 999, 1, 1000}};
    ok = !kernel.set_table(rows);
  }
  // Runs one tick whose mode step is `f`; returns how many requests it published.
  std::uint32_t tick(const std::function<void(Kernel&)>& f) {
    const std::uint32_t before = topic.reader().generation();
    mode.step = f;
    kernel.step();
    return topic.reader().generation() - before;
  }
  VirtualClock clock;
  Kernel kernel{clock, 10 * kNanosPerMilli};
  Topic<MotionRequest, Mode> topic;
  ModeRequests requests;
  Woken woken;
  Mode mode;
  bool ok = false;
};

TEST(ModeRequests, ARunsRequestsWakeTheEmergencyModuleAndItsEndSendsOneZero) {
  Rig r;
  ASSERT_TRUE(r.ok);
  // No run yet: "no request" sends nothing (no zero request before a run).
  EXPECT_EQ(r.tick([&](Kernel& k) { r.requests.send(k, false, 0, 0); }), 0u);
  EXPECT_EQ(r.woken.runs, 0);
  r.requests.begin();
  EXPECT_EQ(r.tick([&](Kernel& k) { r.requests.send(k, true, 10, -5); }), 1u);
  EXPECT_EQ(r.woken.runs, 1);  // woken in the same tick
  EXPECT_EQ(r.topic.reader().peek().left, 10);
  EXPECT_EQ(r.topic.reader().peek().right, -5);
  EXPECT_EQ(r.tick([&](Kernel& k) { r.requests.send(k, true, 10, -5); }), 1u);  // a repeat counts
  EXPECT_EQ(r.woken.runs, 2);
  // The run ends: one zero request, then nothing however often the mode says "no request".
  EXPECT_EQ(r.tick([&](Kernel& k) { r.requests.send(k, false, 7, 7); }), 1u);
  EXPECT_EQ(r.topic.reader().peek().left, 0);
  EXPECT_EQ(r.topic.reader().peek().right, 0);
  EXPECT_EQ(r.woken.runs, 3);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(r.tick([&](Kernel& k) { r.requests.send(k, false, 0, 0); }), 0u);
  EXPECT_EQ(r.woken.runs, 3);
  // A new run sends its own final zero again.
  r.requests.begin();
  EXPECT_EQ(r.tick([&](Kernel& k) { r.requests.send(k, false, 0, 0); }), 1u);
  EXPECT_EQ(r.topic.reader().peek().tick, r.kernel.tick() - 1);
}

// The planner's rule: it repeats its speeds at each activation, and only new speeds (a stop above
// all) wake the emergency module; every request is still published.
TEST(ModeRequests, NewSpeedsWakeTheEmergencyModuleWhenTheSourceRepeatsItself) {
  Rig r(ModeRequests::Wake::new_speeds);
  ASSERT_TRUE(r.ok);
  r.requests.begin();
  EXPECT_EQ(r.tick([&](Kernel& k) { r.requests.send(k, true, 10, 10); }), 1u);
  EXPECT_EQ(r.woken.runs, 1);
  EXPECT_EQ(r.tick([&](Kernel& k) { r.requests.send(k, true, 10, 10); }), 1u);  // published, not woken
  EXPECT_EQ(r.woken.runs, 1);
  EXPECT_EQ(r.tick([&](Kernel& k) { r.requests.send(k, true, 10, 12); }), 1u);
  EXPECT_EQ(r.woken.runs, 2);
  EXPECT_EQ(r.tick([&](Kernel& k) { r.requests.send(k, false, 10, 12); }), 1u);  // the final zero: a stop
  EXPECT_EQ(r.woken.runs, 3);
  EXPECT_EQ(r.requests.left(), 0);
  EXPECT_EQ(r.requests.right(), 0);
}

}  // namespace
}  // namespace robuter
