// SPDX-License-Identifier: GPL-3.0-or-later
// The arbitration table and the owner's changes.
#include "modules/emergency/motion_arbiter.hpp"

#include <array>
#include <cstddef>

namespace robuter::emergency {

namespace {
using A = OperatorAction;
using S = MotionSource;

// One row per action, in OperatorAction's order (checked below).
constexpr std::array<ArbitrationRule, 12> kTable{{
    {A::motion, S::link, false, S::link},          // AM, AM 0 0 too
    {A::go_to, S::go_to, true, S::link},           // AW
    {A::servo, S::link, false, S::link},           // ASN, ASF
    {A::stop_byte, S::link, false, S::link},       // 0x18 (and the emergency latches)
    {A::halt, S::link, false, S::planner},         // XH
    {A::start_gate, S::gate, true, S::link},       // AG
    {A::stop_gate, S::link, false, S::gate},       // AT
    {A::start_doors, S::doors, true, S::link},     // Ad
    {A::stop_doors, S::link, false, S::doors},     // Af
    {A::start_planner, S::planner, true, S::link}, // XG
    {A::start_demo, S::demo, true, S::link},       // XT1
    {A::stop_demo, S::link, false, S::demo},       // XT0
}};

constexpr bool table_in_order() {
  for (std::size_t i = 0; i < kTable.size(); ++i)
    if (static_cast<std::size_t>(kTable[i].action) != i) return false;
  return true;
}
static_assert(table_in_order(), "one row per OperatorAction, in its order");
static_assert(static_cast<std::size_t>(A::stop_demo) + 1 == kTable.size(), "every OperatorAction has a row");

constexpr std::size_t index(MotionSource s) { return static_cast<std::size_t>(s); }
}  // namespace

std::span<const ArbitrationRule> arbitration_table() { return kTable; }

void MotionArbiter::end_running(ModeReason why) {
  if (!automatic(a_.owner)) return;
  a_.ended[index(a_.owner)] = why;
  if (a_.lent_by != MotionSource::link) a_.ended[index(a_.lent_by)] = why;  // the lender's run ends with it
  a_.lent_by = MotionSource::link;
  a_.owner = MotionSource::link;
}

void MotionArbiter::hand_to(MotionSource s) {
  a_.owner = s;
  ++a_.runs[index(s)];
  a_.ended[index(s)] = ModeReason::none;
}

void MotionArbiter::take(OperatorAction action) {
  const ArbitrationRule& r = kTable[static_cast<std::size_t>(action)];
  // A mode's own stop cancels it; while the planner has lent the robot to the door crossing, XH
  // (the planner's stop) and Af (the crossing's) cancel both.
  const bool own = a_.owner == r.own_stop || (a_.lent_by != MotionSource::link && a_.lent_by == r.own_stop);
  end_running(own ? ModeReason::cancelled : ModeReason::operator_motion);
  if (r.starts) hand_to(r.takes);
  else a_.owner = r.takes;
}

void MotionArbiter::emergency_stop() {
  end_running(ModeReason::emergency);
  a_.owner = MotionSource::link;
}

void MotionArbiter::protective_stop() {
  if (a_.owner != MotionSource::go_to) return;
  a_.ended[index(MotionSource::go_to)] = ModeReason::protective;
  a_.owner = MotionSource::link;
}

void MotionArbiter::hand_over_to_doors() {
  if (a_.owner != MotionSource::gate) return;
  hand_to(MotionSource::doors);
}

void MotionArbiter::lend_to_doors() {
  if (a_.owner != MotionSource::planner) return;
  hand_to(MotionSource::doors);
  a_.lent_by = MotionSource::planner;
}

void MotionArbiter::give_back() {
  if (a_.owner != MotionSource::doors || a_.lent_by == MotionSource::link) return;
  a_.owner = a_.lent_by;
  a_.lent_by = MotionSource::link;
}

void MotionArbiter::start_at_boot(MotionSource s) { hand_to(s); }

}  // namespace robuter::emergency
