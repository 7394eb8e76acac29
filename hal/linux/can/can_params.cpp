// SPDX-License-Identifier: GPL-3.0-or-later
// The CAN backends' parameters ([hardware] drive and sonar, [can]): the table (compiled once, not in every includer of the configuration).
#include "hal/linux/can/can_params.hpp"

namespace robuter {

namespace {
constexpr param::Param<HardwareConfig> kHardwareParams[] = {
    {"drive", &HardwareConfig::drive, "", 0, 0, "none|can",
     "\"none\" or \"can\": the drives on CAN (CiA 402)"},
    {"sonar", &HardwareConfig::sonar, "", 0, 0, "none|can",
     "\"none\" or \"can\": the ultrasonic nodes on CAN"},
};
}  // namespace

std::span<const param::Param<HardwareConfig>> hardware_params() { return kHardwareParams; }

namespace {
constexpr param::Param<CanConfig> kCanParams[] = {
    {"interface", &CanConfig::interface, "", 0, 0, "",
     "SocketCAN interface name"},
    {"left_node", &CanConfig::left_node, "", 1, 127, "",
     "CANopen node id of the left wheel's drive, 1..127"},
    {"right_node", &CanConfig::right_node, "", 1, 127, "",
     "node id of the right wheel's drive"},
    {"sonar_node_base", &CanConfig::sonar_node_base, "", 1, 120, "",
     "node id of ring node 0; node n is base + n (7: pan-tilt channel)"},
    {"counts_per_rev", &CanConfig::counts_per_rev, "increments", 1, 100'000'000, "",
     "encoder increments per wheel revolution (gearbox included)"},
    {"wheel_diameter_mm", &CanConfig::wheel_diameter_mm, "mm", 10, 5000, "",
     "drive wheel diameter, mm"},
    {"left_invert", &CanConfig::left_invert, "bool", 0, 0, "",
     "positive velocity turns the left wheel backwards"},
    {"right_invert", &CanConfig::right_invert, "bool", 0, 0, "",
     "… the right wheel (mounted mirrored)"},
    {"heartbeat_ms", &CanConfig::heartbeat_ms, "ms", 10, 10'000, "",
     "heartbeat producer time written to the drives, ms"},
    {"heartbeat_timeout_ms", &CanConfig::heartbeat_timeout_ms, "ms", 20, 60'000, "",
     "a node silent this long is lost, ms"},
    {"sdo_timeout_ms", &CanConfig::sdo_timeout_ms, "ms", 10, 10'000, "",
     "an unanswered SDO write is repeated after this, ms"},
    {"fault_reset_ms", &CanConfig::fault_reset_ms, "ms", 10, 60'000, "",
     "a drive in fault gets a fault reset this often, ms"},
    {"host_node", &CanConfig::host_node, "", 1, 127, "",
     "node id of robuterd's own heartbeat (0x700 + id), 1..127"},
    {"host_heartbeat_ms", &CanConfig::host_heartbeat_ms, "ms", 10, 10'000, "",
     "robuterd's heartbeat period (sent only while every row runs on time), ms"},
    {"drive_watchdog_ms", &CanConfig::drive_watchdog_ms, "ms", 0, 60'000, "",
     "consumer heartbeat time written to the drives (0x1016:01), ms; 0 = off"},
};
}  // namespace

std::span<const param::Param<CanConfig>> can_params() { return kCanParams; }

}  // namespace robuter
