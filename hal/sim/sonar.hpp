// SPDX-License-Identifier: GPL-3.0-or-later
// Ultrasonic range model: a beam cone, nearest specular echo, grazing-incidence misses,
// time-out range, blanking, multipath and cross-talk by specular bounces (image method), and
// optional seeded noise, drop-outs and spurious short echoes.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "hal/sim/rng.hpp"
#include "hal/sim/segment_grid.hpp"
#include "hal/sim/world.hpp"
#include "robot/robot_model.hpp"

namespace robuter::sim {

// How one kind of sonar behaves. Defaults are the Robuter ring's (seed 002: time-out 33 ms,
// calibrated sound speed 300 m/s, so about 5 m of range).
struct SonarParams {
  double half_angle = robot::kRobuter.ring.half_angle;  // half-angle of the beam cone, rad (< 90°)
  double timeout = 0.033;                  // listening time after firing, s
  double sound_speed = 300.0;              // speed of sound in the air, m/s (echo times, time-out range)
  double ranging_speed = 0.0;              // speed the receiver turns echo times into ranges with
                                           // (the firmware's calibration), m/s; 0 = sound_speed
  double min_range = 0.15;                 // echoes nearer than this are lost in blanking, m
  double max_incidence = deg_to_rad(40.0); // echoes hitting a standard surface more obliquely are lost, rad
  double max_incidence_smooth = deg_to_rad(22.5); // the same for a smooth surface (Webots' sonar), rad
  double max_incidence_rough = deg_to_rad(90.0);  // the same for a rough one (diffuse: any), rad
  double noise_sigma = 0.0;                // Gaussian range noise, m
  double noise_relative = 0.0;             // extra Gaussian noise proportional to range, fraction
  double spurious_probability = 0.0;       // chance a reading is a spurious short echo
  double dropout_probability = 0.0;        // chance a reading misses its echo entirely
  bool spurious_in_window = false;         // false: a spurious echo is drawn between min_range
                                           // and the true range (always short); true: it is a
                                           // noise pulse at a uniform time of the listening
                                           // window, heard only when before the true echo
  bool multipath = false;                  // a beam meeting a surface too obliquely to echo
                                           // bounces off it and may return by a surface beyond
                                           // at normal incidence: a long reading
  bool crosstalk = false;                  // transducers fired together hear each other's
                                           // echoes (specular bounce into the cone) when those
                                           // arrive before their own
  double scale = 1.0;                      // reported = scale · ranging_scale() · range + offset (calibration error)
  double offset = 0.0;                     // see scale, m
  double no_echo = 0.0;                    // value reported when nothing echoes in time, m

  // Farthest echo that returns before the time-out, m.
  double max_range() const { return timeout * sound_speed * 0.5; }
  // Reported range per metre of true range from the ranging speed alone.
  double ranging_scale() const { return ranging_speed > 0.0 ? ranging_speed / sound_speed : 1.0; }
};

// Where a sensor sits on the robot and which way it looks.
struct SonarMount {
  int number = 0;           // sensor number, 1..24 on the ring (0 for other sensors)
  Vec2 position;            // transducer position in the robot frame, m
  double direction = 0.0;   // beam axis in the robot frame, rad (0 forward, counter-clockwise)
};

// The nearest echo of one firing, before noise and calibration are applied.
struct Echo {
  bool found = false;       // whether anything echoed within range
  double range = 0.0;       // distance from the transducer to the echoing point, m
  Vec2 point;               // echoing point in the world, m
  double incidence = 0.0;   // angle between the ray and the surface normal there, rad
  int segment = -1;         // world edge that echoed
};

// Computes sonar readings in one world. Holds scratch buffers sized at construction, so no
// measurement allocates; one model per thread.
class SonarModel {
 public:
  // The world must outlive the model.
  SonarModel(const World& world, const SonarParams& params);

  // The ideal echo for a transducer at `origin` looking along `direction` (world frame):
  // the nearest visible surface point inside the cone and the range whose incidence is within
  // its surface kind's max incidence. Surfaces nearer than min_range blind the sensor (no echo).
  Echo trace(const Vec2& origin, double direction);
  // The same for a sensor mounted on a robot at `robot`.
  Echo trace(const Pose& robot, const SonarMount& mount);

  // The reported range, m (params().no_echo without an echo): trace, then drop-outs, spurious
  // echoes and noise drawn from `rng` (none when rng is null), then the calibration line.
  double measure(const Pose& robot, const SonarMount& mount, Rng* rng = nullptr);
  double measure_from(const Vec2& origin, double direction, Rng* rng = nullptr);
  // The transducers of one firing (a node's, fired together), one reported range each in `out`
  // (sized as `mounts`): what each hears first — its own echo, with `multipath` its echo by a
  // bounce off a surface too oblique to echo, with `crosstalk` a node-mate's echo — then the
  // random effects of measure(), drawn sensor by sensor in order.
  void measure_firing(const Pose& robot, std::span<const SonarMount> mounts, std::span<double> out,
                      Rng* rng = nullptr);

  const SonarParams& params() const { return params_; }
  // Replaces the behaviour (and its cached trigonometry).
  void set_params(const SonarParams& params);

 private:
  // Where a traced beam may look: beyond the line through `point` with normal `normal` (the
  // side it points to), edge `skip` ignored. The image of a transducer sees only the world on
  // the real side of the surface that mirrors it.
  struct Beyond {
    Vec2 point;       // a point of the mirror line, world frame, m
    Vec2 normal;      // unit normal, pointing to the side the beam may see
    int skip = -1;    // the mirror's own edge
  };
  // The trace, optionally restricted to what lies beyond a mirror.
  Echo trace_beyond(const Vec2& origin, double direction, const Beyond* beyond);
  // First arrival at a transducer (range, m; negative when nothing in time), before the random
  // effects: own echo, multipath, and the echoes of the mates fired with it (their origins and
  // unit beam axes, world frame).
  double arrival(const Vec2& origin, double direction, std::span<const Vec2> mate_origins,
                 std::span<const Vec2> mate_axes);
  // The random effects and the calibration line applied to a first arrival.
  double report(double range, Rng* rng);

  // One edge's best echo candidate inside the cone.
  struct Candidate {
    double range;     // distance to the nearest in-cone point of the edge, m
    Vec2 point;       // that point, world frame, m
    double cos_incidence; // cosine of the incidence angle there
    int segment;      // edge index
    bool echoes;      // whether it may still be the echo (incidence allows it, not yet found hidden)
    bool grazing;     // whether the incidence is too oblique to echo (it reflects the beam away)
  };

  const World& world_;                 // the world; outlives the model
  SonarParams params_;                 // behaviour
  double cos_half_ = 1.0;              // cos(half_angle), cached
  double sin_half_ = 0.0;              // sin(half_angle), cached
  std::array<double, kSurfaceKinds> cos_max_incidence_{};  // cos of each surface kind's max incidence, cached
  std::vector<Candidate> candidates_;  // scratch, capacity = edge count
  GridScratch scratch_;                // grid query scratch
};

// World-frame position and direction of a mounted sensor (the direction is not wrapped).
inline void sensor_in_world(const Pose& robot, const SonarMount& m, Vec2& origin,
                            double& direction) {
  origin = to_world(robot, m.position);
  direction = robot.theta + m.direction;
}

}  // namespace robuter::sim
