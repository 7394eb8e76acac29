// The ring's non-blocking firing sequence (seed us.c read_sensors): one state machine step per activation.
#pragma once

#include <array>
#include <cstdint>

#include "hal/api/sonar_ring.hpp"
#include "modules/topics.hpp"
#include "modules/us/scan_stats.hpp"

namespace robuter::sonar {

// Sensors to fire per node: bit i = index i of that node.
using NodeMasks = std::array<std::uint8_t, hal::kSonarNodes>;

// Splits a 24-bit table (bit s-1 = sensor s) into per-node firing masks.
NodeMasks node_masks(std::uint32_t active);
// The first node after `after` (−1: from the start) with a sensor to fire, or −1.
int next_node(const NodeMasks& masks, int after);

// What the ring should do, as settings and the emergency module's selection say.
struct ScanRequest {
  std::uint32_t active = 0xFFFFFF;      // sensors to fire, bit s-1 = sensor s
  std::uint32_t node_delay_ticks = 3;   // wait between a node's read and the next firing, ticks
  std::uint32_t timeout_ms = 33;        // echo time-out, ms
  std::uint32_t timeout_ticks = 4;      // the same rounded up to ticks
  std::uint32_t sound_speed_m_s = 300;  // calibrated speed of sound, m/s
};

// Fires every node that has an active sensor, single-shot, one node at a time, waiting the node
// delay between a read and the next firing; reads a node once its time-out has passed. A new
// table, delay or time-out applies when the next scan starts. Never blocks: each step does what
// is due now and returns. No heap.
class RingScanner {
 public:
  // Extra ticks a node may take beyond its time-out (or a busy ring may refuse a firing) before
  // its readings are dropped as lost.
  static constexpr std::uint32_t kGraceTicks = 10;

  // Advances the sequence at `tick`; true when ranges() changed (new readings or a new table).
  bool step(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want);

  const UltrasonicRanges& ranges() const { return ranges_; }
  const ScanStats& stats() const { return stats_; }
  std::uint32_t active() const { return active_; }       // table of the scan in progress
  std::uint64_t lost_reads() const { return lost_; }     // nodes whose readings never came

 private:
  enum class Phase : std::uint8_t { idle, wait_fire, wait_read };

  // Starts a scan with `want`: applies the table and time-out, zeroes sensors switched off.
  // Returns true when ranges changed.
  bool start_scan(std::uint64_t tick, hal::SonarRing& ring, const ScanRequest& want);
  // Stores a node's readings (0 = no echo → the time-out range).
  void store(std::uint64_t tick, int node, const hal::NodeRanges& r);
  // Clears a node's readings after a lost firing: no data, so the emergency holds.
  void drop(int node);
  // Moves to the next node of the scan, or ends the scan.
  void advance(std::uint64_t tick);

  Phase phase_ = Phase::idle;
  UltrasonicRanges ranges_{};           // what is published
  ScanStats stats_{};                   // node and scan times
  NodeMasks masks_{};                   // firing masks of the scan in progress
  std::uint32_t active_ = 0;            // table of the scan in progress
  std::uint32_t node_delay_ = 3;        // node delay of the scan, ticks
  std::uint32_t timeout_ticks_ = 4;     // time-out of the scan, ticks
  std::uint32_t timeout_ms_ = 0;        // time-out the ring was configured with, ms (0: not yet)
  std::uint32_t sound_speed_ = 0;       // speed of sound the ring was configured with, m/s
  std::uint16_t no_echo_mm_ = 4950;     // range reported for "no echo", mm
  int node_ = -1;                       // node being fired / read
  bool full_scan_ = false;              // every node has an active sensor in this scan
  std::uint64_t next_fire_ = 0;         // earliest tick to fire node_
  std::uint64_t fire_tick_ = 0;         // when node_ was fired
  std::uint64_t mark_ = 0;              // previous read (or scan start), for node times
  std::uint64_t scan_start_ = 0;        // when the scan in progress started
  std::uint64_t lost_ = 0;              // lost node firings
};

}  // namespace robuter::sonar
