// The ring's firing state machine: idle → wait to fire → wait for the read → next node.
#include "modules/us/ring_scanner.hpp"

#include <algorithm>

namespace robuter::sonar {

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

bool RingScanner::start_scan(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want) {
  bool changed = false;
  if (want.timeout_ms != timeout_ms_ || want.sound_speed_m_s != sound_speed_) {
    ring.configure(want.timeout_ms, want.sound_speed_m_s);
    timeout_ms_ = want.timeout_ms;
    sound_speed_ = want.sound_speed_m_s;
    const std::uint64_t range = static_cast<std::uint64_t>(want.timeout_ms) * want.sound_speed_m_s / 2;
    no_echo_mm_ = static_cast<std::uint16_t>(std::min<std::uint64_t>(range, 0xFFFF));
  }
  const std::uint32_t wanted = want.active & 0xFFFFFFu;
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
  node_delay_ = want.node_delay_ticks;
  timeout_ticks_ = want.timeout_ticks;
  node_ = next_node(masks_, -1);
  full_scan_ = std::all_of(masks_.begin(), masks_.end(), [](std::uint8_t m) { return m != 0; });
  scan_start_ = mark_ = tick;
  if (node_ < 0) return changed;  // nothing to fire: stay idle
  next_fire_ = tick + node_delay_;
  phase_ = Phase::wait_fire;
  return changed;
}

void RingScanner::store(std::uint64_t tick, int node, const hal::NodeRanges& r) {
  const std::uint8_t mask = masks_[static_cast<std::size_t>(node)];
  for (int i = 0; i < hal::kSensorsPerNode; ++i) {
    if (!(mask & (1u << i))) continue;
    const int s = hal::sensor_number(node, i);
    const auto k = static_cast<std::size_t>(s - 1);
    const std::uint16_t v = r[static_cast<std::size_t>(i)];
    const std::uint32_t bit = 1u << (s - 1);
    ranges_.mm[k] = v == 0 ? no_echo_mm_ : v;
    ranges_.no_echo = v == 0 ? (ranges_.no_echo | bit) : (ranges_.no_echo & ~bit);
    ranges_.read_tick[k] = tick;
  }
  ranges_.tick = tick;
}

void RingScanner::drop(int node) {
  const std::uint8_t mask = masks_[static_cast<std::size_t>(node)];
  for (int i = 0; i < hal::kSensorsPerNode; ++i) {
    if (!(mask & (1u << i))) continue;
    const int s = hal::sensor_number(node, i);
    ranges_.mm[static_cast<std::size_t>(s - 1)] = 0;
    ranges_.no_echo &= ~(1u << (s - 1));
  }
  ++lost_;
}

void RingScanner::advance(std::uint64_t tick) {
  node_ = next_node(masks_, node_);
  if (node_ >= 0) {
    next_fire_ = tick + node_delay_;
    phase_ = Phase::wait_fire;
    return;
  }
  ++ranges_.scans;
  if (full_scan_) stats_.add_scan(tick - scan_start_);
  phase_ = Phase::idle;
}

// Bounded: every pass either waits (returns) or moves the sequence on, and a node needs a
// fire and a read, so a handful of passes cover what can be due in one activation.
bool RingScanner::step(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want) {
  bool changed = false;
  for (int pass = 0; pass < 4 * hal::kSonarNodes; ++pass) {
    switch (phase_) {
      case Phase::idle:
        changed = start_scan(tick, ring, want) || changed;
        if (phase_ == Phase::idle) return changed;
        break;
      case Phase::wait_fire:
        if (tick < next_fire_) return changed;
        if (ring.fire(node_, masks_[static_cast<std::size_t>(node_)])) {
          fire_tick_ = tick;
          phase_ = Phase::wait_read;
        } else if (tick > next_fire_ + kGraceTicks) {
          drop(node_);
          changed = true;
          advance(tick);
        } else {
          return changed;
        }
        break;
      case Phase::wait_read: {
        hal::NodeRanges r{};
        if (ring.read(node_, r)) {
          store(tick, node_, r);
          stats_.add_node(tick - mark_);
          mark_ = tick;
          changed = true;
          advance(tick);
        } else if (tick > fire_tick_ + timeout_ticks_ + kGraceTicks) {
          drop(node_);
          mark_ = tick;
          changed = true;
          advance(tick);
        } else {
          return changed;
        }
        break;
      }
    }
  }
  return changed;
}

}  // namespace robuter::sonar
