// SPDX-License-Identifier: GPL-3.0-or-later
// Door crossing: fresh scan, steer, wait when blocked, through, drive on, done.
#include "modules/doors/crossing.hpp"
#include "robot/robot_model.hpp"

#include <cmath>
#include <numbers>

namespace robuter::doors {

namespace {
bool within(int i, int first, int last) { return i >= first && i <= last; }
}  // namespace

DoorCrossing::DoorCrossing(const CrossingSettings& s) : s_(s), sides_(side_distances(s.body)) {}

void DoorCrossing::start(std::uint64_t tick) {
  state_ = ModeState::starting;
  reason_ = ModeReason::none;
  start_tick_ = tick;
  tick_ = tick;
  wait_since_ = 0;
  entered_ = false;
  view_ = CrossingView{};
}

void DoorCrossing::fail(ModeReason reason) {
  if (!active()) return;
  state_ = ModeState::failed;
  reason_ = reason;
}

// Why along each echo's own bearing: a sonar's echo can come from anywhere in its 25° beam; an
// echo the neighbouring beams place (ptu::locate_echoes) is judged where it is — within its
// remaining uncertainty, at the direction where the body reaches farthest — so a door edge seen
// at 40° by the 30° sector is not taken for an obstacle at 30° (where the body reaches 670 mm
// instead of 521 mm: a 90 cm door would block on both sides), and an echo nothing places is
// judged over its whole beam.
CrossingView DoorCrossing::look(const ptu::Echoes& e, const PanTiltScan& scan, std::uint64_t tick,
                                const CrossingSettings& s) {
  CrossingView v;
  const SideDistances sd = side_distances(s.body);
  int near_left = 0, near_right = 0;  // sectors that hear a jamb beside the pan axis, each side
  for (const ptu::Echo& x : e) {
    if (!x.valid || x.far) continue;
    const int sector = ptu::wrap_sector(static_cast<int>(std::lround(x.bearing_deg / ptu::kSectorDegrees)));
    const double spread = x.spread_deg * s.spread_weight;
    const double lo = (x.bearing_deg - spread) * robot::kDeg, hi = (x.bearing_deg + spread) * robot::kDeg;
    const bool too_close = x.range_mm < min_read_max(sd, lo, hi);
    if (too_close) {
      if (sector == 0 || sector == 71) v.threats.left = v.threats.right = true;  // straight ahead: both
      else if (within(sector, s.sides.left_first, s.sides.left_last)) v.threats.left = true;
      else if (within(sector, s.sides.right_first, s.sides.right_last)) v.threats.right = true;
    }
    // Inside: the jambs beside the pan axis, heard by two sectors or more on each side — not the
    // wall ahead heard at 60°, nor one spurious echo a side (the realistic sonar model, issue #19:
    // "through" came with the body still before the door).
    if (x.range_mm < s.entered_mm && std::abs(x.x_mm - s.echoes.pivot_x_mm) <= s.beside_mm) {
      if (x.bearing_deg >= 60.0 && x.bearing_deg <= 120.0) ++near_left;
      if (x.bearing_deg <= -60.0 && x.bearing_deg >= -120.0) ++near_right;
    }
  }
  v.entered = near_left >= 2 && near_right >= 2;
  // The opening just ahead of the front face: its narrowest left and right edges. Narrower than
  // the body plus its margins, it blocks both sides at once (the seed's rules see one edge at a
  // time, turn away from it into the other, and wander in front of a gap it can never pass).
  const double front = s.body.pan_x_mm + s.echoes.pivot_x_mm;  // axle to the front face, mm
  double left = 1e9, right = 1e9;
  for (const ptu::Echo& x : e) {
    if (!x.valid || x.far || x.x_mm < front - 50.0 || x.x_mm > front + s.look_ahead_mm) continue;
    if (x.y_mm >= 0.0) left = std::min(left, x.y_mm);
    else right = std::min(right, -x.y_mm);
  }
  if (left < 1e9 && right < 1e9) {
    v.opening_mm = left + right;
    v.too_narrow = v.opening_mm < s.body.width_mm + 2.0 * s.body.safety_mm;
    if (v.too_narrow) v.threats.left = v.threats.right = true;
  }
  // The seed's end test on the readings themselves; an unread or stale sector is never clear.
  ptu::SectorValues r;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const std::uint64_t t = scan.read_tick[i];
    r[i] = (t > 0 && t <= tick && tick - t <= s.max_age_ticks) ? scan.raw[i] : -1;
  }
  v.clear = all_clear_on_a_side(r, s.max_dist_mm);
  return v;
}

CrossingOutput DoorCrossing::out(Steer steer) const {
  CrossingOutput o;
  const Wheels w = wheels_for(steer, s_.speeds);
  o.request = active();
  o.left = o.request ? w.left : 0;
  o.right = o.request ? w.right : 0;
  o.state = state_;
  o.reason = reason_;
  o.duration_ticks = static_cast<std::uint32_t>(tick_ - start_tick_);
  return o;
}

CrossingOutput DoorCrossing::step(const CrossingInputs& in) {
  tick_ = in.tick;
  if (!active()) return out(Steer::stop);
  if (in.scanner_failed) {
    fail(ModeReason::scanner);
    return out(Steer::stop);
  }
  if (s_.timeout_ticks > 0 && in.tick - start_tick_ > s_.timeout_ticks) {
    fail(ModeReason::timeout);
    return out(Steer::stop);
  }
  const PanTiltScan& scan = *in.scan;
  if (state_ == ModeState::starting) {
    // Every sector the rules look at read since the start: the front half.
    for (int i = 0; i < ptu::kSectors; ++i) {
      const bool front = within(i, 0, s_.sides.left_last + 1) || within(i, s_.sides.right_first, ptu::kSectors - 1);
      if (front && scan.read_tick[static_cast<std::size_t>(i)] <= start_tick_) return out(Steer::stop);
    }
    state_ = ModeState::crossing;
  }
  ptu::Echoes echoes;
  ptu::locate_echoes(scan, in.pose, in.tick, s_.max_age_ticks, s_.echoes, echoes);
  view_ = look(echoes, scan, in.tick, s_);
  entered_ = entered_ || view_.entered;
  const Steer st = steer(view_.threats);

  if (state_ == ModeState::leaving) {
    const double dx = (in.pose.x - leave_from_.x) * 0.1, dy = (in.pose.y - leave_from_.y) * 0.1;
    if (std::hypot(dx, dy) >= s_.exit_mm) {
      state_ = ModeState::crossed;  // the rear has left the doorway
      return out(Steer::stop);
    }
    // The rear still in the doorway: the seed's rules go on (ending "crossed" at the first threat
    // left the body in the door, issue #19): turn away from one side; blocked on both, wait and
    // give up as a blocked crossing does.
    if (st == Steer::stop) {
      if (wait_since_ == 0) wait_since_ = in.tick;
      else if (in.tick - wait_since_ > s_.time_before_move_ticks) fail(ModeReason::cant_cross);
      return out(Steer::stop);
    }
    wait_since_ = 0;
    return out(st);
  }
  if (entered_ && view_.clear) {  // seed: "Door crossed successfully"
    state_ = s_.exit_mm > 0.0 ? ModeState::leaving : ModeState::crossed;
    leave_from_ = in.pose;
    wait_since_ = 0;
    return out(state_ == ModeState::leaving && st == Steer::straight ? Steer::straight : Steer::stop);
  }
  if (st == Steer::stop) {
    if (state_ != ModeState::waiting) {
      state_ = ModeState::waiting;
      wait_since_ = in.tick;
    } else if (in.tick - wait_since_ > s_.time_before_move_ticks) {
      fail(ModeReason::cant_cross);  // seed: "Can't cross the door"
    }
    return out(Steer::stop);
  }
  state_ = ModeState::crossing;
  return out(st);
}

}  // namespace robuter::doors
