// SPDX-License-Identifier: GPL-3.0-or-later
// The one vocabulary: every enumerator has its own non-empty word, the words read back, and the wire words stay put.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "protocol/codec/vocabulary.hpp"

namespace robuter::protocol::testing {
namespace {

// Checked when compiled, too.
static_assert(word(EmergencyCause::bus_passive) == "bus-error-passive");
static_assert(from_word<ModeReason>("operator") == ModeReason::operator_motion);

// Every enumerator of E has a non-empty word that no other one has, and the word reads back to it.
template <class E>
void expect_own_words() {
  std::set<std::string_view> seen;
  for (std::size_t i = 0; i < kEnumerators<E>; ++i) {
    const auto e = static_cast<E>(i);
    const std::string_view w = word(e);
    EXPECT_FALSE(w.empty()) << "enumerator " << i;
    EXPECT_TRUE(seen.insert(w).second) << "\"" << w << "\" twice";
    EXPECT_EQ(from_word<E>(w), e) << w;
  }
}

// The words of E in enumerator order, one space between.
template <class E>
std::string all_words() {
  std::string s;
  for (std::size_t i = 0; i < kEnumerators<E>; ++i) s += (i ? " " : "") + std::string(word(static_cast<E>(i)));
  return s;
}

TEST(Vocabulary, EveryEnumeratorHasItsOwnWord) {
  expect_own_words<EmergencyCause>();
  expect_own_words<PlannerState>();
  expect_own_words<ModeState>();
  expect_own_words<ModeReason>();
  expect_own_words<DemoPhase>();
}

// One word per enumerator: each table ends with the enum's last enumerator.
TEST(Vocabulary, OneWordPerEnumerator) {
  EXPECT_EQ(kEnumerators<EmergencyCause>, static_cast<std::size_t>(EmergencyCause::bus_off) + 1);
  EXPECT_EQ(kEnumerators<PlannerState>, static_cast<std::size_t>(PlannerState::operator_ended) + 1);
  EXPECT_EQ(kEnumerators<ModeState>, static_cast<std::size_t>(ModeState::finished) + 1);
  EXPECT_EQ(kEnumerators<ModeReason>, static_cast<std::size_t>(ModeReason::protective) + 1);
  EXPECT_EQ(kEnumerators<DemoPhase>, static_cast<std::size_t>(DemoPhase::failed) + 1);
}

// The wire words as clients match them (docs/PROTOCOL.md XE, XP, XD): a change here changes replies.
TEST(Vocabulary, WireWordsInOrder) {
  EXPECT_EQ(all_words<EmergencyCause>(),
            "none bumper obstacle comm-loss stop-byte motion-timeout drive-fault other heartbeat-lost "
            "bus-error-passive bus-off");
  EXPECT_EQ(all_words<PlannerState>(),
            "idle scanning planning moving crossing reached unreachable blocked outside stopped cancelled operator");
  EXPECT_EQ(all_words<ModeState>(),
            "off starting scanning searching moving aligned crossing waiting leaving crossed failed running finished");
  EXPECT_EQ(all_words<ModeReason>(),
            "none no-unit unit-silent unit-garbage unit-refused unit-lost no-passage cannot-align cant-cross "
            "emergency operator scanner cancelled link-lost timeout shutdown no-landmark protective");
  EXPECT_EQ(all_words<DemoPhase>(), "wait out turn lane align advance circle done failed");
}

TEST(Vocabulary, RoundTrips) {
  EXPECT_EQ(from_word<EmergencyCause>(word(EmergencyCause::heartbeat_lost)), EmergencyCause::heartbeat_lost);
  EXPECT_EQ(word(*from_word<ModeReason>("cant-cross")), "cant-cross");
  EXPECT_EQ(from_word<PlannerState>("unreachable"), PlannerState::unreachable);
  EXPECT_EQ(from_word<PlannerState>("operator"), PlannerState::operator_ended);  // XP's word, not the enumerator's name
  EXPECT_EQ(from_word<DemoPhase>("advance"), DemoPhase::advance);
  EXPECT_EQ(from_word<EmergencyCause>("comm_loss"), std::nullopt);  // the enumerator's name is not its word
  EXPECT_EQ(from_word<ModeState>(kAbsentWord), std::nullopt);       // XD's "absent" stands for no state
  EXPECT_EQ(from_word<ModeReason>(""), std::nullopt);
}

// Only a cast makes a value outside the list; it reads as the reply always printed for one.
TEST(Vocabulary, ValueOutsideTheList) {
  EXPECT_EQ(word(static_cast<EmergencyCause>(200)), "other");
  EXPECT_EQ(word(static_cast<PlannerState>(200)), "idle");
  EXPECT_EQ(word(static_cast<ModeState>(200)), "off");
  EXPECT_EQ(word(static_cast<ModeReason>(200)), "none");
  EXPECT_EQ(word(static_cast<DemoPhase>(200)), "done");
}

TEST(Vocabulary, DetectionBits) {
  EXPECT_EQ(kDetectBumper, 1);
  EXPECT_EQ(kDetectUltrasonic, 2);
  EXPECT_EQ(kDetectComm, 4);
  EXPECT_EQ(kDetectAll, 7);
}

}  // namespace
}  // namespace robuter::protocol::testing
