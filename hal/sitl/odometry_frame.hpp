// SPDX-License-Identifier: GPL-3.0-or-later
// Where the firmware's odometry frame lies in the simulated world: written each tick by the kernel's thread, read by picture threads.
#pragma once

#include <Eigen/Geometry>

#include <atomic>
#include <cstdint>

#include "hal/sim/types.hpp"

namespace robuter::hal {

// A sequence lock over one pose (no allocation, no waiting for the writer): the odometry frame's
// origin and x axis in the world, truth ∘ odometry⁻¹ — what turns the planner's (odometry) map
// into world coordinates for its pictures.
class OdometryFrame {
 public:
  // Kernel thread: the frame from the true pose and the odometry at the same instant.
  void publish(const sim::Pose& truth, const sim::Pose& odometry) {
    const double h = truth.theta - odometry.theta;
    const sim::Vec2 origin = sim::Vec2(truth.x, truth.y) - Eigen::Rotation2Dd(h) * sim::Vec2(odometry.x, odometry.y);
    seq_.fetch_add(1, std::memory_order_acq_rel);  // odd: being written
    x_.store(origin.x(), std::memory_order_relaxed);
    y_.store(origin.y(), std::memory_order_relaxed);
    heading_.store(h, std::memory_order_relaxed);
    seq_.fetch_add(1, std::memory_order_release);  // even: done
  }
  // Any thread: the last frame published (m, m, rad); the origin before the first.
  sim::Pose read() const {
    for (;;) {
      const std::uint64_t before = seq_.load(std::memory_order_acquire);
      const sim::Pose p{x_.load(std::memory_order_relaxed), y_.load(std::memory_order_relaxed),
                        heading_.load(std::memory_order_relaxed)};
      std::atomic_thread_fence(std::memory_order_acquire);
      if (before % 2 == 0 && seq_.load(std::memory_order_relaxed) == before) return p;
    }
  }

 private:
  std::atomic<std::uint64_t> seq_{0};  // even: stable; odd: a write in progress
  std::atomic<double> x_{0.0};         // frame origin in the world, m
  std::atomic<double> y_{0.0};         // frame origin in the world, m
  std::atomic<double> heading_{0.0};   // frame x axis in the world, rad
};

}  // namespace robuter::hal
