// SPDX-License-Identifier: GPL-3.0-or-later
// The serial module's parameters: what operators may do ([permissions]) and the links ([links], [links.serial]).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hal/api/serial_port_params.hpp"
#include "kernel/param.hpp"

namespace robuter {

// What operators may do over the link.
struct PermissionsConfig {
  bool pass_through = false;                 // AY accepted at all
  std::vector<std::string> pass_through_allow;  // AY command prefixes allowed when enabled
  bool shutdown = true;                      // AX accepted
};

// [permissions]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<PermissionsConfig>> permissions_params();

// A serial command link ([links.serial]; docs/HARDWARE.md).
// (robuterd --serial overrides its device, --baud its rate.)
using SerialLinkConfig = hal::SerialPortConfig;

// [links.serial]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<SerialLinkConfig>> serial_link_params();

// Command links configured in the file ([links]).
struct LinksConfig {
  SerialLinkConfig serial;                   // [links.serial]
  bool stop_when_clients_leave = false;      // stop the robot when a pty's last client closes it (ARCOS does)
};

// [links]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<LinksConfig>> links_params();

}  // namespace robuter
