// SPDX-License-Identifier: GPL-3.0-or-later
// The envelope fed by the firmware: ring readings and postures into the grid, requests judged on it.
#pragma once

#include <array>
#include <cstdint>

#include "kernel/config.hpp"
#include "modules/emergency/envelope_judge.hpp"
#include "modules/emergency/evidence_grid.hpp"
#include "modules/emergency/pose_history.hpp"
#include "modules/emergency/start_blind.hpp"
#include "modules/emergency/swept_envelope.hpp"
#include "modules/topics.hpp"

namespace robuter::emergency {

// The grid and envelope settings of a configuration (robot model, [robot], [emergency]) at a tick
// of `tick_s` seconds.
GridSettings grid_settings(const EmergencyConfig& cfg);
EnvelopeSettings envelope_settings(const EmergencyConfig& cfg, const RobotConfig& robot, double tick_s);

// Keeps the evidence grid up to date from the executor's postures and the ring's readings (each
// placed at the pose of its read tick: the simulated ring measures there; see docs/SAFETY.md §13)
// and judges requests on it, adding the braking of the current motion when a request reverses a
// wheel. Allocates at construction only.
class RingEnvelope final : public EnvelopeJudge {
 public:
  RingEnvelope(const EmergencyConfig& cfg, const RobotConfig& robot, double tick_s);
  // The kernel's tick length, s (init: ticks-based limits follow it).
  void set_tick(double tick_s);
  // One activation at `tick`: the newest posture and ranges. Work: one grid certification per
  // new reading (≤ 24), one of the body per tick, at most one window move.
  // `at_rest`: the robot stands still (the emergency module's rule).
  void observe(std::uint64_t tick, const Posture& posture, const UltrasonicRanges& ranges, bool at_rest);
  EnvelopeVerdict judge(std::int32_t left, std::int32_t right, bool bumpers) override;

  // The a-priori map's structure, which explains echoes (narrowing); it must outlive the envelope.
  void set_known_structure(KnownStructure* known) { grid_.set_known_structure(known); }
  const EvidenceGrid& grid() const { return grid_; }
  const Pose2& pose() const { return now_; }
  const StartBlind& start() const { return start_; }
  std::uint32_t resets() const { return resets_; }

 private:
  EmergencyConfig cfg_;
  RobotConfig robot_;
  double tick_s_;                        // kernel tick, s
  EvidenceGrid grid_;                    // the evidence
  SweptEnvelope env_;                    // the swept body
  StartBlind start_;                     // where a creep may go: blind from the last start pose
  PoseHistory history_;                  // recent postures
  std::array<std::uint64_t, kSensors> seen_{};  // read tick of each sensor's last reading taken
  // Each sensor's last two readings with an echo, [2 (s − 1) + (newest ? 0 : 1)]: what narrowing
  // tests an arc against point by point (the sensor's own previous one among them).
  std::array<SeenCone, 2 * kSensors> cones_{};
  std::uint64_t posture_tick_ = ~0ull;   // tick of the last posture taken
  std::uint64_t body_tick_ = 0;          // tick the body was last certified
  std::uint64_t reset_tick_ = 0;         // readings older than this belong to an old odometry frame
  std::uint64_t tick_ = 0;               // tick of the current activation
  std::uint64_t last_reading_ = 0;       // read tick of the newest reading taken, ticks
  Pose2 now_;                            // the robot's pose now (extrapolated), odometry frame
  std::uint32_t resets_ = 0;             // odometry frame changes seen (count)
};

}  // namespace robuter::emergency
