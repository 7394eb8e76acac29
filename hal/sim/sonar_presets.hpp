// SPDX-License-Identifier: GPL-3.0-or-later
// Named sonar models: which echo paths and random effects a simulated sonar has (SIMULATOR.md).
#pragma once

#include <optional>
#include <string_view>

#include "hal/sim/sonar.hpp"

namespace robuter::sim {

// The realistic model's random effects (SIMULATOR.md gives each one's source or says it has none).
inline constexpr double kRealisticNoiseRelative = 0.005;  // range noise, fraction of the range (1 σ):
                                                          // the Polaroid 6500 module's ±1 % as 2 σ
inline constexpr double kRealisticDropout = 0.01;         // chance an echo is lost (no source gives
                                                          // a rate: the stress value kept)
inline constexpr double kRealisticSpurious = 0.005;       // chance of a noise pulse in a listening
                                                          // window (the seed's filter(): isolated
                                                          // short values in its scans)

// The sonar models a test or a user picks by name. Geometry, timing and calibration stay as
// configured; a preset sets only the effects below, and later keys may still change each one.
enum class SonarPreset {
  ideal,      // the nearest echo, exactly: no multipath, cross-talk or random effect
  stress,     // the project's first noise (before issue #19, `--sonar-noise`): 10 mm range
              // noise, 1 % drop-outs, 0.2 % spurious short echoes drawn below the true range
  realistic,  // Polaroid-type ring (SIMULATOR.md, "The realistic model" and its sources):
              // multipath, node-mate cross-talk, ±1 % range noise, drop-outs, and noise pulses
              // at a uniform time in the listening window
};

// The preset a name ("ideal", "stress", "realistic") stands for; nothing for any other text.
std::optional<SonarPreset> sonar_preset(std::string_view name);
// The preset's name.
std::string_view sonar_preset_name(SonarPreset preset);
// The names, for messages: "ideal, stress or realistic".
std::string_view sonar_preset_choices();
// Sets the preset's effects in `p` (noise, drop-outs, spurious echoes, multipath, cross-talk).
void apply_sonar_preset(SonarPreset preset, SonarParams& p);

}  // namespace robuter::sim
