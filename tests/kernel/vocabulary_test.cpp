// SPDX-License-Identifier: GPL-3.0-or-later
// Worded enums (kernel/vocabulary.hpp): one list makes the enum and its words; they print, read back and join into a key's choices.
#include <gtest/gtest.h>

#include <cstdint>

#include "hal/api/drive.hpp"
#include "hal/api/serial_port_params.hpp"
#include "kernel/log.hpp"
#include "kernel/vocabulary.hpp"

namespace robuter::test {
namespace {

#define TEST_COLOURS(X) X(red, "red") X(deep_blue, "deep blue") X(green, "green")
enum class Colour : std::uint8_t { TEST_COLOURS(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_VOCABULARY(Colour, TEST_COLOURS, "green");

// Checked when compiled, too.
static_assert(kEnumerators<Colour> == 3);
static_assert(word(Colour::deep_blue) == "deep blue");
static_assert(from_word<Colour>("green") == Colour::green);
static_assert(word_list<Colour>() == "red|deep blue|green");
static_assert(!words_are_tokens<Colour>(24));  // a blank: fine in a log line, not one token of a reply

TEST(Vocabulary, WordsPrintAndReadBack) {
  for (std::size_t i = 0; i < kEnumerators<Colour>; ++i) {
    const auto c = static_cast<Colour>(i);
    EXPECT_EQ(from_word<Colour>(word(c)), c);
  }
  EXPECT_EQ(from_word<Colour>("deep_blue"), std::nullopt);  // the enumerator's name is not its word
  EXPECT_EQ(from_word<Colour>(""), std::nullopt);
  EXPECT_EQ(word(static_cast<Colour>(9)), "green");         // only a cast makes one: the fallback
}

// The configuration keys that name an enum accept exactly its words (the table's choices are the
// enum's list, not a second one), and the log's records print the same words.
TEST(Vocabulary, ConfigurationChoicesAreTheEnumsWords) {
  EXPECT_EQ(word_list<log::Level>(), "debug|info|warn|error|off");
  EXPECT_EQ(word_list<hal::Parity>(), "none|even|odd");
  EXPECT_EQ(word_list<hal::FlowControl>(), "none|hardware|software");
  EXPECT_EQ(word(hal::DriveHealth::silent), "heartbeat lost");  // the CAN backend's log words
}

}  // namespace
}  // namespace robuter::test
