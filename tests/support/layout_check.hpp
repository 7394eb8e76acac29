// SPDX-License-Identifier: GPL-3.0-or-later
// Checks shared by the picture tests: what every picture must lay out, nothing overlapping, all on the page.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "picture/layout.hpp"

namespace robuter::test {

// A title, a legend, a scale bar in metres, axis ticks with both axis names; no two boxes overlap,
// every box on the page; the page at least 1000 px wide.
inline void expect_explained(const picture::Layout& l) {
  using picture::Kind;
  EXPECT_GE(l.width, 1000);
  EXPECT_EQ(l.of(Kind::title).size(), 1u);
  EXPECT_FALSE(l.of(Kind::legend).empty());
  ASSERT_EQ(l.of(Kind::scale_bar).size(), 1u);
  EXPECT_NE(l.of(Kind::scale_bar)[0]->text.find(" m"), std::string::npos);
  EXPECT_NE(l.find(Kind::axis, "x (m)"), nullptr);
  EXPECT_NE(l.find(Kind::axis, "y (m)"), nullptr);
  EXPECT_GE(l.of(Kind::axis).size(), 6u);  // the two names and at least two ticks per axis
  if (const auto o = l.first_overlap()) {
    ADD_FAILURE() << to_string(l.items[o->first].kind) << " '" << l.items[o->first].text << "' overlaps "
                  << to_string(l.items[o->second].kind) << " '" << l.items[o->second].text << "'";
  }
  for (const auto& i : l.items)
    EXPECT_TRUE(i.box.inside(l.page())) << to_string(i.kind) << " '" << i.text << "' leaves the page";
}

}  // namespace robuter::test
