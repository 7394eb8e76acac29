// SPDX-License-Identifier: GPL-3.0-or-later
// Loading worlds: seed 000's environment files (.env) and the project's TOML worlds (.toml).
#pragma once

#include <filesystem>
#include <string_view>

#include "hal/sim/footprint.hpp"
#include "hal/sim/result.hpp"
#include "hal/sim/world.hpp"

namespace robuter::sim {

// Why: which files of a worlds folder are worlds: ".toml" and ".env", but not a place graph
// kept beside its world ("NAME.places.toml", docs/PLACES.md).
bool is_world_file(const std::filesystem::path& path);

// Loads a world by extension: ".toml" (project format) or anything else as a seed-000
// environment file. Errors name the file and line; nothing throws.
Result<World> load_world(const std::filesystem::path& path, const RobotGeometry& robot = {});

// Seed 000 (annex 1) environment file: the number of obstacles on the first line, then for
// each obstacle a line with its vertex count followed by one "x y" line per vertex (metres, in
// order, clockwise or counter-clockwise; the polygon closes by itself). Blank lines are
// ignored. A two-vertex obstacle is a thin wall. `file` is only used in messages.
Result<World> parse_world_env(std::string_view text, std::string_view file);

// The project's TOML world format (docs/SIMULATOR.md): [world], [start], [goal], [[wall]] with
// doors, [[box]], [[rectangle]], [[polygon]], [[marker]]. The start pose is checked against the
// obstacles with the `robot` footprint.
Result<World> parse_world_toml(std::string_view text, std::string_view file,
                               const RobotGeometry& robot = {});

// Checks a world's start pose and goal against its obstacles: the body at the start must not
// touch an edge nor sit inside an obstacle, and the goal must not be inside one.
Status check_world_poses(const World& world, const RobotGeometry& robot);

}  // namespace robuter::sim
