// Pictures: the default world with the robot, its trail, sonar beams and pan-tilt rays, to PNG
// and SVG; the files exist, have the expected size and are not blank.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "hal/sim/render.hpp"
#include "hal/sim/robot.hpp"
#include "hal/sim/world_io.hpp"
#include "tests/sim/sim_test_util.hpp"
#include "tests/support/missing_path.hpp"

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
  const Status s = render_png(pic.scene, RenderOptions{}, path);
  ASSERT_TRUE(s.ok()) << s.error().describe();
  EXPECT_EQ(pic.overlay_calls, 1);
  const std::string png = slurp(path);
  ASSERT_GT(png.size(), 20000u);  // a blank picture of this size compresses to ~2 kB
  EXPECT_EQ(png.substr(1, 3), "PNG");
  // Width and height from the IHDR chunk: (8.1 + 0.8) m × 60 px/m, (6.1 + 0.8) m × 60 px/m.
  auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  EXPECT_EQ(be32(16), 534);
  EXPECT_EQ(be32(20), 414);
}

TEST(Render, DefaultWorldToSvg) {
  Picture pic;
  const std::string path = test::out_path("sim_default.svg");
  const Status s = render_svg(pic.scene, RenderOptions{}, path);
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
    if (ext != ".toml" && ext != ".env") continue;
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
    const Status s = render_png(scene, RenderOptions{}, path);
    ASSERT_TRUE(s.ok()) << s.error().describe();
    EXPECT_GT(std::filesystem::file_size(path), 5000u);
  }
}

TEST(Render, UnwritablePathIsAnError) {
  Picture pic;
  const robuter::test::MissingPaths paths;
  const Status s = render_png(pic.scene, RenderOptions{}, paths.under_file("x.png"));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("cannot write"), std::string::npos);
}

}  // namespace
}  // namespace robuter::sim
