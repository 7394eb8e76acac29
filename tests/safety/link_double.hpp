// SPDX-License-Identifier: GPL-3.0-or-later
// Test stand-in for the serial module: holds the link's topics' writers (claimed through the
// tests' accessor, tests/support/test_writer.hpp) and publishes what the link would.
#pragma once

#include <cstdint>

#include "kernel/kernel.hpp"
#include "modules/topics.hpp"
#include "tests/support/test_writer.hpp"

namespace robuter {

// Publishes what the link would publish for each protocol command; optionally triggers the
// emergency module like a link that wants a same-tick reaction.
class LinkDouble {
 public:
  LinkDouble(Blackboard& bb, Kernel& k)
      : k_(k),
        motion_(test_writer(bb.link_motion)),
        servo_(test_writer(bb.servo_request)),
        odometry_(test_writer(bb.odometry_set)),
        go_to_(test_writer(bb.go_to)),
        us_(test_writer(bb.us_settings)),
        status_(test_writer(bb.link_status)),
        events_(test_writer(bb.operator_events)) {}

  // An operator's action for the motion arbiter, as the link port records it.
  void act(OperatorAction a) {
    const std::uint64_t t = k_.tick();
    events_.modify([&](OperatorEvents& e) {
      e.ring[e.count % OperatorEvents::kCapacity] = OperatorEvent{a, t};
      ++e.count;
    });
  }

  // Any well-formed message: the communication watchdog's time stamp.
  void message() {
    const std::uint64_t t = k_.tick();
    status_.modify([&](LinkStatus& s) { s.last_message_tick = t; });
  }
  // AM left right.
  void am(std::int32_t left, std::int32_t right) {
    message();
    motion_.publish(MotionRequest{left, right, k_.tick()});
    act(OperatorAction::motion);
  }
  // ASN / ASF.
  void as(bool on) {
    message();
    servo_.publish(ServoRequest{on});
    act(OperatorAction::servo);
  }
  // AC x y theta.
  void ac(std::int32_t x, std::int32_t y, std::int32_t theta) {
    message();
    odometry_.publish(OdometrySet{x, y, theta});
  }
  // AW x y theta (active) or a cancel.
  void aw(std::int32_t x, std::int32_t y, std::int32_t theta, bool active = true) {
    message();
    go_to_.publish(GoToRequest{x, y, theta, active});
    if (active) act(OperatorAction::go_to);
  }
  // UT table (bit s-1 = sensor s).
  void ut(std::uint32_t table) {
    message();
    us_.modify([&](UltrasonicSettings& s) { s.user_table = table; });
  }
  // Uu on/off.
  void uu(bool on) {
    message();
    us_.modify([&](UltrasonicSettings& s) { s.auto_toggle = on; });
  }
  // UD ticks.
  void ud(std::uint32_t ticks) {
    message();
    us_.modify([&](UltrasonicSettings& s) { s.node_delay_ticks = ticks; });
  }
  // The settings as the real serial module publishes them at construction.
  void settings(const UltrasonicSettings& s) { us_.publish(s); }
  // XR.
  void xr() {
    message();
    status_.modify([](LinkStatus& s) { ++s.reenable_seq; });
  }
  // The stop byte (not a message).
  void stop_byte() {
    status_.modify([](LinkStatus& s) { ++s.stop_seq; });
    act(OperatorAction::stop_byte);
  }

 private:
  Kernel& k_;
  Writer<MotionRequest> motion_;
  Writer<ServoRequest> servo_;
  Writer<OdometrySet> odometry_;
  Writer<GoToRequest> go_to_;
  Writer<UltrasonicSettings> us_;
  Writer<LinkStatus> status_;
  Writer<OperatorEvents> events_;
};

}  // namespace robuter
