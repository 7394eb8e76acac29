// SPDX-License-Identifier: GPL-3.0-or-later
// Fake HALs for the safety tests: a drive that checks every command, a scripted ring, bumpers.
#pragma once

#include <array>
#include <cstdint>

#include "hal/api/bumpers.hpp"
#include "hal/api/drive.hpp"
#include "hal/api/sonar_ring.hpp"
#include "kernel/clock.hpp"
#include "modules/topics.hpp"

namespace robuter::test {

// One command that reached the drive.
struct DriveCommand {
  std::uint64_t tick = 0;   // kernel tick it arrived in
  bool servo_call = false;  // set_servo (true) or command_wheels (false)
  bool on = false;          // servo state asked (servo_call)
  std::int32_t left = 0;    // cm/s (command_wheels)
  std::int32_t right = 0;   // cm/s
};

// Records every command (a fixed ring, no heap) and checks it against the blackboard at the
// moment it arrives: no non-zero speed and no servo-on while an emergency holds, and never a
// speed the emergency module did not grant. Integrates odometry with the set-points.
class FakeDrive final : public hal::Drive {
 public:
  static constexpr std::size_t kLog = 4096;  // commands kept

  // `bb` (may be null) is what the checks read; `tick` (may be null) stamps the commands.
  FakeDrive(const Blackboard* bb, const std::uint64_t* tick) : bb_(bb), tick_(tick) {}

  void set_servo(bool on) override;
  bool servo() const override { return servo_; }
  void command_wheels(std::int32_t left, std::int32_t right) override;
  void commanded(std::int32_t& left, std::int32_t& right) const override {
    left = left_;
    right = right_;
  }
  hal::Odometry odometry() const override { return odo_; }
  void set_odometry(const hal::Odometry& o) override { odo_ = o; }
  hal::DriveHealth health() const override { return health_; }

  // Moves the robot for `dt` seconds at the current set-points (no acceleration limit).
  void advance(double dt_s, double wheel_base_m = 0.6);
  void set_health(hal::DriveHealth h) { health_ = h; }

  std::uint64_t commands() const { return count_; }               // commands received
  const DriveCommand& command(std::uint64_t i) const { return log_[i % kLog]; }  // i < commands()
  std::uint64_t violations() const { return violations_; }        // commands that broke a rule
  const char* first_violation() const { return what_; }           // the first broken rule
  std::int32_t left() const { return left_; }
  std::int32_t right() const { return right_; }
  bool moving() const { return servo_ && (left_ != 0 || right_ != 0); }

 private:
  void record(const DriveCommand& c);
  void violate(const char* what);

  const Blackboard* bb_;
  const std::uint64_t* tick_;
  bool servo_ = false;
  std::int32_t left_ = 0, right_ = 0;      // set-points, cm/s
  hal::Odometry odo_{};
  hal::DriveHealth health_ = hal::DriveHealth::ok;
  std::array<DriveCommand, kLog> log_{};
  std::uint64_t count_ = 0;
  std::uint64_t violations_ = 0;
  const char* what_ = "";
};

// A ring whose sensors see scripted distances: `world[s-1]` mm (0 = no echo). A fired node's
// readings are ready `timeout` after the firing, on the kernel's clock.
class FakeRing final : public hal::SonarRing {
 public:
  static constexpr std::size_t kLog = 1024;  // firings kept

  explicit FakeRing(Clock& clock) : clock_(clock) { world.fill(3000); }
  void configure(std::uint32_t timeout_ms, std::uint32_t sound_speed_m_s) override {
    timeout_ms_ = timeout_ms;
    sound_ = sound_speed_m_s;
    ++configures;
  }
  bool fire(int node, std::uint8_t mask, std::uint32_t timeout_ms = 0) override;
  bool read(int node, hal::NodeRanges& out) override;

  std::array<std::uint16_t, hal::kRingSensors> world{};  // what each sensor would see, mm
  bool refuse_fire = false;                              // every firing fails (busy ring)
  bool never_ready = false;                              // readings never come back
  int configures = 0;                                    // configure() calls
  std::uint32_t timeout_ms() const { return timeout_ms_; }

  // Firings so far and the i-th one (node, mask, time in ns).
  struct Firing {
    int node = 0;
    std::uint8_t mask = 0;
    Nanos at = 0;
    std::uint32_t timeout_ms = 0;  // the firing's time-out, ms (the configured one when none was given)
  };
  std::uint64_t firings() const { return fired_; }
  const Firing& firing(std::uint64_t i) const { return log_[i % kLog]; }

 private:
  struct Pending {
    bool pending = false;
    std::uint8_t mask = 0;
    Nanos ready = 0;
    std::uint32_t reach_mm = 0;  // farthest echo within the firing's time-out, mm
  };
  Clock& clock_;
  std::uint32_t timeout_ms_ = 33, sound_ = 300;
  std::array<Pending, hal::kSonarNodes> nodes_{};
  std::array<Firing, kLog> log_{};
  std::uint64_t fired_ = 0;
};

class FakeBumpers final : public hal::Bumpers {
 public:
  std::uint32_t pressed() const override { return state; }
  std::uint32_t state = 0;  // bit i = bumper i pressed
};

}  // namespace robuter::test
