// SPDX-License-Identifier: GPL-3.0-or-later
// Handlers of the place graph's X extensions: the robot's place (XN), one place (XI), go to a place (XQ).
#include "protocol/codec/handlers.hpp"

#include <algorithm>

namespace robuter::protocol {

// XN → `N <count> <number> <name>`: the place holding the robot's odometry position (0 and `-`
// outside every place).
void handle_get_place(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  PlaceReport r;
  if (refused(port.place_here(r), out)) return;
  out.open("N");
  out.fields({r.count, r.number});
  out.word(r.number > 0 ? r.name : std::string_view("-"));
}

// XI <n> → `I <n> <name> <centre-x> <centre-y> <k> <neighbour>…`: centre in 0.1 mm, k places
// one door away and (at most 16 of) their numbers.
void handle_get_place_info(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  PlaceReport r;
  if (refused(port.place_info(cmd.ints[0], r), out)) return;
  out.open("I");
  out.field(r.number);
  out.word(r.name);
  out.fields({r.centre_x, r.centre_y, r.neighbours});
  const auto listed = static_cast<std::size_t>(std::clamp<std::int32_t>(r.neighbours, 0, static_cast<std::int32_t>(PlaceReport::kMaxNeighbours)));
  out.fields(std::span<const std::int32_t>(r.neighbour.data(), listed));
}

// XQ <n> [e] → `ack`, or an error changing nothing: the port checks the place, the robot's place,
// the route and the emergency (RobotPort::go_to_place). e = 1: seed 003's exploration.
void handle_go_to_place(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.go_to_place(cmd.ints[0], cmd.int_count == 2 && cmd.ints[1] == 1), out);
}

}  // namespace robuter::protocol
