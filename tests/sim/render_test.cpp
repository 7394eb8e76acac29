// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures: the default world with the robot, its trail, sonar beams and pan-tilt rays, to PNG,
// SVG and PDF; the files exist, are ≥ 1000 px wide and not blank; what they lay out (title,
// legend, scale bar, axes, labels) is there, on the page and never overlapping.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "hal/sim/render.hpp"
#include "hal/sim/robot.hpp"
#include "hal/sim/world_io.hpp"
#include "tests/sim/sim_test_util.hpp"
#include "tests/support/layout_check.hpp"
#include "tests/support/missing_path.hpp"
#include "tests/support/temp_dir.hpp"

namespace robuter::sim {
namespace {

// A whole file as bytes.
std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The default world after a short drive, with every sensor's reading; `overlay_calls` counts
// the overlay hook's invocations.
struct Picture {
  World world;
  std::optional<Robot> robot;
  Scene scene;
  int overlay_calls = 0;

  // Loads the world, drives 4 s on a curve, reads every sensor, fills the scene.
  Picture() {
    auto w = load_world(test::world_path("default.toml"));
    EXPECT_TRUE(w.ok());
    world = std::move(w).value();
    robot.emplace(world, RobotParams{}, *world.start);
    robot->command({0.35, 0.25});
    for (int i = 0; i < 400; ++i) robot->step(0.01);
    SonarModel ring(world, default_ring_params());
    const RingLayout layout = default_ring_layout();
    std::array<double, kRingSensors> ranges{};
    for (int i = 0; i < kRingSensors; ++i) ranges[i] = ring.measure(robot->pose(), layout[i]);
    SonarModel ptu(world, default_pan_tilt_params());
    const PanTiltMount mount;
    const double pan = deg_to_rad(60.0);
    const PanTiltReading reading = measure_pan_tilt(ptu, robot->pose(), mount, pan);
    scene.world = &world;
    scene.robot = robot->pose();
    scene.trail = &robot->trail();
    scene.beams = ring_beams(robot->pose(), layout, ranges, default_ring_params());
    scene.pan_tilt = pan_tilt_beams(robot->pose(), mount, pan, reading, default_pan_tilt_params());
    scene.title = "default world";
    scene.overlay = [this](cairo_t*, const View&) { ++overlay_calls; };
  }
};

// Empties cairo's and fontconfig's caches after the last test, so LeakSanitizer sees no leak.
class RenderCaches : public ::testing::Environment {
 public:
  void TearDown() override { release_render_caches(); }
};
const auto* const kRenderCaches = ::testing::AddGlobalTestEnvironment(new RenderCaches);

TEST(Render, DefaultWorldToPng) {
  Picture pic;
  const std::string path = test::out_path("sim_default.png");
  const auto s = render_png(pic.scene, RenderOptions{}, path);
  ASSERT_TRUE(s.ok()) << s.error().describe();
  EXPECT_EQ(pic.overlay_calls, 1);
  const std::string png = slurp(path);
  ASSERT_GT(png.size(), 20000u);  // a blank picture of this size compresses to ~2 kB
  EXPECT_EQ(png.substr(1, 3), "PNG");
  // Width and height from the IHDR chunk: 1000 px wide by default; (8.1 + 0.8) m across the plot
  // at the scale that fills it, (6.1 + 0.8) m high, plus title and scale bar.
  auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  EXPECT_EQ(be32(16), 1000);
  EXPECT_EQ(be32(20), s.value().height);
  EXPECT_GT(be32(20), 6.9 * 60);
}

TEST(Render, DefaultWorldToSvg) {
  Picture pic;
  const std::string path = test::out_path("sim_default.svg");
  const auto s = render_svg(pic.scene, RenderOptions{}, path);
  ASSERT_TRUE(s.ok()) << s.error().describe();
  const std::string svg = slurp(path);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_GT(svg.size(), 10000u);
}

// Every shipped world with the robot at its start and its ring readings, one PNG each (handy
// pictures of the worlds, in the build tree).
TEST(Render, EveryShippedWorld) {
  for (const auto& e : std::filesystem::directory_iterator(ROBUTER_WORLDS_DIR)) {
    const auto ext = e.path().extension();
    if (!is_world_file(e.path())) continue;
    SCOPED_TRACE(e.path().string());
    auto w = load_world(e.path());
    ASSERT_TRUE(w.ok());
    const World& world = w.value();
    Scene scene;
    scene.world = &world;
    scene.title = e.path().filename().string();
    if (world.start) {
      scene.robot = *world.start;
      SonarModel ring(world, default_ring_params());
      const RingLayout layout = default_ring_layout();
      std::array<double, kRingSensors> ranges{};
      for (int i = 0; i < kRingSensors; ++i) ranges[i] = ring.measure(*world.start, layout[i]);
      scene.beams = ring_beams(*world.start, layout, ranges, default_ring_params());
    }
    const std::string path =
        test::out_path("world_" + e.path().stem().string() + "_" + ext.string().substr(1) + ".png");
    const auto s = render_png(scene, RenderOptions{}, path);
    ASSERT_TRUE(s.ok()) << s.error().describe();
    EXPECT_GT(std::filesystem::file_size(path), 5000u);
    robuter::test::expect_explained(s.value());
  }
}

TEST(Render, UnwritablePathIsAnError) {
  Picture pic;
  const robuter::test::MissingPaths paths;
  const auto s = render_png(pic.scene, RenderOptions{}, paths.under_file("x.png"));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("cannot write"), std::string::npos);
}

// Draws on a memory surface the size make_view picks; what was laid out.
picture::Layout lay_out(const Scene& scene, const RenderOptions& options = {}) {
  const View v = make_view(scene, options);
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, v.width, v.height);
  cairo_t* cr = cairo_create(s);
  picture::Layout l = render(cr, scene, v, options);
  cairo_destroy(cr);
  cairo_surface_destroy(s);
  return l;
}

// The legend's words, one line each (for failure messages).
std::string legend_words(const picture::Layout& l) {
  std::string out;
  for (const auto* i : l.of(picture::Kind::legend)) out += i->text + "\n";
  return out;
}

TEST(Render, LaysOutTitleLegendScaleBarAxesAndLabels) {
  Picture pic;
  const picture::Layout l = lay_out(pic.scene);
  robuter::test::expect_explained(l);
  ASSERT_NE(l.find(picture::Kind::title, "default world"), nullptr);
  // One legend entry per ink drawn: the world, the robot, its trail, both kinds of sonar.
  for (const char* words : {"grid", "obstacle", "door", "start pose", "goal", "robot at its true pose", "robot edge",
                            "trail", "ring sonar: cone to its echo", "pan-tilt sonar"})
    EXPECT_NE(l.find(picture::Kind::legend, words), nullptr) << words << " missing from\n" << legend_words(l);
  // Sensor numbers and names, placed where they collide with nothing.
  EXPECT_NE(l.find(picture::Kind::label, "door"), nullptr);
  EXPECT_GE(l.of(picture::Kind::label).size(), 10u);
}

// Why: a legend lists what was drawn, no more — an empty world has no robot or sonar entries,
// and what a hook draws appears through Scene::keys.
TEST(Render, LegendListsOnlyWhatWasDrawn) {
  const World world = test::make_world({test::rect(0, 0, 2, 1)});
  Scene scene;
  scene.world = &world;
  scene.title = "one box";
  scene.keys.push_back({{0.1, 0.2, 0.9}, picture::Swatch::line, "hook's line"});
  const picture::Layout l = lay_out(scene);
  robuter::test::expect_explained(l);
  EXPECT_EQ(l.of(picture::Kind::legend).size(), 4u) << legend_words(l);  // grid, obstacle, its edge, the hook's line
  EXPECT_NE(l.find(picture::Kind::legend, "hook's line"), nullptr);
  EXPECT_EQ(l.find(picture::Kind::legend, "robot"), nullptr);
  EXPECT_EQ(l.find(picture::Kind::legend, "sonar"), nullptr);
}

// At a small scale the 24 sensor numbers crowd together: colliding ones are moved or left out,
// never drawn on top of each other; the page stays 1000 px wide.
TEST(Render, CrowdedLabelsAreNudgedOrDropped) {
  Picture pic;
  RenderOptions small;
  small.pixels_per_metre = 20.0;
  const picture::Layout l = lay_out(pic.scene, small);
  robuter::test::expect_explained(l);
  const auto labels = l.of(picture::Kind::label);
  EXPECT_GE(labels.size(), 4u);
  EXPECT_LT(labels.size(), 24u + 3u);  // some numbers had no room
}

// End to end: the PDF's words, as a reader extracts them (pdftotext, Debian's poppler-utils),
// hold the title, the legend, the scale bar and the axis names.
TEST(Render, PdfWordsReadByPdftotext) {
  if (std::system("command -v pdftotext >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "pdftotext is missing: install poppler-utils (make deps) to read the PDF's words";
  Picture pic;
  pic.scene.title = "default world picture check";
  const robuter::test::TempDir dir;
  ASSERT_TRUE(dir.ok());
  const std::string pdf = dir.file("sim.pdf"), txt = dir.file("sim.txt");
  const auto s = render_file(pic.scene, RenderOptions{}, pdf);
  ASSERT_TRUE(s.ok()) << s.error().describe();
  ASSERT_EQ(std::system(("pdftotext -layout '" + pdf + "' '" + txt + "'").c_str()), 0);
  const std::string words = slurp(txt);
  for (const char* w : {"default world picture check", "obstacle", "trail", "ring sonar", "x (m)", "y (m)"})
    EXPECT_NE(words.find(w), std::string::npos) << w << " not in the PDF's text:\n" << words;
  // The scale bar's "2 m" (pdftotext may close up the short gap before the unit).
  const auto squeeze = [](std::string t) { return std::erase(t, ' '), t; };
  EXPECT_NE(squeeze(words).find(squeeze(s.value().of(picture::Kind::scale_bar)[0]->text)), std::string::npos) << words;
}

TEST(Render, OnlyPngSvgAndPdfAreWritten) {
  Picture pic;
  const robuter::test::TempDir dir;
  EXPECT_TRUE(picture_format_ok("a.PNG"));
  EXPECT_TRUE(picture_format_ok("a.pdf"));
  EXPECT_FALSE(picture_format_ok("a.jpg"));
  const auto s = render_file(pic.scene, RenderOptions{}, dir.file("x.jpg"));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find(".pdf"), std::string::npos);
}

}  // namespace
}  // namespace robuter::sim
