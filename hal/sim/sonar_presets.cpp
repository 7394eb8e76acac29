// SPDX-License-Identifier: GPL-3.0-or-later
// The named sonar models' values; each value's source is in SIMULATOR.md.
#include "hal/sim/sonar_presets.hpp"

#include <array>
#include <utility>

namespace robuter::sim {

namespace {
// Every model with its name, in the order the messages list them.
constexpr std::array<std::pair<std::string_view, SonarPreset>, 3> kNames{{
    {"ideal", SonarPreset::ideal}, {"stress", SonarPreset::stress}, {"realistic", SonarPreset::realistic}}};
}  // namespace

std::optional<SonarPreset> sonar_preset(std::string_view name) {
  for (const auto& [n, preset] : kNames)
    if (n == name) return preset;
  return std::nullopt;
}

std::string_view sonar_preset_name(SonarPreset preset) {
  for (const auto& [n, p] : kNames)
    if (p == preset) return n;
  return kNames[0].first;
}

std::string_view sonar_preset_choices() { return "ideal, stress or realistic"; }

void apply_sonar_preset(SonarPreset preset, SonarParams& p) {
  p.noise_sigma = 0.0;
  p.noise_relative = 0.0;
  p.dropout_probability = 0.0;
  p.spurious_probability = 0.0;
  p.spurious_in_window = false;
  p.multipath = false;
  p.crosstalk = false;
  switch (preset) {
    case SonarPreset::ideal:
      break;
    case SonarPreset::stress:
      p.noise_sigma = 0.01;
      p.dropout_probability = 0.01;
      p.spurious_probability = 0.002;
      break;
    case SonarPreset::realistic:
      p.noise_relative = kRealisticNoiseRelative;
      p.dropout_probability = kRealisticDropout;
      p.spurious_probability = kRealisticSpurious;
      p.spurious_in_window = true;
      p.multipath = true;
      p.crosstalk = true;
      break;
  }
}

}  // namespace robuter::sim
