// SPDX-License-Identifier: GPL-3.0-or-later
// The serial module's parameters: what operators may do ([permissions]) and the links ([links], [links.serial]): the table (compiled once, not in every includer of the configuration).
#include "modules/serial/serial_params.hpp"

namespace robuter {

std::span<const param::Param<PermissionsConfig>> permissions_params() {
  using P = param::Param<PermissionsConfig>;
  static constexpr P kRows[] = {
      P::flag("pass_through", &PermissionsConfig::pass_through, "AY accepted at all"),
      P::text("pass_through_allow", &PermissionsConfig::pass_through_allow, "strings", "AY command prefixes allowed when enabled"),
      P::flag("shutdown", &PermissionsConfig::shutdown, "AX accepted"),
  };
  return kRows;
}

std::span<const param::Param<SerialLinkConfig>> serial_link_params() {
  static constexpr auto kRows = hal::serial_port_rows<SerialLinkConfig>(
      "device", "its device, empty = none (robuterd --serial overrides)", "line rate, bit/s (robuterd --baud overrides)");
  return kRows;
}

std::span<const param::Param<LinksConfig>> links_params() {
  using P = param::Param<LinksConfig>;
  static constexpr P kRows[] = {
      P::flag("stop_when_clients_leave", &LinksConfig::stop_when_clients_leave, "stop the robot when a pty's last client closes it (ARCOS does)"),
  };
  return kRows;
}

}  // namespace robuter
