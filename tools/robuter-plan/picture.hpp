// SPDX-License-Identifier: GPL-3.0-or-later
// The tool's picture of a plan (map, grown obstacles, path, footprints, goal; title with the outcome).
#pragma once

#include <string>

#include "modules/planner/lib/planner.hpp"
#include "modules/planner/lib/result.hpp"

namespace robuter::plan::tool {

// Why: the thesis wrote a picture of the map and the path for every plan; so does the tool
// (drawn by modules/planner/picture, as the firmware's pictures). `result`, when given, is the
// plan's outcome for the title (with the reason when there is no path). A .pdf path writes a PDF.
Status write_picture(const Planner& planner, const Pose2& start, Point2 goal,
                     const std::string& path, const PlanResult* result = nullptr);

}  // namespace robuter::plan::tool
