// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures of plans: title with the outcome (the reason when there is no path), the goal marked,
// legend, scale bar and axes laid out without overlap, world frame, ≥ 1000 px wide, PNG and PDF.
#include <gtest/gtest.h>

#include <cairo.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "modules/planner/lib/planner.hpp"
#include "modules/planner/lib/thesis_files.hpp"
#include "modules/planner/picture/plan_picture.hpp"
#include "picture/page.hpp"
#include "tests/support/layout_check.hpp"
#include "tests/support/temp_dir.hpp"

namespace robuter::plan {
namespace {

// Empties cairo's and fontconfig's caches after the last test, so LeakSanitizer sees no leak.
class PictureCaches : public ::testing::Environment {
 public:
  void TearDown() override { picture::release_caches(); }
};
const auto* const kPictureCaches = ::testing::AddGlobalTestEnvironment(new PictureCaches);

// A 6 m × 4 m room split at y = 2 m by a wall with a 90 cm door (x from 2.5 to 3.45 m).
OccupancyMap door_map() {
  OccupancyMap m(MapGeometry{120, 80, 0.05, {}});
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 120; ++x) m.mark_free({x, y});
  rasterise_polygons(m, {Polygon{{{0.0, 2.0}, {2.5, 2.0}, {2.5, 2.1}, {0.0, 2.1}}},
                         Polygon{{{3.45, 2.0}, {6.0, 2.0}, {6.0, 2.1}, {3.45, 2.1}}}});
  m.clear_changes();
  return m;
}

// The plan from (1, 0.8) to `goal` with the given footprint, copied for a picture.
PlanSnapshot snapshot(FootprintKind kind, Point2 goal) {
  PlannerConfig cfg;
  cfg.footprint = kind;
  if (kind == FootprintKind::Disc) cfg.radius = circumscribed_radius(RectangleFootprint{});
  Planner planner(cfg);
  planner.set_map(door_map());
  const Pose2 start{1.0, 0.8, 0.0};
  const PlanResult r = planner.plan(start, goal);
  PlanSnapshot s;
  s.reserve(planner, 4096);
  EXPECT_TRUE(s.capture(planner, r, start, goal));
  for (std::size_t i = 1; i < s.path_len; ++i)
    s.length += std::hypot(s.path[i].pose.x - s.path[i - 1].pose.x, s.path[i].pose.y - s.path[i - 1].pose.y);
  return s;
}

// Draws on a memory surface; what was laid out.
picture::Layout lay_out(const PlanSnapshot& s, const PlanPictureOptions& o = {}) {
  const picture::Frame f = plan_frame(s, o);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, f.width, f.height);
  cairo_t* cr = cairo_create(surface);
  picture::Layout l = draw_plan_picture(cr, s, f, o);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  return l;
}

TEST(PlanPicture, PathFoundIsExplained) {
  const PlanSnapshot s = snapshot(FootprintKind::Rectangle, {5.0, 3.2});
  ASSERT_EQ(s.status, PlanStatus::Found);
  const picture::Layout l = lay_out(s);
  robuter::test::expect_explained(l);
  EXPECT_NE(l.find(picture::Kind::title, "path found"), nullptr);
  EXPECT_NE(l.find(picture::Kind::title, "world frame"), nullptr);
  for (const char* words : {"obstacle", "grown obstacle", "planned path", "footprint", "start", "goal"})
    EXPECT_NE(l.find(picture::Kind::legend, words), nullptr) << words;
  EXPECT_NE(l.find(picture::Kind::label, "goal"), nullptr);
  EXPECT_NE(l.find(picture::Kind::label, "start"), nullptr);
}

// The disc cannot pass the 90 cm door: the title says there is no path and why; the goal is marked.
TEST(PlanPicture, UnreachableGoalHasTheReasonInTheTitleAndIsMarked) {
  PlanSnapshot s = snapshot(FootprintKind::Disc, {5.0, 3.2});
  ASSERT_EQ(s.status, PlanStatus::Unreachable);
  s.goal_seq = 2;  // an XG goal of the firmware
  const picture::Layout l = lay_out(s);
  robuter::test::expect_explained(l);
  const picture::Item* title = l.find(picture::Kind::title, "no path: unreachable");
  ASSERT_NE(title, nullptr);
  EXPECT_NE(title->text.find("disc footprint"), std::string::npos) << title->text;
  EXPECT_NE(l.find(picture::Kind::label, "XG goal"), nullptr);
  EXPECT_NE(l.find(picture::Kind::legend, "goal"), nullptr);
  EXPECT_EQ(l.find(picture::Kind::legend, "planned path"), nullptr);  // nothing drawn, nothing listed
}

TEST(PlanPicture, EveryReasonIsWorded) {
  PlanSnapshot s;
  s.status = PlanStatus::GoalBlocked;
  EXPECT_NE(plan_outcome(s).find("goal blocked"), std::string::npos);
  s.status = PlanStatus::StartOutside;
  EXPECT_NE(plan_outcome(s).find("start outside the map"), std::string::npos);
}

// The firmware's map is in the odometry frame; placed by the start pose, the picture's world
// area follows the turn and shift (a 6 × 4 m map turned by 90° is 4 m wide, 6 m high).
TEST(PlanPicture, OdometryMapIsDrawnInTheWorldFrame) {
  const PlanSnapshot s = snapshot(FootprintKind::Rectangle, {5.0, 3.2});
  PlanPictureOptions o;
  o.map_in_world = {10.0, 20.0, kPi / 2};
  const picture::Frame f = plan_frame(s, o);
  EXPECT_NEAR(f.hi.x() - f.lo.x(), 4.0 + 0.4, 0.05);
  EXPECT_NEAR(f.hi.y() - f.lo.y(), 6.0 + 0.4, 0.05);
  EXPECT_NEAR(f.lo.x(), 10.0 - 4.0 - 0.2, 0.05);
  EXPECT_NEAR(f.lo.y(), 20.0 - 0.2, 0.05);
  robuter::test::expect_explained(lay_out(s, o));
}

// The files: a PNG at least 1000 px wide, and a PDF whose words pdftotext reads back.
TEST(PlanPicture, WritesPngAndPdf) {
  const PlanSnapshot s = snapshot(FootprintKind::Disc, {5.0, 3.2});
  const robuter::test::TempDir dir;
  ASSERT_TRUE(dir.ok());
  const auto png = write_plan_picture(s, dir.file("plan.png"));
  ASSERT_TRUE(png.ok()) << png.error().message;
  cairo_surface_t* img = cairo_image_surface_create_from_png(dir.file("plan.png").c_str());
  EXPECT_GE(cairo_image_surface_get_width(img), 1000);
  cairo_surface_destroy(img);
  const auto pdf = write_plan_picture(s, dir.file("plan.pdf"));
  ASSERT_TRUE(pdf.ok()) << pdf.error().message;
  if (std::system("command -v pdftotext >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "pdftotext is missing: install poppler-utils (make deps) to read the PDF's words";
  ASSERT_EQ(std::system(("pdftotext '" + dir.file("plan.pdf") + "' '" + dir.file("plan.txt") + "'").c_str()), 0);
  std::ifstream in(dir.file("plan.txt"));
  const std::string words{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(words.find("no path: unreachable"), std::string::npos) << words;
}

}  // namespace
}  // namespace robuter::plan
