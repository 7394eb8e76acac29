// SPDX-License-Identifier: GPL-3.0-or-later
// Pan-tilt process glue: what is wanted, one driver step, scan and status out.
#include "modules/ptu/ptu_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "modules/mode_status.hpp"

namespace robuter {

namespace {
ModeState to_state(ptu::DriverState s) {
  switch (s) {
    case ptu::DriverState::off: return ModeState::off;
    case ptu::DriverState::starting: return ModeState::starting;
    case ptu::DriverState::scanning: return ModeState::scanning;
    case ptu::DriverState::failed: return ModeState::failed;
  }
  return ModeState::off;
}
ModeReason to_reason(ptu::DriverFault f) {
  switch (f) {
    case ptu::DriverFault::none: return ModeReason::none;
    case ptu::DriverFault::no_unit: return ModeReason::no_unit;
    case ptu::DriverFault::silent: return ModeReason::unit_silent;
    case ptu::DriverFault::garbage: return ModeReason::unit_garbage;
    case ptu::DriverFault::refused: return ModeReason::unit_refused;
    case ptu::DriverFault::lost: return ModeReason::unit_lost;
  }
  return ModeReason::none;
}
const char* fault_text(ptu::DriverFault f) {
  switch (f) {
    case ptu::DriverFault::none: return "none";
    case ptu::DriverFault::no_unit: return "no unit configured (ptu.port) or its port would not open";
    case ptu::DriverFault::silent: return "the unit stopped answering";
    case ptu::DriverFault::garbage: return "the unit's replies are not the PTU protocol";
    case ptu::DriverFault::refused: return "the unit refused a command";
    case ptu::DriverFault::lost: return "the unit's port went away";
  }
  return "?";
}
// A mode that keeps the scanner busy.
bool needs_scanner(const ModeStatus& s) {
  return s.state == ModeState::searching || s.state == ModeState::moving || s.state == ModeState::starting ||
         s.state == ModeState::crossing || s.state == ModeState::waiting || s.state == ModeState::leaving;
}
}  // namespace

PtuModule::PtuModule(Blackboard& bb, hal::ByteStream* stream, hal::SonarRing& ring, const ptu::PtuSettings& s)
    : driver_(stream, ring, s),
      modes_(bb.modes.reader()),
      gate_(bb.gate_status.reader()),
      doors_(bb.doors_status.reader()),
      posture_(bb.posture.reader()),
      scan_out_(bb.pan_tilt_scan.writer()),
      status_out_(bb.pan_tilt_status.writer()) {}

bool PtuModule::init(Kernel& k) {
  status_out_.publish(off_status(k.tick()));
  scan_out_.publish(driver_.scan());
  modes_.copy();  // an Ap from before the start is not replayed as a new one
  return true;
}

bool PtuModule::wanted() const {
  return modes_.peek().pan_tilt || needs_scanner(gate_.peek()) || needs_scanner(doors_.peek());
}

// Why restart on a new Ap even while wanted: the operator's way to retry a failed unit.
void PtuModule::run(Kernel& k) {
  const std::uint64_t tick = k.tick();
  const bool want = wanted();
  const bool new_ap = modes_.updated() && modes_.copy().pan_tilt;
  if (want && (!was_wanted_ || new_ap)) driver_.start(tick);
  if (!want && was_wanted_) {
    driver_.stop();
    scan_out_.publish(driver_.scan());
  }
  was_wanted_ = want;
  const Posture& p = posture_.peek();
  if (driver_.step(tick, SectorPose{p.x, p.y, p.theta})) scan_out_.publish(driver_.scan());
  report(tick);
}

void PtuModule::report(std::uint64_t tick) {
  const ModeState st = to_state(driver_.state());
  const ModeReason why = to_reason(driver_.fault());
  const ModeStatus& cur = status_out_.current();
  if (cur.state == st && cur.reason == why) return;
  const bool new_run = st == ModeState::starting || (st == ModeState::scanning && cur.state == ModeState::off);
  ModeStatus s = moved_on(cur, st, st == ModeState::failed ? why : ModeReason::none, new_run, tick);
  s.since_tick = tick;  // a new reason in the same state restarts it too
  status_out_.publish(s);
  if (st == ModeState::failed) log::warn("pan-tilt: failed: {}", fault_text(driver_.fault()));
  else if (st == ModeState::scanning) log::info("pan-tilt: scanning");
  else if (st == ModeState::off) log::info("pan-tilt: off");
}

void PtuModule::close(Kernel&) { driver_.stop(); }

}  // namespace robuter
