// SPDX-License-Identifier: GPL-3.0-or-later
// The polygon predicates and localisation in a place (seed 003's inside_polygon / placenode).
#include <gtest/gtest.h>

#include "modules/places/place_graph.hpp"

namespace robuter::places {
namespace {

const std::vector<Vec2> kSquare = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
// An L: the notch (2..4, 2..4) is outside.
const std::vector<Vec2> kEll = {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};

TEST(InsidePolygon, ConvexAndConcave) {
  EXPECT_TRUE(inside_polygon(kSquare, {2, 2}));
  EXPECT_FALSE(inside_polygon(kSquare, {5, 2}));
  EXPECT_FALSE(inside_polygon(kSquare, {-0.01, 2}));
  EXPECT_TRUE(inside_polygon(kEll, {1, 3}));
  EXPECT_TRUE(inside_polygon(kEll, {3, 1}));
  EXPECT_FALSE(inside_polygon(kEll, {3, 3})) << "the notch";
}

TEST(InsidePolygon, APointOnAnEdgeOrVertexIsInside) {
  EXPECT_TRUE(inside_polygon(kSquare, {4, 2}));
  EXPECT_TRUE(inside_polygon(kSquare, {0, 0}));
  EXPECT_TRUE(inside_polygon(kEll, {3, 2}));
  EXPECT_TRUE(inside_polygon(kSquare, {4.0005, 2})) << "within 1 mm";
  EXPECT_FALSE(inside_polygon(kSquare, {4.01, 2}));
}

TEST(InsidePolygon, DegeneratePolygonsHoldNothing) {
  EXPECT_FALSE(inside_polygon({}, {0, 0}));
  EXPECT_FALSE(inside_polygon({{0, 0}, {1, 1}}, {0.5, 0.5}));
}

TEST(Polygon, AreaSignAndCrossings) {
  EXPECT_DOUBLE_EQ(signed_area(kSquare), 16.0);
  std::vector<Vec2> cw(kSquare.rbegin(), kSquare.rend());
  EXPECT_DOUBLE_EQ(signed_area(cw), -16.0);
  EXPECT_DOUBLE_EQ(signed_area(kEll), 12.0);
  EXPECT_TRUE(segments_cross({0, 0}, {2, 2}, {0, 2}, {2, 0}));
  EXPECT_FALSE(segments_cross({0, 0}, {2, 0}, {2, 0}, {2, 2})) << "a shared end point";
  EXPECT_FALSE(segments_cross({0, 0}, {2, 0}, {1, 0}, {3, 0})) << "along one line";
  EXPECT_FALSE(segments_cross({0, 0}, {1, 0}, {2, -1}, {2, 1}));
  EXPECT_DOUBLE_EQ(distance_to_boundary(kSquare, {2, 1}), 1.0);
}

TEST(PlaceGraph, PlaceAtFindsThePlaceAndTheFirstOnASharedEdge) {
  PlaceGraph g({Place{"west", kSquare, {2, 2}},
                Place{"east", {{4, 0}, {8, 0}, {8, 4}, {4, 4}}, {6, 2}}},
               {Door{"d", 0, 1, {4, 2}, 0.9}});
  EXPECT_EQ(g.place_at({1, 1}), std::optional<std::size_t>(0));
  EXPECT_EQ(g.place_at({7, 3}), std::optional<std::size_t>(1));
  EXPECT_EQ(g.place_at({4, 1}), std::optional<std::size_t>(0)) << "shared edge: file order";
  EXPECT_EQ(g.place_at({9, 1}), std::nullopt);
  EXPECT_EQ(g.find("east"), std::optional<std::size_t>(1));
  EXPECT_EQ(g.find("north"), std::nullopt);
  ASSERT_EQ(g.doors_of(0).size(), 1u);
  EXPECT_EQ(g.doors_of(1)[0], 0u);
}

TEST(PlaceGraph, NameRule) {
  EXPECT_TRUE(valid_name("room-01_b"));
  EXPECT_FALSE(valid_name(""));
  EXPECT_FALSE(valid_name("sixteen-chars-xx"));
  EXPECT_FALSE(valid_name("with space"));
  EXPECT_FALSE(valid_name("é"));
}

}  // namespace
}  // namespace robuter::places
