// SPDX-License-Identifier: GPL-3.0-or-later
// Handlers of the X extensions: emergency, re-enable, kernel figures, version, session options.
#include <algorithm>

#include "protocol/codec/handlers.hpp"

namespace robuter::protocol {

// XE → `E <held> <latched> <cause> <enabled-mask> <clock> <granted-%> <rule> <protective>`; the
// last three came later and follow the clock, so a reader of the first five keeps working.
void handle_get_emergency(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  const EmergencyStatus e = port.emergency();
  out.open("E");
  out.field(e.held ? 1 : 0);
  out.field(e.latched ? 1 : 0);
  out.raw(" ");
  out.raw(word(e.cause));
  out.field(e.enabled);
  out.field(port.clock());
  out.field(e.granted_pct);
  out.raw(e.envelope ? " envelope" : " seed");
  out.field(e.protective ? 1 : 0);
}

// XR: the port refuses (refused_emergency) while the cause is still present.
void handle_reenable(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.reenable(), out);
}

// XK → `K <ticks> <max-late-us> <p99-late-us> <n> {<name> <act> <ovr> <slip> <mean-us> <max-us>}
// <clock>`.
void handle_get_kernel_figures(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  const KernelFigures k = port.kernel_figures();
  const std::size_t n = std::min(k.processes.size(), kMaxKernelProcesses);
  out.open("K");
  out.field(static_cast<std::int64_t>(k.ticks));
  out.field(k.max_late_us);
  out.field(k.p99_late_us);
  out.field(static_cast<std::int64_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const ProcessFigures& p = k.processes[i];
    out.word(p.name);
    out.field(static_cast<std::int64_t>(p.activations));
    out.field(static_cast<std::int64_t>(p.overruns));
    out.field(static_cast<std::int64_t>(p.slips));
    out.field(p.mean_us);
    out.field(p.max_us);
  }
  out.field(port.clock());
}

// XV → `V robuterd <version> proto <n> caps <c1,c2,…>`: codec features plus fitted equipment.
void handle_get_version(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  out.open("V robuterd");
  out.word(port.firmware_version());
  out.raw(" proto");
  out.field(kProtocolVersion);
  out.raw(" caps stop,emergency,reenable,kernel,stream,verbose,checksum,terminator");
  const std::uint32_t f = port.features();
  if (f & kFeaturePanTilt) out.raw(",pantilt");
  if (f & kFeatureGate) out.raw(",gate");
  if (f & kFeatureDoors) out.raw(",doors");
  if (f & kFeaturePassThrough) out.raw(",passthrough");
  if (f & kFeatureGoTo) out.raw(",goto");
  if (f & kFeaturePlanner) out.raw(",planner");
}

// XS<ticks>: 0 stops the stream; otherwise at least kMinStreamPeriod ticks.
void handle_set_stream(const Command& cmd, RobotPort&, ReplyWriter& out) noexcept {
  const std::int32_t period = cmd.ints[0];
  if (period != 0 && period < static_cast<std::int32_t>(kMinStreamPeriod)) {
    out.error(ErrorCode::out_of_range);
    return;
  }
  out.session().stream_period = static_cast<std::uint32_t>(period);
  out.ack();
}

// XB0 / XB1: the `ack` itself is the same either way.
void handle_set_verbose_errors(const Command& cmd, RobotPort&, ReplyWriter& out) noexcept {
  out.session().verbose_errors = cmd.choice == '1';
  out.ack();
}

// XC0 / XC1: the reply to XC still uses the mode the line arrived in.
void handle_set_checksums(const Command& cmd, RobotPort&, ReplyWriter& out) noexcept {
  out.session().checksums = cmd.choice == '1';
  out.ack();
}

// XL0 (CR) / XL1 (LF) / XL2 (CRLF): from the next reply on.
void handle_set_terminator(const Command& cmd, RobotPort&, ReplyWriter& out) noexcept {
  out.session().terminator = static_cast<Terminator>(cmd.choice - '0');
  out.ack();
}

}  // namespace robuter::protocol
