// SPDX-License-Identifier: GPL-3.0-or-later
// The ring's firing state machine: pick a firing (seed order or watch schedule) → wait → fire → read.
#include "modules/us/ring_scanner.hpp"

#include <algorithm>

namespace robuter::us {

// Per-node masks, as the seed's active-sensor table (AST) held them.
NodeMasks node_masks(std::uint32_t active) {
  NodeMasks m{};
  for (int s = 1; s <= hal::kRingSensors; ++s)
    if (active & (1u << (s - 1)))
      m[static_cast<std::size_t>(hal::sensor_node(s))] |= static_cast<std::uint8_t>(1u << hal::sensor_index(s));
  return m;
}

// Nodes with nothing to fire are skipped, as the seed's "table.node[i] > 0".
int next_node(const NodeMasks& masks, int after) {
  for (int n = after + 1; n < hal::kSonarNodes; ++n)
    if (masks[static_cast<std::size_t>(n)] != 0) return n;
  return -1;
}

bool RingScanner::wants_watch(const ScanRequest& want) {
  return want.watch && (want.priority & want.active & 0xFFFFFFu) != 0;
}

void RingScanner::configure(hal::SonarRing& ring, const ScanRequest& want) {
  if (want.timeout_ms == timeout_ms_ && want.sound_speed_m_s == sound_speed_) return;
  ring.configure(want.timeout_ms, want.sound_speed_m_s);
  timeout_ms_ = want.timeout_ms;
  sound_speed_ = want.sound_speed_m_s;
}

bool RingScanner::apply(hal::SonarRing& ring, const ScanRequest& want) {
  configure(ring, want);
  node_delay_ = want.node_delay_ticks;
  timeout_ticks_ = want.timeout_ticks;
  const std::uint32_t wanted = want.active & 0xFFFFFFu;
  bool changed = false;
  const std::uint32_t off = active_ & ~wanted;
  for (int s = 1; s <= hal::kRingSensors; ++s) {
    const std::uint32_t bit = 1u << (s - 1);
    if (!(off & bit)) continue;
    ranges_.mm[static_cast<std::size_t>(s - 1)] = 0;  // inactive reads 0
    ranges_.no_echo &= ~bit;
    changed = true;
  }
  active_ = wanted;
  masks_ = node_masks(wanted);
  full_scan_ = std::all_of(masks_.begin(), masks_.end(), [](std::uint8_t m) { return m != 0; });
  return changed;
}

bool RingScanner::start_scan(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want) {
  watching_ = false;
  priority_ = 0;
  const bool changed = apply(ring, want);
  scan_start_ = mark_;
  node_ = next_node(masks_, -1);
  if (node_ < 0) {
    phase_ = Phase::idle;  // nothing to fire
    return changed;
  }
  NodeMasks one{};
  one[static_cast<std::size_t>(node_)] = masks_[static_cast<std::size_t>(node_)];
  arm(one, Role::scan, 0, 0);
  next_fire_ = tick + node_delay_;
  return changed;
}

// The watch firing and the rotation take turns; a new set of priority sensors fires next.
bool RingScanner::choose_watch(hal::SonarRing& ring, const ScanRequest& want) {
  const bool changed = apply(ring, want);
  if (!watching_) {
    watching_ = true;
    rotation_ = -1;
    scan_start_ = mark_;
  }
  const std::uint32_t priority = want.priority & active_;
  if (priority != priority_) {
    priority_ = priority;
    watch_next_ = true;
  }
  if (watch_next_) {
    watch_next_ = false;
    arm(node_masks(priority), Role::watch, want.priority_timeout_ms, want.priority_timeout_ticks);
    return changed;
  }
  watch_next_ = true;
  int next = next_node(masks_, rotation_);
  if (next < 0) next = next_node(masks_, -1);
  rotation_ = next;
  NodeMasks one{};
  one[static_cast<std::size_t>(next)] = masks_[static_cast<std::size_t>(next)];
  arm(one, Role::rotation, want.moving_timeout_ms, want.moving_timeout_ticks);
  return changed;
}

// The seed's order decides at the read (a scan goes on with its table); the watch schedule
// decides when the firing is due, with the newest request. Coming back from the watch, a scan
// in the seed's order starts at once (the delay since the last read is over).
bool RingScanner::pick(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want) {
  if (wants_watch(want)) return watching_ && picked_ ? false : choose_watch(ring, want);
  if (!watching_ && picked_) return false;
  const bool changed = start_scan(tick, ring, want);
  next_fire_ = tick;
  return changed;
}

void RingScanner::arm(const NodeMasks& masks, Role role, std::uint32_t ms, std::uint32_t ticks) {
  role_ = role;
  picked_ = true;
  started_ = false;
  fire_masks_ = masks;
  to_fire_ = to_read_ = 0;
  got_read_ = false;
  for (int n = 0; n < hal::kSonarNodes; ++n)
    if (masks[static_cast<std::size_t>(n)] != 0) to_fire_ |= static_cast<std::uint8_t>(1u << n);
  const bool shorter = ms > 0 && ms < timeout_ms_;
  fire_ms_ = shorter ? ms : 0;
  fire_ticks_ = shorter && ticks > 0 ? ticks : timeout_ticks_;
  const std::uint64_t range = static_cast<std::uint64_t>(shorter ? ms : timeout_ms_) * sound_speed_ / 2;
  reach_mm_ = static_cast<std::uint16_t>(std::min<std::uint64_t>(range, 0xFFFF));
  phase_ = Phase::firing;
}

void RingScanner::store(std::uint64_t tick, int node, const hal::NodeRanges& r) {
  const auto n = static_cast<std::size_t>(node);
  const std::uint8_t mask = fire_masks_[n] & masks_[n];
  for (int i = 0; i < hal::kSensorsPerNode; ++i) {
    if (!(mask & (1u << i))) continue;
    const int s = hal::sensor_number(node, i);
    const auto k = static_cast<std::size_t>(s - 1);
    const std::uint16_t v = r[static_cast<std::size_t>(i)];
    const std::uint32_t bit = 1u << (s - 1);
    ranges_.mm[k] = v == 0 ? reach_mm_ : v;
    ranges_.no_echo = v == 0 ? (ranges_.no_echo | bit) : (ranges_.no_echo & ~bit);
    ranges_.read_tick[k] = tick;
  }
  ranges_.tick = tick;
}

void RingScanner::drop(int node) {
  const std::uint8_t mask = fire_masks_[static_cast<std::size_t>(node)];
  for (int i = 0; i < hal::kSensorsPerNode; ++i) {
    if (!(mask & (1u << i))) continue;
    const int s = hal::sensor_number(node, i);
    ranges_.mm[static_cast<std::size_t>(s - 1)] = 0;
    ranges_.no_echo &= ~(1u << (s - 1));
  }
  ++lost_;
}

// Each node of the firing is fired (a refusing node is tried again until the grace is over),
// then read as soon as it reports, each on its own; one that never reports is dropped.
bool RingScanner::fire_and_read(std::uint64_t tick, hal::SonarRing& ring) {
  bool changed = false;
  for (int n = 0; n < hal::kSonarNodes; ++n) {
    const auto bit = static_cast<std::uint8_t>(1u << n);
    const auto i = static_cast<std::size_t>(n);
    if (to_fire_ & bit) {
      if (ring.fire(n, fire_masks_[i], fire_ms_)) {
        started_ = true;
        to_fire_ &= static_cast<std::uint8_t>(~bit);
        to_read_ |= bit;
        fired_at_[i] = tick;
      } else if (tick > next_fire_ + kGraceTicks) {
        started_ = true;
        to_fire_ &= static_cast<std::uint8_t>(~bit);
        drop(n);
        changed = true;
      }
    }
    if (to_read_ & bit) {
      hal::NodeRanges r{};
      if (ring.read(n, r)) {
        to_read_ &= static_cast<std::uint8_t>(~bit);
        store(tick, n, r);
        got_read_ = changed = true;
      } else if (tick > fired_at_[i] + fire_ticks_ + kGraceTicks) {
        to_read_ &= static_cast<std::uint8_t>(~bit);
        drop(n);
        changed = true;
      }
    }
  }
  return changed;
}

void RingScanner::end_scan(std::uint64_t tick) {
  ++ranges_.scans;
  if (full_scan_) stats_.add_scan(tick - scan_start_);
  scan_start_ = tick;
}

bool RingScanner::advance(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want) {
  if (got_read_) stats_.add_node(tick - mark_);
  mark_ = tick;
  if (watching_) {
    if (role_ == Role::rotation && next_node(masks_, rotation_) < 0) end_scan(tick);
    picked_ = started_ = false;
    next_fire_ = tick + node_delay_;
    return false;
  }
  if (wants_watch(want)) {  // the robot started moving: its watch firing when the delay is over
    picked_ = started_ = false;
    next_fire_ = tick + node_delay_;
    return false;
  }
  node_ = next_node(masks_, node_);
  if (node_ >= 0) {
    NodeMasks one{};
    one[static_cast<std::size_t>(node_)] = masks_[static_cast<std::size_t>(node_)];
    arm(one, Role::scan, 0, 0);
    next_fire_ = tick + node_delay_;
    return false;
  }
  end_scan(tick);
  return start_scan(tick, ring, want);
}

// Bounded: every pass either waits (returns) or ends a firing, and a firing's nodes are fired
// and read within one pass, so a handful of passes cover what can be due in one activation.
bool RingScanner::step(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want) {
  bool changed = false;
  for (int pass = 0; pass < 4 * hal::kSonarNodes; ++pass) {
    if (phase_ == Phase::idle) {
      mark_ = tick;  // nothing was going on
      if (wants_watch(want)) {
        changed = choose_watch(ring, want) || changed;
        next_fire_ = tick + node_delay_;
      } else {
        changed = start_scan(tick, ring, want) || changed;
      }
      if (phase_ == Phase::idle) return changed;
    }
    if (tick < next_fire_) return changed;
    if (!started_) {  // nothing of it fired yet: decide now
      changed = pick(tick, ring, want) || changed;
      if (phase_ == Phase::idle) continue;
    }
    changed = fire_and_read(tick, ring) || changed;
    if (to_fire_ != 0 || to_read_ != 0) return changed;
    changed = advance(tick, ring, want) || changed;
  }
  return changed;
}

}  // namespace robuter::us
