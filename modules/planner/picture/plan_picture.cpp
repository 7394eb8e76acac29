// SPDX-License-Identifier: GPL-3.0-or-later
// A plan's picture: its page in the world frame, its title and outcome, and the PNG or PDF file.
#include "modules/planner/picture/plan_picture.hpp"

#include <cmath>
#include <cstdio>

#include "modules/planner/picture/plan_drawing.hpp"
#include "picture/file.hpp"
#include "picture/page.hpp"

namespace robuter::plan {

std::string plan_outcome(const PlanSnapshot& s) {
  char t[200];
  const char* body = s.footprint == FootprintKind::Rectangle ? "rectangle" : "disc";
  switch (s.status) {
    case PlanStatus::Found:
      std::snprintf(t, sizeof t, "path found, %.2f m (%s footprint)", s.length, body);
      return t;
    case PlanStatus::Unreachable:
      std::snprintf(t, sizeof t, "no path: unreachable - no way for the %s footprint from start to goal on this map", body);
      return t;
    case PlanStatus::StartOutside: return "no path: start outside the map";
    case PlanStatus::GoalOutside: return "no path: goal outside the map";
    case PlanStatus::StartBlocked:
      std::snprintf(t, sizeof t, "no path: start blocked - the start lies in an obstacle grown by the %s footprint", body);
      return t;
    case PlanStatus::GoalBlocked:
      std::snprintf(t, sizeof t, "no path: goal blocked - the goal lies in an obstacle grown by the %s footprint", body);
      return t;
    case PlanStatus::SearchLimit:
      return "no path: search memory exhausted - the search needed more states than its budget holds";
  }
  return "no path";
}

// Why the corners: a turned map's bounding box in the world holds all four.
picture::Frame plan_frame(const PlanSnapshot& s, const PlanPictureOptions& o) {
  const MapPlacement place(s, o);
  const double w = s.geometry.width * s.geometry.resolution, h = s.geometry.height * s.geometry.resolution;
  const Point2 o0 = s.geometry.origin;
  picture::Vec2 lo = place.world({o0.x, o0.y}), hi = lo;
  for (const Point2 p : {Point2{o0.x + w, o0.y}, Point2{o0.x, o0.y + h}, Point2{o0.x + w, o0.y + h}, s.goal,
                         Point2{s.start.x, s.start.y}}) {
    lo = lo.cwiseMin(place.world(p));
    hi = hi.cwiseMax(place.world(p));
  }
  const picture::Vec2 margin = picture::Vec2::Constant(0.2);
  return picture::make_frame(lo - margin, hi + margin, o.page);
}

picture::Layout draw_plan_picture(cairo_t* cr, const PlanSnapshot& s, const picture::Frame& f,
                                  const PlanPictureOptions& o) {
  picture::Layout layout = f.layout();
  picture::Legend legend;
  std::vector<picture::Label> labels;
  draw_plan(cr, s, f, MapPlacement(s, o), legend, labels);
  char when[96];
  if (s.tick > 0) std::snprintf(when, sizeof when, "tick %llu, %s", static_cast<unsigned long long>(s.tick), picture::utc_now().c_str());
  else std::snprintf(when, sizeof when, "%s", picture::utc_now().c_str());
  const std::string frame = o.world_frame ? "world frame" : "odometry frame";
  picture::draw_words(cr, f, o.what + " (" + frame + ", " + when + "): " + plan_outcome(s), legend, labels, layout);
  return layout;
}

// Why PNG for any other extension: the firmware's pictures are plan-gGGG-NNN.png, the tool's
// -o has always written PNG.
Result<picture::Layout> write_plan_picture(const PlanSnapshot& snap, const std::string& path,
                                           const PlanPictureOptions& options) {
  const int w = snap.geometry.width, h = snap.geometry.height;
  if (w <= 0 || h <= 0 || snap.cells.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h))
    return Error{path, 0, "empty snapshot: nothing to draw"};
  const picture::Frame f = plan_frame(snap, options);
  const picture::Format format = picture::format_of(path) == picture::Format::none ? picture::Format::png : picture::format_of(path);
  picture::Layout layout;
  const auto why = picture::write_page(path, format, f.width, f.height,
                                       [&](cairo_t* cr) { layout = draw_plan_picture(cr, snap, f, options); });
  if (why) return Error{path, 0, *why};
  return layout;
}

}  // namespace robuter::plan
