// SPDX-License-Identifier: GPL-3.0-or-later
// The CAN backends' parameters ([hardware] drive and sonar, [can]): the table (compiled once, not in every includer of the configuration).
#include "hal/linux/can/can_params.hpp"

namespace robuter {

std::span<const param::Param<HardwareConfig>> hardware_params() {
  using P = param::Param<HardwareConfig>;
  static constexpr P kRows[] = {
      P::word("drive", &HardwareConfig::drive, "none|can", "\"none\" or \"can\": the drives on CAN (CiA 402)"),
      P::word("sonar", &HardwareConfig::sonar, "none|can", "\"none\" or \"can\": the ultrasonic nodes on CAN"),
  };
  return kRows;
}

std::span<const param::Param<CanConfig>> can_params() {
  using P = param::Param<CanConfig>;
  static constexpr P kRows[] = {
      P::text("interface", &CanConfig::interface, "", "SocketCAN interface name"),
      P::integer("left_node", &CanConfig::left_node, "", 1, 127, "CANopen node id of the left wheel's drive, 1..127"),
      P::integer("right_node", &CanConfig::right_node, "", 1, 127, "node id of the right wheel's drive"),
      P::integer("sonar_node_base", &CanConfig::sonar_node_base, "", 1, 120, "node id of ring node 0; node n is base + n (7: pan-tilt channel)"),
      P::integer("counts_per_rev", &CanConfig::counts_per_rev, "increments", 1, 100'000'000, "encoder increments per wheel revolution (gearbox included)"),
      P::integer("wheel_diameter_mm", &CanConfig::wheel_diameter_mm, "mm", 10, 5000, "drive wheel diameter, mm"),
      P::flag("left_invert", &CanConfig::left_invert, "positive velocity turns the left wheel backwards"),
      P::flag("right_invert", &CanConfig::right_invert, "… the right wheel (mounted mirrored)"),
      P::integer("heartbeat_ms", &CanConfig::heartbeat_ms, "ms", 10, 10'000, "heartbeat producer time written to the drives, ms"),
      P::integer("heartbeat_timeout_ms", &CanConfig::heartbeat_timeout_ms, "ms", 20, 60'000, "a node silent this long is lost, ms"),
      P::integer("sdo_timeout_ms", &CanConfig::sdo_timeout_ms, "ms", 10, 10'000, "an unanswered SDO write is repeated after this, ms"),
      P::integer("fault_reset_ms", &CanConfig::fault_reset_ms, "ms", 10, 60'000, "a drive in fault gets a fault reset this often, ms"),
      P::integer("host_node", &CanConfig::host_node, "", 1, 127, "node id of robuterd's own heartbeat (0x700 + id), 1..127"),
      P::integer("host_heartbeat_ms", &CanConfig::host_heartbeat_ms, "ms", 10, 10'000, "robuterd's heartbeat period (sent only while every row runs on time), ms"),
      P::integer("drive_watchdog_ms", &CanConfig::drive_watchdog_ms, "ms", 0, 60'000, "consumer heartbeat time written to the drives (0x1016:01), ms; 0 = off"),
  };
  return kRows;
}

}  // namespace robuter
