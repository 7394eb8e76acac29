// SPDX-License-Identifier: GPL-3.0-or-later
// A scriptable RobotPort for tests, fuzzing and benchmarks: fixed values in, calls recorded.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "protocol/codec/robot_port.hpp"

namespace robuter::protocol::testing {

// Every read returns a public field; every request records its arguments and returns
// `result` (or the per-request field). Fixed storage only, so it never allocates.
class FakeRobotPort final : public RobotPort {
 public:
  // ---- what reads return ----
  Ticks now = 1523;                          // clock, ticks
  Posture pose{1204, -3, 12};                // odometry, 0.1 mm / 0.01 degree
  bool servo = true;                         // servo status
  WheelSpeeds speeds{10, 10};                // cm/s
  Ranges us{};                               // mm
  std::int32_t timeout_ms = 33;              // ultrasonic time-out, ms
  bool has_pan_tilt = true;                  // pan_tilt() answers unavailable when false
  Sectors raw{}, filtered{}, differences{};  // pan-tilt arrays, mm
  std::int32_t delay_ticks = 3;              // node delay, ticks
  std::int32_t node_time = 4;                // mean node read, ticks
  std::int32_t scan_time = 29;               // mean full scan, ticks
  EmergencyStatus emerg{false, false, EmergencyCause::none, kDetectAll};
  std::array<ProcessFigures, 3> processes{{{"serial", 100, 0, 0, 12, 40},
                                           {"emergency", 50, 1, 2, 30, 95},
                                           {"execute", 50, 0, 0, 20, 60}}};
  std::size_t process_count = 3;             // how many of `processes` to report
  KernelFigures kernel{1000, 180, 42, {}};   // processes filled in by kernel_figures()
  std::string_view version = "0.1.0";        // firmware version
  std::uint32_t feature_bits = kFeaturePanTilt | kFeatureGate | kFeatureDoors;
  bool has_planner = true;                   // planner calls answer unavailable when false
  PlannerReport planner{PlannerState::moving, 150000, 55000, 13950, 1480, 3, 4, 812, 4650};
  std::array<char, kMapWindowSide * kMapWindowSide> map_cells{};  // XM window, filled by the constructor
  std::int32_t place_count = 0;              // places in the graph; 0: no place graph (XN, XI unavailable)
  PlaceReport here{};                        // XN answer (count filled in)
  std::int32_t last_place_goal = 0;          // last XQ accepted by the checks above
  bool last_place_explore = false;           // its exploration flag (XQ <n> 1)
  PlaceReport info{};                        // XI answer (count and number filled in)

  // ---- what requests return ----
  PortResult result = PortResult::ok;          // default answer of every request
  PortResult motion_result = PortResult::ok;   // answer of request_motion
  PortResult place_goal_result = PortResult::ok;  // answer of go_to_place past its checks
  PortResult pass_result = PortResult::not_permitted;  // answer of pass_through

  // ---- what requests recorded ----
  int calls = 0;                     // requests received
  int messages = 0;                  // message_received() calls
  int stops = 0;                     // immediate_stop() calls
  int shutdowns = 0;                 // request_shutdown() calls
  WheelSpeeds last_motion{};         // last request_motion, cm/s
  int motion_requests = 0;           // request_motion calls
  bool last_servo = false;           // last set_servo
  std::array<char, 256> pass_text{};  // last pass_through text
  std::size_t pass_length = 0;       // its length
  Posture last_odometry{};           // last set_odometry
  Posture last_goal{};               // last go_to
  bool pan_tilt_on = false, gate_on = false, doors_on = false, demo_on = false;  // last switch values
  SensorTable last_table{};          // last set_sensor_table
  std::int32_t last_delay = -1;      // last set_node_delay, ticks
  std::int32_t last_timeout = -1;    // last set_us_timeout, ms
  bool auto_toggle = false;          // last set_auto_toggle
  int reenables = 0;                 // reenable() calls
  Posture last_planner_goal{};       // last set_goal
  bool last_goal_theta = false;      // its with_theta
  int goals = 0;                     // set_goal calls
  int goal_cancels = 0;              // cancel_goal calls

  // A window of free cells with one obstacle row at the top, the robot in the middle.
  FakeRobotPort() {
    map_cells.fill(' ');
    for (int c = 0; c < kMapWindowSide; ++c) map_cells[static_cast<std::size_t>(c)] = '#';
    map_cells[static_cast<std::size_t>(kMapWindowSide * kMapWindowSide / 2)] = 'P';
  }

  // The last pass-through text as a view.
  std::string_view passed() const { return {pass_text.data(), pass_length}; }

  Ticks clock() const noexcept override { return now; }
  Posture posture() const noexcept override { return pose; }
  bool servo_on() const noexcept override { return servo; }
  WheelSpeeds wheel_speeds() const noexcept override { return speeds; }
  void ranges(Ranges& out) const noexcept override { out = us; }
  std::int32_t us_timeout() const noexcept override { return timeout_ms; }
  PortResult pan_tilt(SectorKind kind, Sectors& out) const noexcept override {
    if (!has_pan_tilt) return PortResult::unavailable;
    out = kind == SectorKind::raw ? raw : kind == SectorKind::filtered ? filtered : differences;
    return PortResult::ok;
  }
  std::int32_t node_delay() const noexcept override { return delay_ticks; }
  std::int32_t mean_node_time() const noexcept override { return node_time; }
  std::int32_t mean_scan_time() const noexcept override { return scan_time; }

  PortResult request_motion(std::int32_t left, std::int32_t right) noexcept override {
    ++calls;
    ++motion_requests;
    last_motion = {left, right};
    return motion_result;
  }
  PortResult set_servo(bool on) noexcept override { return record(last_servo, on); }
  PortResult pass_through(std::string_view line) noexcept override {
    ++calls;
    pass_length = line.size() < pass_text.size() ? line.size() : pass_text.size();
    for (std::size_t i = 0; i < pass_length; ++i) pass_text[i] = line[i];
    return pass_result;
  }
  PortResult set_odometry(const Posture& p) noexcept override { return record(last_odometry, p); }
  PortResult go_to(const Posture& p) noexcept override { return record(last_goal, p); }
  PortResult request_shutdown() noexcept override {
    ++calls;
    ++shutdowns;
    return result;
  }
  PortResult set_pan_tilt(bool on) noexcept override { return record(pan_tilt_on, on); }
  PortResult set_gate_finder(bool on) noexcept override { return record(gate_on, on); }
  PortResult set_door_crossing(bool on) noexcept override { return record(doors_on, on); }
  PortResult set_demo(bool on) noexcept override { return record(demo_on, on); }
  PortResult set_sensor_table(const SensorTable& t) noexcept override {
    return record(last_table, t);
  }
  PortResult set_node_delay(std::int32_t t) noexcept override { return record(last_delay, t); }
  PortResult set_us_timeout(std::int32_t ms) noexcept override {
    return record(last_timeout, ms);
  }
  PortResult set_auto_toggle(bool on) noexcept override { return record(auto_toggle, on); }

  void message_received() noexcept override { ++messages; }
  void immediate_stop() noexcept override { ++stops; }

  EmergencyStatus emergency() const noexcept override { return emerg; }
  PortResult reenable() noexcept override {
    ++calls;
    ++reenables;
    return result;
  }
  KernelFigures kernel_figures() const noexcept override {
    KernelFigures k = kernel;
    k.processes = std::span<const ProcessFigures>(processes.data(),
                                                  process_count < processes.size()
                                                      ? process_count
                                                      : processes.size());
    return k;
  }
  std::string_view firmware_version() const noexcept override { return version; }
  std::uint32_t features() const noexcept override { return feature_bits; }
  PortResult set_goal(const Posture& goal, bool with_theta) noexcept override {
    if (!has_planner) return PortResult::unavailable;
    ++goals;
    last_goal_theta = with_theta;
    return record(last_planner_goal, goal);
  }
  PortResult cancel_goal() noexcept override {
    if (!has_planner) return PortResult::unavailable;
    ++calls;
    ++goal_cancels;
    return result;
  }
  PortResult planner_status(PlannerReport& out) const noexcept override {
    if (!has_planner) return PortResult::unavailable;
    out = planner;
    return PortResult::ok;
  }
  PortResult planner_map(MapWindow& out) const noexcept override {
    if (!has_planner) return PortResult::unavailable;
    out = MapWindow{kMapWindowSide, 50, -12345, 67890, std::string_view(map_cells.data(), map_cells.size())};
    return PortResult::ok;
  }
  PortResult place_here(PlaceReport& out) const noexcept override {
    if (place_count == 0) return PortResult::unavailable;
    out = here;
    out.count = place_count;
    return PortResult::ok;
  }
  PortResult go_to_place(std::int32_t number, bool explore) noexcept override {
    if (place_count == 0) return PortResult::unavailable;
    if (number > place_count) return PortResult::out_of_range;
    if (place_goal_result == PortResult::ok) {
      last_place_goal = number;
      last_place_explore = explore;
    }
    return place_goal_result;
  }
  PortResult place_info(std::int32_t number, PlaceReport& out) const noexcept override {
    if (place_count == 0) return PortResult::unavailable;
    if (number > place_count) return PortResult::out_of_range;
    out = info;
    out.count = place_count;
    out.number = number;
    return PortResult::ok;
  }

 private:
  // Stores a request's argument and returns the scripted answer.
  template <class T>
  PortResult record(T& slot, const T& value) noexcept {
    ++calls;
    slot = value;
    return result;
  }
};

}  // namespace robuter::protocol::testing
