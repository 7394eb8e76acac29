// SPDX-License-Identifier: GPL-3.0-or-later
// The robot port: everything the protocol's messages read or change, as an abstract interface.
#pragma once

#include <string_view>

#include "protocol/codec/port_types.hpp"

namespace robuter::protocol {

// Implemented by the serial module over the blackboards (and by fakes in tests). The codec
// calls it only while handling a line, from the thread that feeds the codec. Reads are const;
// requests return a PortResult that becomes `ack` or `error`. Nothing here may throw.
class RobotPort {
 public:
  virtual ~RobotPort() = default;

  // ---- reads (B requests, U queries, status stream) ----
  virtual Ticks clock() const noexcept = 0;                     // ticks of 10 ms since start
  virtual Posture posture() const noexcept = 0;                 // odometry
  virtual bool servo_on() const noexcept = 0;                   // servo (brake) status
  virtual WheelSpeeds wheel_speeds() const noexcept = 0;        // speeds in force, cm/s
  virtual void ranges(Ranges& out) const noexcept = 0;          // 24 ultrasonic ranges, mm
  virtual std::int32_t us_timeout() const noexcept = 0;         // ultrasonic time-out, ms
  // Fills one of the 72-sector pan-tilt arrays; not ok (unavailable) when no pan-tilt.
  virtual PortResult pan_tilt(SectorKind kind, Sectors& out) const noexcept = 0;
  virtual std::int32_t node_delay() const noexcept = 0;         // node firing delay, ticks
  virtual std::int32_t mean_node_time() const noexcept = 0;     // mean read of one node, ticks
  virtual std::int32_t mean_scan_time() const noexcept = 0;     // mean read of six nodes, ticks

  // ---- requests (A and U commands) ----
  // Wheel speeds, cm/s; always through the emergency module's request-to-move.
  virtual PortResult request_motion(std::int32_t left, std::int32_t right) noexcept = 0;
  virtual PortResult set_servo(bool on) noexcept = 0;          // ASN (on) / ASF (off)
  // A raw line for the low-level controller; not_permitted unless configured and allowed.
  virtual PortResult pass_through(std::string_view line) noexcept = 0;
  virtual PortResult set_odometry(const Posture& posture) noexcept = 0;  // AC
  virtual PortResult go_to(const Posture& target) noexcept = 0;          // AW
  // AX: shut down cleanly once the `ack` has been written.
  virtual PortResult request_shutdown() noexcept = 0;
  virtual PortResult set_pan_tilt(bool on) noexcept = 0;       // Ap / Ag
  virtual PortResult set_gate_finder(bool on) noexcept = 0;    // AG / AT
  virtual PortResult set_door_crossing(bool on) noexcept = 0;  // Ad / Af
  virtual PortResult set_demo(bool on) noexcept = 0;           // XT1 / XT0
  virtual PortResult set_sensor_table(const SensorTable& active) noexcept = 0;  // UT
  virtual PortResult set_node_delay(std::int32_t ticks) noexcept = 0;          // UD
  virtual PortResult set_us_timeout(std::int32_t ms) noexcept = 0;             // Ut
  virtual PortResult set_auto_toggle(bool on) noexcept = 0;                    // Uu

  // ---- link events ----
  // A complete line arrived (valid or not, as the seed): stamp it for the communication-loss
  // watchdog. Called by the codec before the line is handled.
  virtual void message_received() noexcept = 0;
  // The immediate stop byte (0x18) arrived: stop the robot now; no reply is written.
  virtual void immediate_stop() noexcept = 0;

  // ---- extensions (X) ----
  virtual EmergencyStatus emergency() const noexcept = 0;       // XE
  virtual PortResult reenable() noexcept = 0;                   // XR: clear a latched emergency
  virtual KernelFigures kernel_figures() const noexcept = 0;    // XK
  virtual std::string_view firmware_version() const noexcept = 0;  // XV, e.g. "0.1.0"
  virtual std::uint32_t features() const noexcept = 0;          // XV, kFeature* bits

  // ---- extensions (X): the grid planner; a port without one answers unavailable ----
  // XG: navigate to goal.x, goal.y (0.1 mm), then turn to goal.theta when `with_theta`.
  virtual PortResult set_goal(const Posture& goal, bool with_theta) noexcept {
    (void)goal;
    (void)with_theta;
    return PortResult::unavailable;
  }
  virtual PortResult cancel_goal() noexcept { return PortResult::unavailable; }  // XH
  virtual PortResult planner_status(PlannerReport& out) const noexcept {         // XP
    (void)out;
    return PortResult::unavailable;
  }
  virtual PortResult planner_map(MapWindow& out) const noexcept {                // XM
    (void)out;
    return PortResult::unavailable;
  }
  // ---- extensions (X): the place graph ([places] file); without one: unavailable ----
  virtual PortResult place_here(PlaceReport& out) const noexcept {               // XN
    (void)out;
    return PortResult::unavailable;
  }
  // XI: place `number` (1-based); out_of_range past the last.
  virtual PortResult place_info(std::int32_t number, PlaceReport& out) const noexcept {
    (void)number;
    (void)out;
    return PortResult::unavailable;
  }

  // XQ: go to place `number` (1-based) over the place graph's route, through the planner;
  // out_of_range for no such place, the robot outside every place, or no route that the
  // planner's window can follow; refused_emergency while latched (as XG). `explore`: seed 003's
  // exploration of that route (a full turn and a scan at each place's centre, docs/PLACES.md).
  virtual PortResult go_to_place(std::int32_t number, bool explore) noexcept {
    (void)number;
    (void)explore;
    return PortResult::unavailable;
  }

  // ---- extensions (X): localisation on the map ([localise]); without it: unavailable ----
  virtual PortResult localisation(LocaliseReport& out) const noexcept {  // XW
    (void)out;
    return PortResult::unavailable;
  }
  // XA x y theta: the robot is at this map pose (0.1 mm, 0.01 degree); XA alone (`global`):
  // search the whole map for it.
  virtual PortResult set_map_pose(const Posture& pose, bool global) noexcept {
    (void)pose;
    (void)global;
    return PortResult::unavailable;
  }

  // ---- extensions (X): pan-tilt, passage finder and door crossing states (XD) ----
  virtual PortResult modes(ModesReport& out) const noexcept {
    (void)out;
    return PortResult::unavailable;
  }
};

}  // namespace robuter::protocol
