// SPDX-License-Identifier: GPL-3.0-or-later
// SITL backend: the HAL's drive, ultrasonic ring and bumpers implemented on the simulated Robuter.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "hal/api/bumpers.hpp"
#include "hal/api/drive.hpp"
#include "hal/api/sonar_ring.hpp"
#include "hal/sim/result.hpp"
#include "hal/sim/robot.hpp"
#include "hal/sim/sim_config.hpp"
#include "hal/sim/sonar.hpp"
#include "hal/sim/sonar_presets.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/world.hpp"
#include "hal/sitl/ptu_emulator.hpp"
#include "kernel/config.hpp"

namespace robuter::hal {

// Everything the simulated robot needs, chosen on the command line or in tests.
struct SimOptions {
  std::string world_file;        // world to load; empty = the default lab
  std::uint64_t seed = 1;        // seed of every random source
  bool odometry_noise = false;   // encoder noise and slip on
  sim::SonarPreset sonar_model = sim::SonarPreset::ideal;  // the sonars' base model (SIMULATOR.md): the
                                                           // [sim] tables may change it; robuterd's
                                                           // command line defaults to realistic
  PtuParams ptu;                 // the emulated pan-tilt unit: limits and power-up state
  std::function<void(sim::SimConfig&)> adjust;  // tests: last word on the simulated robot's parameters
};

// The simulated robot the firmware's configuration describes: its robot model ([robot], [ptu]
// mount) and ring settings ([sonar]), before the [sim] tables.
sim::SimConfig firmware_sim_defaults(const Config& cfg);

// The simulated robot's own parameters: firmware_sim_defaults() with the options' sonar model,
// then the configuration's [sim] tables ([sim.robot], [sim.odometry], [sim.sonar] — whose
// `model` and effect keys are the last word on the sonars —, [[sim.sonar.sensor]],
// [sim.pan_tilt]: the robot may differ from what the firmware believes), then the odometry noise. The odometry
// always integrates with the firmware's wheel base and the ring ranges with its speed of sound.
sim::Result<sim::SimConfig> simulated_robot_config(const Config& cfg, const SimOptions& opt);

// The last firing of the pan-tilt's two sonars (channel 7), for pictures and tests.
struct PanTiltShot {
  bool valid = false;                      // a firing has happened
  double time_s = 0.0;                     // simulated time of the firing, s
  double angle_deg = 0.0;                  // the unit's pan angle then, degrees (pos·185/3600)
  std::array<std::uint16_t, 2> mm{};      // reported ranges, mm (0: no echo); [1] looks along
                                           // angle + 90°, [0] along angle − 90° (seed ptu.c)
};

class SimRobot;

// The drive: servo, wheel set-points, odometry (the simulated encoders).
class SimDrive final : public Drive {
 public:
  explicit SimDrive(SimRobot& r) : r_(r) {}
  void set_servo(bool on) override;
  bool servo() const override;
  void command_wheels(std::int32_t left_cm_s, std::int32_t right_cm_s) override;
  void commanded(std::int32_t& left_cm_s, std::int32_t& right_cm_s) const override;
  Odometry odometry() const override;
  void set_odometry(const Odometry& o) override;
  DriveHealth health() const override { return DriveHealth::ok; }

 private:
  SimRobot& r_;
};

// The ring: nodes fire single-shot; a node measures when it fires and reports when every fired
// sensor has heard its echo, or at the firing's time-out when one has not (seed 002: a full scan
// of READs took ≈ 29 ticks with a 33 ms time-out, so a READ returned once its echoes were in). Channel 7
// (kPanTiltChannel) fires the pan-tilt's two sonars (mask bits 0 and 1) at the emulated unit's
// current pan angle, with the pan-tilt's own time-out and sound speed (15 ms, 335 m/s: the
// seed's READ C=7 T=15 V=335); configure() changes the ring's only.
class SimSonarRing final : public SonarRing {
 public:
  explicit SimSonarRing(SimRobot& r) : r_(r) {}
  void configure(std::uint32_t timeout_ms, std::uint32_t sound_speed_m_s) override;
  bool fire(int node, std::uint8_t mask, std::uint32_t timeout_ms = 0) override;
  bool read(int node, NodeRanges& out) override;

 private:
  SimRobot& r_;
};

class SimBumpers final : public Bumpers {
 public:
  explicit SimBumpers(SimRobot& r) : r_(r) {}
  std::uint32_t pressed() const override;

 private:
  SimRobot& r_;
};

// The simulated robot in its world; stepped by the kernel's clock through SimStepper.
class SimRobot {
 public:
  // Loads the world and builds the robot at the world's start pose; error() says why not.
  SimRobot(const Config& cfg, const SimOptions& opt);

  const std::optional<std::string>& error() const { return error_; }
  // Advances the simulation to time `t_s` (seconds of the kernel clock).
  void advance_to(double t_s);

  SimDrive& drive() { return drive_; }
  SimSonarRing& ring() { return ring_; }
  SimBumpers& bumpers() { return bumpers_; }
  const sim::World& world() const { return *world_; }
  sim::Robot& robot() { return *robot_; }
  const sim::Robot& robot() const { return *robot_; }
  PtuEmulator& ptu() { return ptu_; }
  const PtuEmulator& ptu() const { return ptu_; }
  const sim::SonarParams& ring_params() const { return sonar_->params(); }
  const sim::SonarParams& pan_tilt_params() const { return pan_tilt_sonar_->params(); }
  const sim::PanTiltMount& pan_tilt_mount() const { return pan_tilt_mount_; }
  const PanTiltShot& last_pan_tilt() const { return last_pan_tilt_; }
  // Robot-frame direction (rad) of the pan-tilt sonar read as channel-7 index 1 at pan angle
  // `angle_deg`: angle + 90° (seed ptu.c stores it at sector (angle + 90) / 5); index 0 looks
  // the opposite way.
  static double pan_tilt_direction(double angle_deg);
  const sim::RingLayout& layout() const { return layout_; }
  double time() const { return time_; }

 private:
  friend class SimDrive;
  friend class SimSonarRing;
  friend class SimBumpers;

  // Channel 7: measures both pan-tilt sonars now; results ready after the pan-tilt time-out.
  bool fire_pan_tilt(std::uint8_t mask);

  // A node's firing in progress.
  struct Firing {
    bool pending = false;      // fired, results not yet taken
    double ready_s = 0.0;      // simulated time the results are ready, s
    std::uint8_t mask = 0;     // sensors fired, bit i = index i
    NodeRanges mm{};           // ring node: ranges measured at firing, mm (0: no echo in time)
    std::array<std::uint16_t, 2> pan_tilt_mm{};  // channel 7: ranges measured at firing, mm
  };

  std::optional<std::string> error_;       // why the robot could not be built
  std::unique_ptr<sim::World> world_;      // obstacles
  std::unique_ptr<sim::Robot> robot_;      // body, drive, odometry
  std::unique_ptr<sim::SonarModel> sonar_; // ring sonar model
  std::unique_ptr<sim::SonarModel> pan_tilt_sonar_;  // pan-tilt sonar model (its own params)
  sim::PanTiltMount pan_tilt_mount_{};     // where the pan-tilt carries its sonars
  PtuEmulator ptu_;                        // the pan-tilt unit
  PanTiltShot last_pan_tilt_{};            // the last channel-7 firing
  sim::RingLayout layout_{};               // mounts of sensors 1..24
  sim::Rng rng_{1};                        // sonar noise source
  bool servo_ = false;                     // servo on
  std::int32_t left_ = 0, right_ = 0;      // set-points accepted, cm/s
  std::array<Firing, kSonarNodes + 2> firings_{};  // per node (and the pan-tilt channel)
  double time_ = 0.0;                      // simulated time, s
  SimDrive drive_{*this};
  SimSonarRing ring_{*this};
  SimBumpers bumpers_{*this};
};

}  // namespace robuter::hal
