// SPDX-License-Identifier: GPL-3.0-or-later
// The "robuter-places 1" file: a good one read, every broken one refused with its line.
#include <gtest/gtest.h>

#include <string>

#include "modules/places/place_graph_file.hpp"

namespace robuter::places {
namespace {

// Two rooms side by side, a corridor below both, doors into it (line numbers matter below).
const std::string kGood = R"([places]
format = "robuter-places 1"
units = "m"
world = "test.toml"

[[place]]
name = "west"
area = [[0, 2], [4, 2], [4, 6], [0, 6]]
centre = [2, 4]

[[place]]
name = "east"
area = [[4, 6], [4, 2], [8, 2], [8, 6]]
centre = [6, 4]

[[place]]
name = "corridor"
area = [[0, 0], [8, 0], [8, 2], [0, 2]]
centre = [4, 1]

[[door]]
name = "d-west"
between = ["corridor", "west"]
at = [2, 2]
width = 0.9

[[door]]
name = "d-east"
between = ["east", "corridor"]
at = [6, 2.1]
width = 1.0
)";

TEST(PlaceFile, AGoodFileIsRead) {
  auto r = parse_place_graph(kGood, "good.toml");
  ASSERT_TRUE(r.ok()) << r.error().describe();
  const PlaceGraph& g = r.value();
  ASSERT_EQ(g.places().size(), 3u);
  ASSERT_EQ(g.doors().size(), 2u);
  EXPECT_EQ(g.places()[1].name, "east");
  EXPECT_GT(signed_area(g.places()[1].area), 0.0) << "stored counter-clockwise";
  EXPECT_EQ(g.doors()[1].a, 1u);
  EXPECT_EQ(g.doors()[1].b, 2u);
  EXPECT_DOUBLE_EQ(g.doors()[1].width, 1.0);
  EXPECT_EQ(g.place_at({7, 5}), std::optional<std::size_t>(1));
}

TEST(PlaceFile, UnitsScaleEveryLength) {
  std::string mm = kGood;
  mm.replace(mm.find("units = \"m\""), 11, "units = \"cm\"");
  auto r = parse_place_graph(mm, "cm.toml");
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_DOUBLE_EQ(r.value().places()[0].centre.x(), 0.02);
  EXPECT_DOUBLE_EQ(r.value().doors()[0].width, 0.009);
}

struct Broken {
  const char* what;     // the case
  std::string from;     // replaced in kGood
  std::string to;       // by this
  int line;             // expected error line (0: whole file)
  const char* message;  // expected in the message
};

class BrokenPlaceFile : public ::testing::TestWithParam<Broken> {};

TEST_P(BrokenPlaceFile, IsRefusedWithItsLine) {
  const Broken& b = GetParam();
  std::string text = kGood;
  const auto at = text.find(b.from);
  ASSERT_NE(at, std::string::npos) << b.from;
  text.replace(at, b.from.size(), b.to);
  auto r = parse_place_graph(text, "broken.toml");
  ASSERT_FALSE(r.ok()) << b.what;
  EXPECT_EQ(r.error().line, b.line) << r.error().describe();
  EXPECT_NE(r.error().message.find(b.message), std::string::npos) << r.error().describe();
  EXPECT_EQ(r.error().file, "broken.toml");
}

const Broken kBroken[] = {
    {"format", "robuter-places 1", "robuter-places 2", 2, "format: expected"},
    {"no header", "[places]\nformat = \"robuter-places 1\"\nunits = \"m\"\nworld = \"test.toml\"\n", "", 1, "missing [places]"},
    {"units", "units = \"m\"", "units = \"ft\"", 3, "units"},
    {"unknown header key", "world = \"test.toml\"", "wrld = 1", 4, "wrld"},
    {"unknown table", "[[door]]\nname = \"d-west\"", "[[doors]]\nname = \"d-west\"", 21, "unknown table 'doors'"},
    {"[place] for [[place]]", "[[place]]\nname = \"west\"", "[place]\nname = \"west\"", 11, "redefine"},
    {"TOML syntax", "centre = [2, 4]", "centre = [2, 4", 11, ""},
    {"bad name", "name = \"west\"", "name = \"west wing\"", 7, "letters, digits"},
    {"name twice", "name = \"east\"", "name = \"west\"", 12, "used twice"},
    {"two vertices", "area = [[0, 2], [4, 2], [4, 6], [0, 6]]", "area = [[0, 2], [4, 2]]", 6, "at least 3 vertices"},
    {"not simple", "area = [[0, 2], [4, 2], [4, 6], [0, 6]]", "area = [[0, 2], [4, 6], [4, 2], [0, 6]]", 6, "not simple"},
    {"repeated vertex", "area = [[0, 2], [4, 2], [4, 6], [0, 6]]", "area = [[0, 2], [4, 2], [4, 2], [4, 6], [0, 6]]", 6, "repeats"},
    {"centre outside", "centre = [2, 4]", "centre = [5, 4]", 6, "outside the place's area"},
    {"not a point", "centre = [2, 4]", "centre = [2, 4, 0]", 9, "expected a point"},
    {"overlap", "area = [[4, 6], [4, 2], [8, 2], [8, 6]]", "area = [[3, 6], [3, 2], [8, 2], [8, 6]]", 11, "overlaps place 'west'"},
    {"contains", "area = [[0, 0], [8, 0], [8, 2], [0, 2]]\ncentre = [4, 1]", "area = [[-1, -1], [9, -1], [9, 7], [-1, 7]]\ncentre = [4, 1]", 16, "overlaps"},
    {"door to nowhere", "between = [\"corridor\", \"west\"]", "between = [\"corridor\", \"north\"]", 23, "no place named \"north\""},
    {"door to itself", "between = [\"corridor\", \"west\"]", "between = [\"west\", \"west\"]", 23, "two different places"},
    {"between one", "between = [\"corridor\", \"west\"]", "between = [\"corridor\"]", 23, "two place names"},
    {"door off its place", "at = [2, 2]", "at = [2, 3]", 24, "from place 'corridor'"},
    {"no width", "width = 0.9\n", "", 21, "missing key 'width'"},
    {"zero width", "width = 0.9", "width = 0", 25, "0 < width"},
    {"door name twice", "name = \"d-east\"", "name = \"d-west\"", 28, "used twice"},
    {"unknown door key", "width = 1.0", "width = 1.0\nhinge = \"left\"", 32, "hinge"},
};

std::string case_name(const ::testing::TestParamInfo<Broken>& p) {
  std::string n;
  for (const char c : std::string(p.param.what)) n += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Cases, BrokenPlaceFile, ::testing::ValuesIn(kBroken), case_name);

TEST(PlaceFile, NoPlaceAtAllIsRefused) {
  auto r = parse_place_graph("[places]\nformat = \"robuter-places 1\"\n", "empty.toml");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("at least one place"), std::string::npos);
}

TEST(PlaceFile, AMissingFileNamesTheFile) {
  auto r = load_place_graph(::testing::TempDir() + "/no-such-places.toml");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().describe().find("no-such-places.toml"), std::string::npos);
}

}  // namespace
}  // namespace robuter::places
