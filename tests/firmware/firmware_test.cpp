// SPDX-License-Identifier: GPL-3.0-or-later
// The whole firmware on the simulated robot: AX, motion on the simulated robot.
#include <gtest/gtest.h>

#include <cmath>

#include "modules/firmware/sim_firmware.hpp"

namespace robuter {
namespace {

TEST(Firmware, AnsweringAndMovingOnTheSimulatedRobot) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_EQ(fw.ask("UN"), "N 3");
  EXPECT_EQ(fw.ask("ASN"), "ack");
  EXPECT_EQ(fw.ask("AM 20 20"), "ack");
  fw.run_ticks(300);
  const auto bo = fw.ask("BO");
  ASSERT_TRUE(bo);
  int x = 0, y = 0, theta = 0, servo = 0, clock = 0;
  ASSERT_EQ(std::sscanf(bo->c_str(), "S %d %d %d %d %d", &x, &y, &theta, &servo, &clock), 5) << *bo;
  EXPECT_GT(x, 3000);  // at 20 cm/s for about 2.5 s (after the first ring scan): well over 30 cm
  EXPECT_EQ(servo, 1);
  EXPECT_EQ(fw.ask("AM 0 0"), "ack");
}

// What an operator does after `make run`: ASN, AM 10 10, and watch BO and BU change.
TEST(Firmware, BoAndBuChangeAsTheRobotMoves) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(100);  // a first full ring scan
  const auto bo0 = fw.ask("BO"), bu0 = fw.ask("BU");
  EXPECT_EQ(fw.ask("ASN"), "ack");
  EXPECT_EQ(fw.ask("AM 10 10"), "ack");
  std::string last_bo = *bo0, last_bu = *bu0;
  int bo_changes = 0, bu_changes = 0;
  for (int i = 0; i < 10; ++i) {
    fw.run_ticks(50);
    const auto bo = fw.ask("BO"), bu = fw.ask("BU");
    ASSERT_TRUE(bo && bu);
    // Compare without the trailing clock field, which changes anyway.
    auto body = [](const std::string& r) { return r.substr(0, r.rfind(' ')); };
    bo_changes += body(*bo) != body(last_bo);
    bu_changes += body(*bu) != body(last_bu);
    last_bo = *bo;
    last_bu = *bu;
  }
  EXPECT_GE(bo_changes, 9);
  EXPECT_GE(bu_changes, 8);
}

// The link checks AM against the configured top speed (robot.max_speed_cm_s), handed to it by
// the composition (LinkSettings): not the default's 100 cm/s.
TEST(Firmware, TheLinkRefusesAmAboveTheConfiguredTopSpeed) {
  Config cfg;
  cfg.robot.max_speed_cm_s = 50;
  test::SimFirmware fw("", cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_EQ(fw.ask("ASN"), "ack");
  const std::string fast = fw.ask("AM 60 60").value_or("(no reply)");
  EXPECT_EQ(fast.rfind("error", 0), 0u) << "AM 60 60 answered " << fast;
  EXPECT_EQ(fw.ask("AM 50 -50"), "ack");
  EXPECT_EQ(fw.ask("AM 0 0"), "ack");
}

TEST(Firmware, AxStopsTheMotorsAndEndsTheLoop) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_EQ(fw.ask("ASN"), "ack");
  EXPECT_EQ(fw.ask("AM 15 15"), "ack");
  fw.run_ticks(200);
  std::int32_t l = 0, r = 0;
  fw.sim().drive().commanded(l, r);
  EXPECT_EQ(l, 15);
  EXPECT_EQ(fw.ask("AX"), "ack");
  fw.run_ticks(2);
  EXPECT_TRUE(fw.kernel().stop_requested());
  fw.kernel().shutdown();
  fw.sim().drive().commanded(l, r);
  EXPECT_EQ(l, 0);
  EXPECT_EQ(r, 0);
  EXPECT_FALSE(fw.sim().drive().servo());
}

}  // namespace
}  // namespace robuter
