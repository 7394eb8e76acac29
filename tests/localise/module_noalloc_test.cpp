// SPDX-License-Identifier: GPL-3.0-or-later
// Proves the localisation module allocates nothing on the periodic path: the whole firmware on the
// building floor, driving, with XW, XA (a pose, a global search) and AC among its lines.
#include <gtest/gtest.h>

#include "modules/firmware/sim_firmware.hpp"
#include "tests/support/alloc_counter.hpp"

namespace robuter {
namespace {

TEST(LocaliseModule, TenThousandTicksOfLocalisationAllocateNothing) {
  Config cfg;
  cfg.places.file = ROBUTER_WORLDS_DIR "/building_floor.places.toml";
  cfg.localise.enabled = true;
  hal::SimOptions sim;
  sim.world_file = ROBUTER_WORLDS_DIR "/building_floor.toml";
  sim.odometry_noise = true;
  test::SimFirmware fw(ROBUTER_WORLDS_DIR "/building_floor.toml", cfg, sim);
  ASSERT_TRUE(fw.ok()) << fw.error();
  for (const char* l : {"AC 30000 200500 0", "ASN", "AM 20 20", "XW", "XA", "XA 30000 200500 0", "XB1"}) ASSERT_TRUE(fw.ask(l)) << l;
  fw.run_ticks(300);
  fw.count_lines();
  const auto steps_before = fw.bb().localisation.reader().peek().steps;
  const std::string_view cycle[] = {"AM 20 20\r", "XW\r", "BO\r", "AM 20 20\r", "XA\r", "XW\r",
                                    "AM 20 20\r", "XA 40000 200500 0\r", "AM 20 20\r", "AC 40000 200500 0\r"};
  int replies = 0;
  test::AllocCounter counter;
  for (int i = 0; i < 10'000; ++i) {
    if (i % 50 == 0) fw.send_raw(cycle[(i / 50) % std::size(cycle)]);
    fw.step();
    replies += fw.count_lines().first;
  }
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_EQ(replies, 200);  // every line answered
  const Localisation& l = fw.bb().localisation.reader().peek();
  EXPECT_GT(l.steps, steps_before + 50);  // the filter kept stepping
  EXPECT_GT(fw.sim().robot().pose().x, 15.0);  // it drove the corridor: 12 m and more
  std::printf("localise: %u steps, longest activation %u us CPU\n", l.steps - steps_before, l.run_us_max);
}

}  // namespace
}  // namespace robuter
