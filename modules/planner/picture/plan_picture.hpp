// PNG pictures of a plan (cairo), drawn from a PlanSnapshot: map, expanded obstacles, path, footprints.
#pragma once

#include <string>

#include "modules/planner/lib/plan_snapshot.hpp"
#include "modules/planner/lib/result.hpp"

namespace robuter::plan {

// Why: the thesis wrote a picture of the map and the path for every plan; the tool and the
// firmware's picture writer both draw them here. Obstacles black, expanded obstacles grey
// (orange where the rectangle fits at some headings), unknown light grey, the path red (the
// followed prefix darker and thicker), the rectangle's outline blue at turns and every 0.5 m,
// the start green, the goal magenta. No text is drawn: fonts would bring fontconfig's caches,
// which leak-checking builds report (the plan's number is in the file name). Blocking file I/O:
// never call it from the periodic path.
Status write_plan_picture(const PlanSnapshot& snapshot, const std::string& path);

}  // namespace robuter::plan
