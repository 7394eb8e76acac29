// SPDX-License-Identifier: GPL-3.0-or-later
// The localisation process: the particle filter on the robot's map, fed by the ring and odometry.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "kernel/config.hpp"
#include "kernel/process.hpp"
#include "modules/localise/lib/distance_field.hpp"
#include "modules/localise/lib/particle_filter.hpp"
#include "modules/localise/map_frame.hpp"
#include "modules/localise/ring_readings.hpp"
#include "modules/localise/state_file.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/topics.hpp"

namespace robuter {

// Monte Carlo localisation as a periodic process (docs/LOCALISATION.md, "The module"): each
// activation either begins a filter step (the odometry moved 0.1 m or turned 0.1 rad: every
// particle moved, the ring's ranges since the last step taken) or weighs up to
// particles_per_run more particles; the last weighing resamples and publishes the estimate.
// Everything is allocated at init(); nothing after.
class LocaliseModule final : public Process {
 public:
  // Its own section ([localise]) and the robot model (the ring's geometry), nothing else.
  LocaliseModule(Blackboard& bb, const LocaliseConfig& cfg, const robot::RobotModel& robot);
  // The map's walls (an a-priori map, or the place graph's), in the map frame; start-up only.
  void set_map(const plan::OccupancyMap& walls) { walls_ = &walls; }
  bool init(Kernel& k) override;
  void run(Kernel& k) override;

  // Where the map pose is kept across restarts (start-up only; null = nowhere), and the pose an
  // earlier run kept: the first start pose instead of the odometry's.
  void set_state_file(localise::StateFileWriter* w) { state_file_ = w; }
  void set_start(const localise::SavedPose& p) { saved_start_ = p; }
  void close(Kernel& k) override;

  // The filter, for tests and the bench (null before init).
  const loc::ParticleFilter* filter() const { return filter_.get(); }

 private:
  // The robot is at map pose `pose` now (odometry `odo`): the filter starts there.
  void start_at(const loc::Pose& pose, const loc::Pose& odo, std::uint64_t tick);
  // Requests (XA), the odometry's jumps (AC) and the history of postures.
  void take_inputs(std::uint64_t tick);
  // The estimate and the state; after a step (`stepped`) in tracking, the correction too.
  void publish(std::uint64_t tick, bool stepped);

  const LocaliseConfig cfg_;
  const robot::Ring ring_;
  const plan::OccupancyMap* walls_ = nullptr;
  Reader<Posture> posture_;
  Reader<UltrasonicRanges> ranges_;
  Reader<LocaliseRequest> request_;
  Writer<Localisation> out_;
  loc::DistanceField field_;                      // built at init from walls_
  std::unique_ptr<loc::ParticleFilter> filter_;   // built at init
  emergency::PoseHistory history_;                  // the executor's recent postures (odometry)
  localise::RingReadings readings_;
  std::array<loc::SonarReading, loc::ParticleFilter::kMaxReadings> batch_{};
  Localisation report_{};             // what is published
  bool started_ = false;              // the filter has a start pose
  bool searching_ = false;            // a global search has not converged yet
  loc::Pose step_odometry_ = loc::Pose::Zero();  // the odometry the step under way began at
  std::uint32_t step_odometry_seq_ = 0;          // and the odometry frame it is in (Posture.odometry_seq)
  Posture last_posture_{};            // the last posture seen
  bool have_posture_ = false;
  localise::StateFileWriter* state_file_ = nullptr;   // where the map pose is kept, or null
  std::optional<localise::SavedPose> saved_start_;    // an earlier run's last map pose
  std::uint64_t saved_tick_ = 0;                      // tick of the last pose handed to the state file
  localise::SavedPose saved_{};                       // and that pose
  // Hands the map pose now to the state file: at most once a second while tracking, when it
  // moved; `now` forces it (shutdown).
  void keep_pose(std::uint64_t tick, bool now);
};

}  // namespace robuter
