// SPDX-License-Identifier: GPL-3.0-or-later
// The arbiter's loan of the robot from the planner to the door crossing (XQ at a narrow door).
#include <gtest/gtest.h>

#include "modules/emergency/motion_arbiter.hpp"

namespace robuter {
namespace {

using emergency::MotionArbiter;
constexpr std::size_t kPlanner = static_cast<std::size_t>(MotionSource::planner);
constexpr std::size_t kDoors = static_cast<std::size_t>(MotionSource::doors);

// Why: the arbiter with the planner driving (XG or XQ).
MotionArbiter planner_driving() {
  MotionArbiter a;
  a.take(OperatorAction::start_planner);
  return a;
}

// The loan: a new run of the crossing, the planner's run unchanged and not ended; the crossing
// ending by itself gives the same run back.
TEST(ArbiterLend, TheCrossingRunsAndGivesThePlannersRunBack) {
  MotionArbiter a = planner_driving();
  const std::uint32_t planner_run = a.authority().runs[kPlanner];
  a.lend_to_doors();
  EXPECT_EQ(a.authority().owner, MotionSource::doors);
  EXPECT_EQ(a.authority().lent_by, MotionSource::planner);
  EXPECT_EQ(a.authority().runs[kDoors], 1u);
  EXPECT_EQ(a.authority().runs[kPlanner], planner_run);
  EXPECT_EQ(a.authority().ended[kPlanner], ModeReason::none);
  EXPECT_TRUE(a.accepts(MotionSource::doors));
  EXPECT_FALSE(a.accepts(MotionSource::planner));  // the planner's requests are dropped meanwhile
  a.give_back();
  EXPECT_EQ(a.authority().owner, MotionSource::planner);
  EXPECT_EQ(a.authority().lent_by, MotionSource::link);
  EXPECT_EQ(a.authority().runs[kPlanner], planner_run);
}

// Only the planner lends, and only the crossing gives back what was lent.
TEST(ArbiterLend, NothingElseLendsOrGivesBack) {
  MotionArbiter idle;
  idle.lend_to_doors();
  EXPECT_EQ(idle.authority().owner, MotionSource::link);
  MotionArbiter ad;
  ad.take(OperatorAction::start_doors);  // Ad: the operator's crossing, nobody's loan
  ad.give_back();
  EXPECT_EQ(ad.authority().owner, MotionSource::doors);
  MotionArbiter gate;
  gate.take(OperatorAction::start_gate);
  gate.lend_to_doors();
  EXPECT_EQ(gate.authority().owner, MotionSource::gate);
}

// Whatever ends the crossing early ends the planner's run too, with the same reason: the
// operator's motion, XH and Af (both are the route's stops: cancelled), an emergency; and a
// later give_back() finds nothing to give.
TEST(ArbiterLend, EveryEarlyEndOfTheCrossingEndsTheRoute) {
  struct Case {
    const char* name;
    void (*end)(MotionArbiter&);
    ModeReason why;
  };
  const Case cases[] = {
      {"AM", [](MotionArbiter& a) { a.take(OperatorAction::motion); }, ModeReason::operator_motion},
      {"stop byte", [](MotionArbiter& a) { a.take(OperatorAction::stop_byte); }, ModeReason::operator_motion},
      {"XH", [](MotionArbiter& a) { a.take(OperatorAction::halt); }, ModeReason::cancelled},
      {"Af", [](MotionArbiter& a) { a.take(OperatorAction::stop_doors); }, ModeReason::cancelled},
      {"AT", [](MotionArbiter& a) { a.take(OperatorAction::stop_gate); }, ModeReason::operator_motion},
      {"emergency", [](MotionArbiter& a) { a.emergency_stop(); }, ModeReason::emergency},
      {"lost actions", [](MotionArbiter& a) { a.lost_actions(); }, ModeReason::operator_motion},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    MotionArbiter a = planner_driving();
    a.lend_to_doors();
    c.end(a);
    EXPECT_EQ(a.authority().owner, MotionSource::link);
    EXPECT_EQ(a.authority().lent_by, MotionSource::link);
    EXPECT_EQ(a.authority().ended[kDoors], c.why);
    EXPECT_EQ(a.authority().ended[kPlanner], c.why);
    a.give_back();
    EXPECT_EQ(a.authority().owner, MotionSource::link);  // nothing resumes by itself
  }
  // A new XG while lent: the old route and the crossing end, the new run is the planner's own.
  MotionArbiter a = planner_driving();
  a.lend_to_doors();
  a.take(OperatorAction::start_planner);
  EXPECT_EQ(a.authority().owner, MotionSource::planner);
  EXPECT_EQ(a.authority().lent_by, MotionSource::link);
  EXPECT_EQ(a.authority().ended[kDoors], ModeReason::operator_motion);
}

}  // namespace
}  // namespace robuter
