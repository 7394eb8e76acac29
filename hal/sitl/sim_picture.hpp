// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures of the simulated robot as the firmware left it: world, robot, trail, ring beams, last pan-tilt firing.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "hal/sim/render.hpp"
#include "hal/sitl/sim_robot.hpp"

namespace robuter::hal {

// The scene of `r` now: its world, true pose and trail; one beam per ring sensor from `mm`
// (entry i = sensor i + 1, mm; 0 = inactive or nothing) where bit i of `no_echo` marks a
// sensor that heard nothing; and the last pan-tilt firing, if there was one. `r` must outlive
// the scene.
sim::Scene sim_scene(const SimRobot& r, std::span<const std::uint16_t, kRingSensors> mm,
                     std::uint32_t no_echo, const std::string& title);

// Writes that scene to `path` (.png, .svg or .pdf by extension), titled with the world, the time
// and the outcome (where the robot ended and `outcome`, e.g. the emergency); the problem when it
// could not, or what was laid out.
sim::Result<picture::Layout> write_sim_picture(const SimRobot& r,
                                             std::span<const std::uint16_t, kRingSensors> mm,
                                             std::uint32_t no_echo, const std::string& outcome,
                                             const std::string& path);

// True when `path` ends in .png, .svg or .pdf (checked at start-up, before running).
bool picture_path_ok(const std::string& path);

// Frees the renderer's process-wide caches; call once when no more pictures will be drawn.
void release_picture_caches();

}  // namespace robuter::hal
