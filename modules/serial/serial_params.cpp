// SPDX-License-Identifier: GPL-3.0-or-later
// The serial module's parameters: what operators may do ([permissions]) and the links ([links], [links.serial]): the table (compiled once, not in every includer of the configuration).
#include "modules/serial/serial_params.hpp"

namespace robuter {

namespace {
constexpr param::Param<PermissionsConfig> kPermissionsParams[] = {
    {"pass_through", &PermissionsConfig::pass_through, "bool", 0, 0, "",
     "AY accepted at all"},
    {"pass_through_allow", &PermissionsConfig::pass_through_allow, "strings", 0, 0, "",
     "AY command prefixes allowed when enabled"},
    {"shutdown", &PermissionsConfig::shutdown, "bool", 0, 0, "",
     "AX accepted"},
};
}  // namespace

std::span<const param::Param<PermissionsConfig>> permissions_params() { return kPermissionsParams; }

namespace {
constexpr param::Param<SerialLinkConfig> kSerialLinkParams[] = {
    {"device", &SerialLinkConfig::device, "path", 0, 0, "",
     "its device, empty = none (robuterd --serial overrides)"},
    {"baud", &SerialLinkConfig::baud, "bit/s", 1200, 921'600, "",
     "line rate, bit/s (robuterd --baud overrides)"},
    {"parity", &SerialLinkConfig::parity, "", 0, 0, "none|even|odd",
     "none, even, odd"},
    {"stop_bits", &SerialLinkConfig::stop_bits, "", 1, 2, "",
     "1 or 2"},
    {"flow_control", &SerialLinkConfig::flow_control, "", 0, 0, "none|hardware|software",
     "none, hardware (RTS/CTS), software (XON/XOFF)"},
    {"retry_ms", &SerialLinkConfig::retry_ms, "ms", 10, 60'000, "",
     "a lost device is looked for this often, ms"},
};
}  // namespace

std::span<const param::Param<SerialLinkConfig>> serial_link_params() { return kSerialLinkParams; }

namespace {
constexpr param::Param<LinksConfig> kLinksParams[] = {
    {"stop_when_clients_leave", &LinksConfig::stop_when_clients_leave, "bool", 0, 0, "",
     "stop the robot when a pty's last client closes it (ARCOS does)"},
};
}  // namespace

std::span<const param::Param<LinksConfig>> links_params() { return kLinksParams; }

}  // namespace robuter
