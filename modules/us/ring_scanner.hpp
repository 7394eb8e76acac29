// SPDX-License-Identifier: GPL-3.0-or-later
// The ring's non-blocking firing sequence (seed us.c read_sensors): one state machine step per activation.
#pragma once

#include <array>
#include <cstdint>

#include "hal/api/sonar_ring.hpp"
#include "modules/topics.hpp"
#include "modules/us/scan_stats.hpp"

namespace robuter::us {

// Sensors to fire per node: bit i = index i of that node.
using NodeMasks = std::array<std::uint8_t, hal::kSonarNodes>;

// Splits a 24-bit table (bit s-1 = sensor s) into per-node firing masks.
NodeMasks node_masks(std::uint32_t active);
// The first node after `after` (−1: from the start) with a sensor to fire, or −1.
int next_node(const NodeMasks& masks, int after);

// What the ring should do, as settings and the emergency module's selection say.
struct ScanRequest {
  std::uint32_t active = 0xFFFFFF;      // sensors to fire, bit s-1 = sensor s
  std::uint32_t node_delay_ticks = 3;   // wait between a read and the next firing, ticks
  std::uint32_t timeout_ms = 33;        // echo time-out, ms
  std::uint32_t timeout_ticks = 4;      // the same rounded up to ticks
  std::uint32_t sound_speed_m_s = 300;  // calibrated speed of sound, m/s
  bool watch = true;                    // false: the seed's order even while moving ([sonar] schedule)
  std::uint32_t priority = 0;           // sensors watching where the robot goes, bit s-1 = sensor s
  std::uint32_t priority_timeout_ms = 0;     // time-out of the watch firing, ms (0: timeout_ms)
  std::uint32_t priority_timeout_ticks = 0;  // the same in ticks (0: timeout_ticks)
  std::uint32_t moving_timeout_ms = 0;       // time-out of the rotation's firings while moving, ms (0: timeout_ms)
  std::uint32_t moving_timeout_ticks = 0;    // the same in ticks (0: timeout_ticks)
};

// Stopped (no priority sensor), the seed's order: every node that has an active sensor, in node
// order, single-shot, one node at a time, waiting the node delay after each read; a new table,
// delay or time-out applies when the next scan starts.
//
// Moving (priority sensors and `watch`), the ring watches where the robot goes: every other
// firing is the watch firing — the priority sensors alone, on all their nodes at once (the five
// neighbouring sensors of a watch-dog set, like a node's own four), with the priority time-out —
// and the firings in between are a rotation over every active node with the moving time-out,
// which is what a scan is then. A new set of priority sensors is fired at once (a held motion
// waits for its data); the request applies at every firing. The node delay separates any two
// firings, as it did when stopped.
//
// A node is read when the ring reports it (every echo in, or the firing's time-out). Never
// blocks: each step does what is due now and returns. No heap.
class RingScanner {
 public:
  // Extra ticks a node may take beyond its time-out (or a busy ring may refuse a firing) before
  // its readings are dropped as lost.
  static constexpr std::uint32_t kGraceTicks = 10;

  // Advances the sequence at `tick`; true when ranges() changed (new readings or a new table).
  bool step(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want);

  const UltrasonicRanges& ranges() const { return ranges_; }
  const ScanStats& stats() const { return stats_; }
  std::uint32_t active() const { return active_; }       // table in force
  std::uint64_t lost_reads() const { return lost_; }     // node firings whose readings never came

 private:
  enum class Phase : std::uint8_t { idle, firing };
  // What the firing in progress is for.
  enum class Role : std::uint8_t { scan, watch, rotation };

  // True when the request asks for the moving schedule.
  static bool wants_watch(const ScanRequest& want);
  // Configures the ring when the time-out or speed of sound changed.
  void configure(hal::SonarRing& ring, const ScanRequest& want);
  // Applies a request's table, delay and time-out: zeroes sensors switched off. Returns true
  // when ranges changed.
  bool apply(hal::SonarRing& ring, const ScanRequest& want);
  // Starts a scan in the seed's order, its first node due a node delay after `tick`. Returns
  // true when ranges changed.
  bool start_scan(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want);
  // Sets up the next firing while moving. Returns true when ranges changed.
  bool choose_watch(hal::SonarRing& ring, const ScanRequest& want);
  // When a firing is due and nothing of it fired yet: what fires (the watch schedule or the
  // seed's order). Returns true when ranges changed.
  bool pick(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want);
  // Sets up a firing of `masks` (per node) with a time-out of `ms` / `ticks` (0: the full one).
  void arm(const NodeMasks& masks, Role role, std::uint32_t ms, std::uint32_t ticks);
  // Stores a node's readings (0 = no echo → the firing's reach).
  void store(std::uint64_t tick, int node, const hal::NodeRanges& r);
  // Clears a node's readings after a lost firing: no data, so the emergency holds.
  void drop(int node);
  // Fires what is still to fire and reads what came back; true when ranges changed.
  bool fire_and_read(std::uint64_t tick, hal::SonarRing& ring);
  // The firing is over (read or lost): the next node of the scan (or the next scan), or a
  // watch firing to pick when due. Returns true when ranges changed.
  bool advance(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want);
  // The scan (or the moving rotation) is over: counts it.
  void end_scan(std::uint64_t tick);

  Phase phase_ = Phase::idle;
  UltrasonicRanges ranges_{};           // what is published
  ScanStats stats_{};                   // node and scan times
  NodeMasks masks_{};                   // firing masks of the table in force
  std::uint32_t active_ = 0;            // table in force
  std::uint32_t node_delay_ = 3;        // node delay in force, ticks
  std::uint32_t timeout_ticks_ = 4;     // full time-out in force, ticks
  std::uint32_t timeout_ms_ = 0;        // time-out the ring was configured with, ms (0: not yet)
  std::uint32_t sound_speed_ = 0;       // speed of sound the ring was configured with, m/s
  // The firing in progress.
  Role role_ = Role::scan;              // what it is for
  bool picked_ = false;                 // decided (else: picked when due)
  bool started_ = false;                // a node of it fired (or was given up): it is committed
  NodeMasks fire_masks_{};              // sensors it fires per node, bit i = index i
  std::uint8_t to_fire_ = 0;            // its nodes not fired yet, bit n = node n
  std::uint8_t to_read_ = 0;            // its nodes fired and not read yet, bit n = node n
  bool got_read_ = false;               // a node of it was read
  std::array<std::uint64_t, hal::kSonarNodes> fired_at_{};  // tick each of its nodes fired
  std::uint32_t fire_ms_ = 0;           // its time-out, ms (0: the configured one)
  std::uint32_t fire_ticks_ = 4;        // its time-out, ticks
  std::uint16_t reach_mm_ = 4950;       // its reach: the range reported for "no echo", mm
  std::uint64_t next_fire_ = 0;         // earliest tick to fire it
  // The sequence.
  int node_ = -1;                       // seed order: the node of the scan fired last (or armed)
  bool watching_ = false;               // the moving schedule is in force
  std::uint32_t priority_ = 0;          // watch: priority sensors in force, bit s-1 = sensor s
  bool watch_next_ = true;              // watch: the watch firing is next (else the rotation)
  int rotation_ = -1;                   // watch: last node of the rotation fired
  bool full_scan_ = false;              // every node has an active sensor in the scan
  std::uint64_t mark_ = 0;              // previous read (or scan start), for node times
  std::uint64_t scan_start_ = 0;        // when the scan in progress started
  std::uint64_t lost_ = 0;              // lost node firings
};

}  // namespace robuter::us
