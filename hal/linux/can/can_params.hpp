// SPDX-License-Identifier: GPL-3.0-or-later
// The CAN backends' parameters ([hardware] drive and sonar, [can]).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"

namespace robuter {

// Which hardware backends robuterd uses without --sim (docs/CAN.md).
struct HardwareConfig {
  std::string drive = "none";                // "none" or "can": the drives on CAN (CiA 402)
  std::string sonar = "none";                // "none" or "can": the ultrasonic nodes on CAN
};

// [hardware]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<HardwareConfig>> hardware_params();

// The CAN bus, its CiA 402 drives and ultrasonic nodes (docs/CAN.md).
struct CanConfig {
  std::string interface = "can0";            // SocketCAN interface name
  std::uint32_t left_node = 1;               // CANopen node id of the left wheel's drive, 1..127
  std::uint32_t right_node = 2;              // node id of the right wheel's drive
  std::uint32_t sonar_node_base = 16;        // node id of ring node 0; node n is base + n (7: pan-tilt channel)
  std::uint32_t counts_per_rev = 16384;      // encoder increments per wheel revolution (gearbox included)
  std::uint32_t wheel_diameter_mm = 200;     // drive wheel diameter, mm
  bool left_invert = false;                  // positive velocity turns the left wheel backwards
  bool right_invert = true;                  // … the right wheel (mounted mirrored)
  std::uint32_t heartbeat_ms = 100;          // heartbeat producer time written to the drives, ms
  std::uint32_t heartbeat_timeout_ms = 350;  // a node silent this long is lost, ms
  std::uint32_t sdo_timeout_ms = 100;        // an unanswered SDO write is repeated after this, ms
  std::uint32_t fault_reset_ms = 1000;       // a drive in fault gets a fault reset this often, ms
  std::uint32_t host_node = 127;             // node id of robuterd's own heartbeat (0x700 + id), 1..127
  std::uint32_t host_heartbeat_ms = 50;      // robuterd's heartbeat period (sent only while every row runs on time), ms
  std::uint32_t drive_watchdog_ms = 300;     // consumer heartbeat time written to the drives (0x1016:01), ms; 0 = off
};

// [can]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<CanConfig>> can_params();

}  // namespace robuter
