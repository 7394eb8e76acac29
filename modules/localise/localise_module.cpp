// SPDX-License-Identifier: GPL-3.0-or-later
// The localisation process (localise_module.hpp).
#include "modules/localise/localise_module.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "kernel/cpu_time.hpp"
#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "modules/executor/posture_units.hpp"
#include "modules/localise/map_field.hpp"

namespace robuter {
namespace {

constexpr double kNoJumpLimit = 1e9;       // PoseHistory::add's jump test, off (m, rad per tick)
constexpr double kFieldReach = 2.0;        // the distance field's cap, m (beyond: "far from any wall")
constexpr std::uint64_t kKeepEveryTicks = 100;  // the state file is written at most once a second
constexpr std::int32_t kKeepMoved = 100;        // and only after the robot moved 10 mm (0.1 mm)
constexpr std::int32_t kKeepTurned = 100;       // or turned 1° (0.01°)

loc::FilterParams filter_params(const LocaliseConfig& c) {
  loc::FilterParams p;
  p.min_particles = static_cast<int>(c.min_particles);
  p.max_particles = static_cast<int>(c.max_particles);
  return p;
}

std::int32_t mm(double m) { return static_cast<std::int32_t>(std::lround(std::clamp(m, 0.0, 1e6) * 1000.0)); }

}  // namespace

LocaliseModule::LocaliseModule(Blackboard& bb, const LocaliseConfig& cfg, const robot::RobotModel& robot)
    : cfg_(cfg),
      ring_(robot.ring),
      posture_(bb.posture.reader()),
      ranges_(bb.ranges.reader()),
      request_(bb.localise_request.reader()),
      out_(bb.localisation.writer()),
      readings_(ring_) {}

bool LocaliseModule::init(Kernel&) {
  if (walls_ == nullptr) {
    log::error("localise: no map to localise on");
    return false;
  }
  const auto& g = walls_->geometry();
  field_ = localise::distance_field(*walls_, kFieldReach);
  filter_ = std::make_unique<loc::ParticleFilter>(field_, filter_params(cfg_), cfg_.seed);
  if (filter_->free_cells() == 0) {  // an empty or walled-up map: no pose to start at, none to search
    log::error("localise: the map ({} x {} cells) has no place the robot fits ({} mm from every wall)", g.width, g.height,
               mm(filter_->params().body_clearance));
    return false;
  }
  report_.state = LocaliseState::uncertain;  // no pose yet: the first posture gives it
  out_.publish(report_);                     // advertised: XW answers from the start
  log::info("localise: map {} x {} cells of {} mm, {}..{} particles, {} weighed per activation", g.width, g.height,
            mm(g.resolution), cfg_.min_particles, cfg_.max_particles, cfg_.particles_per_run);
  return true;
}

void LocaliseModule::start_at(const loc::Pose& pose, const loc::Pose& odo, std::uint64_t tick) {
  const double s = static_cast<double>(cfg_.initial_sigma_mm) * 1e-3;
  const double st = static_cast<double>(cfg_.initial_sigma_deg) * std::numbers::pi / 180.0;
  filter_->set_pose(pose, Eigen::Vector3d(s, s, st));
  filter_->rebase(odo);
  started_ = true;
  searching_ = false;
  report_.map_x = executor::metres_to_tenth_mm(pose.x());
  report_.map_y = executor::metres_to_tenth_mm(pose.y());
  report_.map_theta = executor::radians_to_centideg(pose.z());
  report_.odo_x = executor::metres_to_tenth_mm(odo.x());
  report_.odo_y = executor::metres_to_tenth_mm(odo.y());
  report_.odo_theta = executor::radians_to_centideg(odo.z());
  report_.odometry_seq = last_posture_.odometry_seq;
  publish(tick, false);
}

void LocaliseModule::take_inputs(std::uint64_t tick) {
  if (!posture_.updated()) return;
  const Posture p = posture_.copy();
  const loc::Pose odo = localise::to_pose(p.x, p.y, p.theta);
  const bool set = have_posture_ && p.odometry_seq != last_posture_.odometry_seq;
  last_posture_ = p;
  have_posture_ = true;
  if (set) {
    // AC: the seed's "the robot is here" — the odometry and the map pose both start there
    // (docs/LOCALISATION.md, "AC and XA").
    history_.clear();
    start_at(odo, odo, tick);
    log::info("localise: the odometry was set (AC {} {} {}): the map pose is set there too", p.x, p.y, p.theta);
  }
  // AC is told by odometry_seq, not by the size of the jump: no jump limit here.
  history_.add(p.tick, emergency::Pose2{{odo.x(), odo.y()}, odo.z()}, kNoJumpLimit, kNoJumpLimit);
  if (!started_) {
    if (saved_start_) {  // where an earlier run left the robot
      start_at(localise::to_pose(saved_start_->x, saved_start_->y, saved_start_->theta), odo, tick);
      log::info("localise: starting at the kept map pose {} {} {}", saved_start_->x, saved_start_->y, saved_start_->theta);
    } else {
      start_at(odo, odo, tick);  // the map frame starts as the odometry frame
    }
  }
}

void LocaliseModule::run(Kernel& k) {
  const std::int64_t t0 = thread_cpu_us();
  const std::uint64_t tick = k.tick();
  take_inputs(tick);
  if (started_ && request_.updated()) {
    const LocaliseRequest r = request_.copy();
    report_.request_seq = request_.generation();
    const loc::Pose odo = localise::to_pose(last_posture_.x, last_posture_.y, last_posture_.theta);
    if (r.global) {
      filter_->set_global();
      filter_->rebase(odo);
      searching_ = true;
      log::info("localise: global search (XA)");
      publish(tick, false);
    } else {
      start_at(localise::to_pose(r.x, r.y, r.theta), odo, tick);
      log::info("localise: pose set (XA {} {} {})", r.x, r.y, r.theta);
    }
  }
  if (started_) {
    if (filter_->stepping()) {
      if (filter_->weigh_some(static_cast<int>(cfg_.particles_per_run), static_cast<int>(cfg_.traces_per_run)))
        publish(tick, step_odometry_seq_ == last_posture_.odometry_seq);  // an AC since: no correction from it
    } else {
      const loc::Pose odo = localise::to_pose(last_posture_.x, last_posture_.y, last_posture_.theta);
      const std::size_t n = readings_.collect(ranges_.peek(), history_, odo, batch_);
      if (filter_->begin_step(odo, std::span<const loc::SonarReading>(batch_.data(), n))) {
        readings_.mark_used(ranges_.peek());
        step_odometry_ = odo;
        step_odometry_seq_ = last_posture_.odometry_seq;
      }
    }
  }
  keep_pose(tick, false);
  const auto used = static_cast<std::uint32_t>(std::max<std::int64_t>(0, thread_cpu_us() - t0));
  if (used > report_.run_us_max) {
    report_.run_us_max = used;
    out_.publish(report_);
  }
}

void LocaliseModule::keep_pose(std::uint64_t tick, bool now) {
  if (state_file_ == nullptr || !started_ || !have_posture_) return;
  if (!now && (report_.state != LocaliseState::tracking || tick < saved_tick_ + kKeepEveryTicks)) return;
  const executor::PostureUnits m = localise::map_posture(last_posture_, report_);
  const localise::SavedPose p{m.x, m.y, m.theta};
  if (!now && std::abs(p.x - saved_.x) < kKeepMoved && std::abs(p.y - saved_.y) < kKeepMoved &&
      std::abs(p.theta - saved_.theta) < kKeepTurned)
    return;
  state_file_->post(p);
  saved_ = p;
  saved_tick_ = tick;
}

// The last map pose for the next run (the writer's stop writes it).
void LocaliseModule::close(Kernel& k) { keep_pose(k.tick(), true); }

void LocaliseModule::publish(std::uint64_t tick, bool stepped) {
  if (stepped) ++report_.steps;
  const loc::Estimate& e = filter_->estimate();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(e.covariance.topLeftCorner<2, 2>());
  const Eigen::Vector2d values = eig.eigenvalues().cwiseMax(0.0);  // ascending
  const Eigen::Vector2d major = eig.eigenvectors().col(1);
  const double sigma_theta = std::sqrt(std::max(0.0, e.covariance(2, 2)));
  report_.x = executor::metres_to_tenth_mm(e.pose.x());
  report_.y = executor::metres_to_tenth_mm(e.pose.y());
  report_.theta = executor::radians_to_centideg(e.pose.z());
  report_.major_mm = mm(std::sqrt(values(1)));
  report_.minor_mm = mm(std::sqrt(values(0)));
  double axis = std::atan2(major.y(), major.x());  // a direction, not an arrow: into (-90°, 90°]
  if (axis <= -std::numbers::pi / 2) axis += std::numbers::pi;
  if (axis > std::numbers::pi / 2) axis -= std::numbers::pi;
  report_.axis = executor::radians_to_centideg(axis);
  report_.sigma_theta = executor::radians_to_centideg(sigma_theta);
  report_.cluster_pct = static_cast<std::uint8_t>(std::lround(std::clamp(e.cluster_weight, 0.0, 1.0) * 100.0));
  report_.particles = static_cast<std::uint16_t>(std::clamp(e.particles, 0, 65535));
  report_.scouts_fired = static_cast<std::uint32_t>(filter_->scouts_fired());
  report_.tick = tick;
  // The estimate corrects the map frame only as one compact cluster (docs/LOCALISATION.md, "States").
  if (e.compact) {
    searching_ = false;
    report_.state = LocaliseState::tracking;
    if (stepped) {  // the estimate is the map pose of the odometry the step began at
      report_.map_x = report_.x;
      report_.map_y = report_.y;
      report_.map_theta = report_.theta;
      report_.odo_x = executor::metres_to_tenth_mm(step_odometry_.x());
      report_.odo_y = executor::metres_to_tenth_mm(step_odometry_.y());
      report_.odo_theta = executor::radians_to_centideg(step_odometry_.z());
      report_.odometry_seq = step_odometry_seq_;
    }
  } else {
    report_.state = searching_ ? LocaliseState::searching : LocaliseState::uncertain;
  }
  out_.publish(report_);
}

}  // namespace robuter
