// SPDX-License-Identifier: GPL-3.0-or-later
// Blackboard topics: generation counters, updated()/copy(), and the owner's writable handle.
#include <gtest/gtest.h>

#include <cstdint>
#include <type_traits>
#include <utility>

#include "kernel/blackboard.hpp"
#include "tests/support/test_writer.hpp"

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
  std::uint32_t written() const { return w_.generation(); }

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
  EXPECT_EQ(owner.written(), 2u);  // the writer knows its own count: what an owner's echo is compared with
  EXPECT_EQ(r2.copy().mm, 121);
}

TEST(Blackboard, HandlesAreSmallAndTopicsCannotBeCopied) {
  EXPECT_FALSE((std::is_copy_constructible_v<Topic<Range, Owner>>));
  EXPECT_FALSE((std::is_copy_constructible_v<Writer<Range>>));  // held by its owner, never lent as a copy
  EXPECT_FALSE((std::is_copy_assignable_v<Writer<Range>>));
  EXPECT_TRUE((std::is_nothrow_move_constructible_v<Writer<Range>>));
  EXPECT_FALSE((std::is_constructible_v<Writer<Range>, TopicData<Range>&>));  // no public way in
  EXPECT_LE(sizeof(Reader<Range>), 16u);
}

// The writer is yielded once: a second owner object on the same topic gets an empty handle, and
// the topic counts both claims (the firmware's start-up check names it).
TEST(Blackboard, TheWriterIsYieldedOnce) {
  Topic<Range, Owner> topic;
  EXPECT_EQ(topic.claims(), 0);
  Owner first(topic);
  EXPECT_EQ(topic.claims(), 1);
  Owner second(topic);
  EXPECT_EQ(topic.claims(), 2);
  first.put(7);
  EXPECT_EQ(topic.reader().peek().mm, 7);
}

TEST(Blackboard, AMovedWriterLeavesAnEmptyHandle) {
  Topic<Range, Owner> topic;
  Writer<Range> a = test_writer(topic);
  ASSERT_TRUE(a.valid());
  Writer<Range> b = std::move(a);
  EXPECT_FALSE(a.valid());  // NOLINT(bugprone-use-after-move): the moved-from handle is empty by contract
  EXPECT_TRUE(b.valid());
  b.publish(Range{3});
  EXPECT_EQ(topic.reader().peek().mm, 3);
}

// advertised(): the owner runs (it published, or said so without a value); the generation alone
// counts publications.
TEST(Blackboard, AdvertisedSaysTheOwnerRuns) {
  Topic<Range, Owner> topic;
  Reader<Range> r = topic.reader();
  Writer<Range> w = test_writer(topic);
  EXPECT_FALSE(r.advertised());  // claimed at composition, but not running yet
  w.advertise();
  EXPECT_TRUE(r.advertised());
  EXPECT_EQ(r.generation(), 0u);
  EXPECT_FALSE(r.updated());
  Topic<Range, Owner> other;
  Reader<Range> o = other.reader();
  Writer<Range> ow = test_writer(other);
  ow.publish(Range{1});
  EXPECT_TRUE(o.advertised());
}

}  // namespace
}  // namespace robuter
