// SPDX-License-Identifier: GPL-3.0-or-later
// The grid planner's X extensions: XG (goal, optional theta), XH (halt), XP (status), XM (map window).
#include <gtest/gtest.h>

#include <string>

#include "protocol/codec/checksum.hpp"
#include "protocol/codec/handlers.hpp"
#include "tests/protocol/codec_harness.hpp"

namespace robuter::protocol::testing {
namespace {

TEST(PlannerMessages, XGWithAndWithoutTheta) {
  Harness h;
  EXPECT_EQ(h.ask("XG 150000 55000"), "ack");
  EXPECT_EQ(h.port.goals, 1);
  EXPECT_EQ(h.port.last_planner_goal.x, 150000);
  EXPECT_EQ(h.port.last_planner_goal.y, 55000);
  EXPECT_FALSE(h.port.last_goal_theta);
  EXPECT_EQ(h.ask("XG -10,20,-9000"), "ack");
  EXPECT_EQ(h.port.last_planner_goal.theta, -9000);
  EXPECT_TRUE(h.port.last_goal_theta);
  h.port.result = PortResult::out_of_range;  // the port: off the map
  h.codec.session().verbose_errors = true;
  EXPECT_EQ(h.ask("XG 900000 0"), "error 4 out-of-range");
}

TEST(PlannerMessages, XGMalformedNeverReachesThePort) {
  Harness h;
  h.codec.session().verbose_errors = true;
  EXPECT_EQ(h.ask("XG"), "error 2 bad-parameter-count");
  EXPECT_EQ(h.ask("XG 1"), "error 2 bad-parameter-count");
  EXPECT_EQ(h.ask("XG 1 2 3 4"), "error 2 bad-parameter-count");
  EXPECT_EQ(h.ask("XG 1 x"), "error 3 not-a-number");
  EXPECT_EQ(h.ask("XG 1 2 18001"), "error 4 out-of-range");
  EXPECT_EQ(h.ask("XG 1 2 -18000"), "error 4 out-of-range");
  EXPECT_EQ(h.ask("XG 1 99999999999"), "error 4 out-of-range");
  EXPECT_EQ(h.ask("Xg 1 2"), "error 1 unknown-command");
  EXPECT_EQ(h.port.goals, 0);
  EXPECT_EQ(h.port.calls, 0);
}

TEST(PlannerMessages, XHAndUnavailable) {
  Harness h;
  EXPECT_EQ(h.ask("XH"), "ack");
  EXPECT_EQ(h.port.goal_cancels, 1);
  h.codec.session().verbose_errors = true;
  EXPECT_EQ(h.ask("XH 1"), "error 2 bad-parameter-count");
  h.port.has_planner = false;
  EXPECT_EQ(h.ask("XH"), "error 12 unavailable");
  EXPECT_EQ(h.ask("XG 1 2"), "error 12 unavailable");
  EXPECT_EQ(h.ask("XP"), "error 12 unavailable");
  EXPECT_EQ(h.ask("XM"), "error 12 unavailable");
}

TEST(PlannerMessages, XP) {
  Harness h;
  EXPECT_EQ(h.ask("XP"), "P moving 150000 55000 13950 1480 3 4 812 4650 1523");
  h.port.planner = PlannerReport{};
  EXPECT_EQ(h.ask("XP"), "P idle 0 0 0 0 0 0 0 0 1523");
  h.port.planner.state = PlannerState::unreachable;
  EXPECT_EQ(h.ask("XP").substr(0, 14), "P unreachable ");
  EXPECT_EQ(word(PlannerState::cancelled), "cancelled");
  EXPECT_EQ(word(PlannerState::reached), "reached");
}

TEST(PlannerMessages, XMIsOneLineOfRowsTopFirst) {
  Harness h;
  const std::string r = h.ask("XM");
  const std::string head = "M 41 41 50 -12345 67890 ";
  ASSERT_EQ(r.rfind(head, 0), 0u) << r;
  const std::string rows = r.substr(head.size());
  ASSERT_EQ(rows.size(), 41u * 41u + 40u);
  EXPECT_EQ(rows.substr(0, 41), std::string(41, '#'));
  EXPECT_EQ(rows[41], '|');
  EXPECT_EQ(rows[20 * 42 + 20], 'P');
  EXPECT_EQ(rows.find('\r'), std::string::npos);
  EXPECT_LE(r.size() + 1, kReplyCapacity);
  // With checksums on, the line still fits and carries its checksum.
  h.codec.session().checksums = true;
  char hex[kChecksumDigits];
  format_checksum(crc16("XM"), hex);
  const std::string c = h.ask("XM*" + std::string(hex, kChecksumDigits));
  ASSERT_EQ(c.size(), r.size() + 5) << c.substr(0, 40);
  EXPECT_EQ(c.substr(0, r.size()), r);
  EXPECT_EQ(c[r.size()], '*');
}

}  // namespace
}  // namespace robuter::protocol::testing
