// PNG pictures of a plan (cairo): map, expanded obstacles, path and footprints.
#pragma once

#include <string>

#include "modules/planner/lib/planner.hpp"
#include "modules/planner/lib/result.hpp"

namespace robuter::plan::tool {

// Why: the thesis wrote a picture of the map and the path for every plan; so does the tool.
Status write_picture(const Planner& planner, const Pose2& start, Point2 goal,
                     const std::string& path);

}  // namespace robuter::plan::tool
