// SPDX-License-Identifier: GPL-3.0-or-later
// Blackboard topics: generation counters, updated()/copy(), and the owner's writable handle.
#include <gtest/gtest.h>

#include <type_traits>

#include "kernel/blackboard.hpp"

namespace robuter {
namespace {

struct Range {
  int mm = 0;  // a range, mm
};

class Owner {
 public:
  explicit Owner(Topic<Range, Owner>& t) : w_(t.writer()) {}
  void put(int mm) { w_.publish(Range{mm}); }
  void bump() { w_.modify([](Range& r) { r.mm += 1; }); }

 private:
  Writer<Range> w_;
};

TEST(Blackboard, ReadersSeeNewDataByGeneration) {
  Topic<Range, Owner> topic;
  Owner owner(topic);
  Reader<Range> r1 = topic.reader(), r2 = topic.reader();
  EXPECT_FALSE(r1.updated());
  EXPECT_EQ(r1.generation(), 0u);
  owner.put(120);
  EXPECT_TRUE(r1.updated());
  EXPECT_TRUE(r2.updated());
  EXPECT_EQ(r1.copy().mm, 120);
  EXPECT_FALSE(r1.updated());
  EXPECT_TRUE(r2.updated());  // each reader keeps its own place
  owner.bump();
  EXPECT_TRUE(r1.updated());
  EXPECT_EQ(r1.peek().mm, 121);
  EXPECT_TRUE(r1.updated());  // peek does not mark seen
  EXPECT_EQ(r1.generation(), 2u);
  EXPECT_EQ(r2.copy().mm, 121);
}

TEST(Blackboard, HandlesAreSmallAndTopicsCannotBeCopied) {
  EXPECT_FALSE((std::is_copy_constructible_v<Topic<Range, Owner>>));
  EXPECT_FALSE((std::is_constructible_v<Writer<Range>, TopicData<Range>&>));  // no public way in
  EXPECT_LE(sizeof(Reader<Range>), 16u);
}

}  // namespace
}  // namespace robuter
