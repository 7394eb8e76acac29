// SPDX-License-Identifier: GPL-3.0-or-later
// The place graph's X extensions: XN (the robot's place) and XI <n> (one place), on a fake port.
#include <gtest/gtest.h>

#include <string>

#include "tests/protocol/codec_harness.hpp"

namespace robuter::protocol::testing {
namespace {

TEST(PlaceMessages, WithoutAPlaceGraphBothAreUnavailable) {
  Harness h;
  h.codec.session().verbose_errors = true;
  EXPECT_EQ(h.ask("XN"), "error 12 unavailable");
  EXPECT_EQ(h.ask("XI 1"), "error 12 unavailable");
  EXPECT_EQ(h.ask("XQ 1"), "error 12 unavailable");
}

// Why: XQ's decoding and the port's refusals, each changing nothing.
TEST(PlaceMessages, XQAcksOrSaysWhyNot) {
  Harness h;
  h.port.place_count = 32;
  h.codec.session().verbose_errors = true;
  EXPECT_EQ(h.ask("XQ 16"), "ack");
  EXPECT_EQ(h.port.last_place_goal, 16);
  EXPECT_FALSE(h.port.last_place_explore);
  EXPECT_EQ(h.ask("XQ 17 1"), "ack") << "exploring";
  EXPECT_EQ(h.port.last_place_goal, 17);
  EXPECT_TRUE(h.port.last_place_explore);
  EXPECT_EQ(h.ask("XQ 16 0"), "ack") << "not exploring, said so";
  EXPECT_FALSE(h.port.last_place_explore);
  EXPECT_EQ(h.ask("XQ 33"), "error 4 out-of-range") << "past the last place: the port";
  EXPECT_EQ(h.ask("XQ 0"), "error 4 out-of-range") << "numbers start at 1: the decoder";
  EXPECT_EQ(h.ask("XQ"), "error 2 bad-parameter-count");
  EXPECT_EQ(h.ask("XQ 1 2"), "error 4 out-of-range") << "the exploration flag is 0 or 1";
  EXPECT_EQ(h.ask("XQ 1 1 1"), "error 2 bad-parameter-count");
  EXPECT_EQ(h.ask("XQ 1 x"), "error 3 not-a-number");
  EXPECT_EQ(h.port.last_place_goal, 16);
  EXPECT_EQ(h.ask("XQ room-16"), "error 3 not-a-number");
  h.port.place_goal_result = PortResult::refused_emergency;
  EXPECT_EQ(h.ask("XQ 5"), "error 7 refused-emergency") << "latched: as XG";
  EXPECT_EQ(h.port.last_place_goal, 16) << "nothing changed by the refusals";
  EXPECT_FALSE(h.port.last_place_explore);
}

TEST(PlaceMessages, XNNamesThePlaceOrADash) {
  Harness h;
  h.port.place_count = 32;
  h.port.here.number = 3;
  h.port.here.name = "corridor-ew-1";
  EXPECT_EQ(h.ask("XN"), "N 32 3 corridor-ew-1");
  h.port.here = PlaceReport{};
  EXPECT_EQ(h.ask("XN"), "N 32 0 -") << "outside every place";
  h.codec.session().verbose_errors = true;
  EXPECT_EQ(h.ask("XN 1"), "error 2 bad-parameter-count");
}

TEST(PlaceMessages, XIGivesNameCentreAndNeighbours) {
  Harness h;
  h.port.place_count = 32;
  h.port.info.name = "room-16";
  h.port.info.centre_x = 541000;
  h.port.info.centre_y = -306500;
  h.port.info.neighbours = 2;
  h.port.info.neighbour = {5, 31};
  EXPECT_EQ(h.ask("XI 16"), "I 16 room-16 541000 -306500 2 5 31");
  h.port.info.neighbours = 20;  // more than are listed
  for (std::size_t k = 0; k < PlaceReport::kMaxNeighbours; ++k) h.port.info.neighbour[k] = static_cast<std::int32_t>(k + 1);
  EXPECT_EQ(h.ask("XI 16"), "I 16 room-16 541000 -306500 20 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16");
  h.codec.session().verbose_errors = true;
  EXPECT_EQ(h.ask("XI 33"), "error 4 out-of-range") << "past the last place: the port";
  EXPECT_EQ(h.ask("XI 0"), "error 4 out-of-range") << "numbers start at 1: the decoder";
  EXPECT_EQ(h.ask("XI"), "error 2 bad-parameter-count");
  EXPECT_EQ(h.ask("XI x"), "error 3 not-a-number");
}

}  // namespace
}  // namespace robuter::protocol::testing
