// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures of a plan (cairo), drawn from a PlanSnapshot in the world frame: map, grown obstacles, path, goal, outcome.
#pragma once

#include <cairo.h>

#include <string>

#include "modules/planner/lib/plan_snapshot.hpp"
#include "modules/planner/lib/result.hpp"
#include "picture/frame.hpp"
#include "picture/layout.hpp"

namespace robuter::plan {

// How to draw a plan: where its map frame lies in the world, and what to call it.
struct PlanPictureOptions {
  Pose2 map_in_world{};          // m, rad: the map frame's origin and x axis in the world frame
  bool world_frame = true;       // false: the placement is unknown; drawn in the map's own frame
  std::string what = "plan";     // the title's first words, e.g. "robuter-plan" or "robuterd plan g001-003"
  picture::FrameOptions page{};  // scale and page size (default: ≥ 1000 px wide)
};

// The outcome in words: "path found, 4.32 m" or "no path: goal blocked — …" (the reason).
std::string plan_outcome(const PlanSnapshot& snapshot);

// The page for a snapshot: the map, its start and goal in the world frame, with room for the words.
picture::Frame plan_frame(const PlanSnapshot& snapshot, const PlanPictureOptions& options);

// Why: the thesis wrote a picture of the map and the path for every plan; the tool and the
// firmware's picture writer both draw them here. Obstacles black, grown obstacles grey (orange
// where the rectangle fits at some headings), unknown light grey, the path red (the followed
// prefix darker and thicker), the rectangle's outline blue at turns and every 0.5 m, the start
// green, the goal a magenta cross; a title (what, when, outcome — the reason when there is no
// path), axes and a scale bar in metres, a legend. What was laid out.
picture::Layout draw_plan_picture(cairo_t* cr, const PlanSnapshot& snapshot, const picture::Frame& frame,
                                  const PlanPictureOptions& options);

// Writes the picture as PNG (SVG or PDF for a .svg or .pdf path). Blocking file I/O, text through cairo's
// fonts: never call it from the periodic path (the firmware's writer thread does).
Result<picture::Layout> write_plan_picture(const PlanSnapshot& snapshot, const std::string& path,
                                           const PlanPictureOptions& options = {});

}  // namespace robuter::plan
