// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the decoder: lookup, every schema, separators, and every parameter error.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "protocol/codec/command_table.hpp"
#include "protocol/codec/decoder.hpp"

namespace robuter::protocol {
namespace {

// The error a line decodes to (none when it is a command).
ErrorCode error_of(std::string_view line) { return decode(line).error; }

TEST(CommandTable, EveryPairIsUnique) {
  std::set<std::pair<char, char>> seen;
  std::set<CommandId> ids;
  for (const CommandRow& row : command_table()) {
    EXPECT_TRUE(seen.insert({row.category, row.type}).second) << row.category << row.type;
    EXPECT_TRUE(ids.insert(row.id).second) << row.category << row.type;
    EXPECT_NE(row.handler, nullptr);
  }
}

TEST(CommandTable, CoversEverySeedMessage) {
  for (const char* m : {"BO", "BU", "BV", "BC", "BT", "BP", "BF", "BD", "AM", "AS", "AY", "AC",
                        "AW", "AX", "Ap", "Ag", "AG", "AT", "Ad", "Af", "UT", "UD", "UN", "US",
                        "Ut", "Uu"}) {
    EXPECT_NE(find_command(m[0], m[1]), nullptr) << m;
  }
}

TEST(CommandTable, ExtensionsUseOnlyTheXCategory) {
  for (const CommandRow& row : command_table()) {
    EXPECT_TRUE(row.category == 'A' || row.category == 'B' || row.category == 'U' ||
                row.category == 'X');
  }
  for (const char* m : {"XE", "XR", "XK", "XV", "XS", "XB", "XC", "XL"}) {
    EXPECT_NE(find_command(m[0], m[1]), nullptr) << m;
  }
}

TEST(Decoder, NoParameters) {
  const Decoded d = decode("BO");
  ASSERT_EQ(d.error, ErrorCode::none);
  EXPECT_EQ(d.command.id, CommandId::get_posture);
  EXPECT_EQ(d.row->category, 'B');
  EXPECT_EQ(error_of("BO "), ErrorCode::none);
  EXPECT_EQ(error_of("BO , "), ErrorCode::none);
  EXPECT_EQ(error_of("BOX"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("BO 1"), ErrorCode::bad_parameter_count);
}

TEST(Decoder, CaseSensitive) {
  EXPECT_EQ(decode("Ut33").command.id, CommandId::set_us_timeout);
  EXPECT_EQ(decode("UT111111111111111111111111").command.id, CommandId::set_sensor_table);
  EXPECT_EQ(error_of("bo"), ErrorCode::unknown_command);
  EXPECT_EQ(error_of("bO"), ErrorCode::unknown_command);
  EXPECT_EQ(decode("AG").command.id, CommandId::gate_on);
  EXPECT_EQ(decode("Ag").command.id, CommandId::pan_tilt_off);
}

TEST(Decoder, ShortAndUnknownLines) {
  EXPECT_EQ(error_of(""), ErrorCode::line_too_short);
  EXPECT_EQ(error_of("B"), ErrorCode::line_too_short);
  EXPECT_EQ(error_of("Zz"), ErrorCode::unknown_command);
  EXPECT_EQ(error_of("Zz 1 2"), ErrorCode::unknown_command);
  EXPECT_EQ(error_of("BZ"), ErrorCode::unknown_command);
  EXPECT_EQ(error_of(" BO"), ErrorCode::unknown_command);
}

TEST(Decoder, TwoIntegersWithSeparators) {
  for (const char* line : {"AM 5 4", "AM5 4", "AM 5,4", "AM  5,  4", "AM,5,4", "AM 5 4 ",
                           "AM +5 4", "AM5,,,4,"}) {
    const Decoded d = decode(line);
    ASSERT_EQ(d.error, ErrorCode::none) << line;
    EXPECT_EQ(d.command.id, CommandId::move);
    EXPECT_EQ(d.command.int_count, 2);
    EXPECT_EQ(d.command.ints[0], 5) << line;
    EXPECT_EQ(d.command.ints[1], 4) << line;
  }
  const Decoded neg = decode("AM -10 -20");
  EXPECT_EQ(neg.command.ints[0], -10);
  EXPECT_EQ(neg.command.ints[1], -20);
}

TEST(Decoder, IntegerCountErrors) {
  EXPECT_EQ(error_of("AM 10"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("AM"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("AM 1 2 3"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("AC 1 2"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("AC 1 2 3 4"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("UD"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("Ut"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("AM x"), ErrorCode::bad_parameter_count);  // count wins over shape
}

TEST(Decoder, NonIntegersAreErrors) {
  for (const char* line : {"AM 1.5 2", "AM 1 2x", "AM - 2", "AM + 2", "AM 0x10 2", "AM 1e3 2",
                           "AM -+1 2", "UD5.", "UDa", "AC 1 2 3-"}) {
    EXPECT_EQ(error_of(line), ErrorCode::not_a_number) << line;
  }
}

TEST(Decoder, RangesAreChecked) {
  EXPECT_EQ(error_of("AM 1000 -1000"), ErrorCode::none);
  EXPECT_EQ(error_of("AM 1001 0"), ErrorCode::out_of_range);
  EXPECT_EQ(error_of("AM 0 -1001"), ErrorCode::out_of_range);
  EXPECT_EQ(error_of("AC 0 0 18000"), ErrorCode::none);
  EXPECT_EQ(error_of("AC 0 0 18001"), ErrorCode::out_of_range);
  EXPECT_EQ(error_of("AC 0 0 -18000"), ErrorCode::out_of_range);
  EXPECT_EQ(error_of("AC 0 0 -17999"), ErrorCode::none);
  EXPECT_EQ(error_of("AC 2147483647 -2147483648 0"), ErrorCode::none);
  EXPECT_EQ(error_of("AC 2147483648 0 0"), ErrorCode::out_of_range);
  EXPECT_EQ(error_of("AC 99999999999999999999999999 0 0"), ErrorCode::out_of_range);
  EXPECT_EQ(error_of("Ut0"), ErrorCode::out_of_range);
  EXPECT_EQ(error_of("UD-1"), ErrorCode::out_of_range);
  EXPECT_EQ(error_of("UD1001"), ErrorCode::out_of_range);
}

TEST(Decoder, ParametersRightAfterTheType) {
  const Decoded d = decode("UD5");
  ASSERT_EQ(d.error, ErrorCode::none);
  EXPECT_EQ(d.command.ints[0], 5);
  EXPECT_EQ(decode("Ut33").command.ints[0], 33);
  EXPECT_EQ(decode("AC1,2,3").command.ints[2], 3);
}

TEST(Decoder, OneOfChoices) {
  EXPECT_EQ(decode("ASN").command.choice, 'N');
  EXPECT_EQ(decode("ASF").command.choice, 'F');
  EXPECT_EQ(decode("AS N").command.choice, 'N');
  EXPECT_EQ(decode("Uu0").command.choice, '0');
  EXPECT_EQ(decode("Uu1").command.choice, '1');
  EXPECT_EQ(decode("USN").command.choice, 'N');
  EXPECT_EQ(decode("USS").command.choice, 'S');
  EXPECT_EQ(error_of("AS"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("ASX"), ErrorCode::bad_parameter);
  EXPECT_EQ(error_of("ASn"), ErrorCode::bad_parameter);
  EXPECT_EQ(error_of("ASNF"), ErrorCode::bad_parameter);
  EXPECT_EQ(error_of("AS N F"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("Uu2"), ErrorCode::bad_parameter);
  EXPECT_EQ(error_of("US"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("USX"), ErrorCode::bad_parameter);
}

TEST(Decoder, SensorTable) {
  const Decoded d = decode("UT100000000000000000000001");
  ASSERT_EQ(d.error, ErrorCode::none);
  EXPECT_TRUE(d.command.table.test(0));
  EXPECT_TRUE(d.command.table.test(23));
  EXPECT_EQ(d.command.table.count(), 2u);
  EXPECT_EQ(error_of("UT 111111111111111111111111"), ErrorCode::none);
  EXPECT_EQ(error_of("UT1011"), ErrorCode::bad_parameter);
  EXPECT_EQ(error_of("UT11111111111111111111111"), ErrorCode::bad_parameter);     // 23
  EXPECT_EQ(error_of("UT1111111111111111111111111"), ErrorCode::bad_parameter);   // 25
  EXPECT_EQ(error_of("UT11111111111111111111111x"), ErrorCode::bad_parameter);
  EXPECT_EQ(error_of("UT111111111111 111111111111"), ErrorCode::bad_parameter_count);
  EXPECT_EQ(error_of("UT"), ErrorCode::bad_parameter_count);
}

TEST(Decoder, PassThroughTakesTheRestVerbatim) {
  const Decoded d = decode("AY hello, world  ");
  ASSERT_EQ(d.error, ErrorCode::none);
  EXPECT_EQ(d.command.text, " hello, world  ");
  EXPECT_EQ(decode("AYPA6000").command.text, "PA6000");
  EXPECT_EQ(error_of("AY"), ErrorCode::bad_parameter_count);
}

TEST(Decoder, ParseIntegerDirectly) {
  std::int32_t v = 0;
  EXPECT_EQ(parse_integer("-0", IntRange{}, v), ErrorCode::none);
  EXPECT_EQ(v, 0);
  EXPECT_EQ(parse_integer("007", IntRange{}, v), ErrorCode::none);
  EXPECT_EQ(v, 7);
  EXPECT_EQ(parse_integer("", IntRange{}, v), ErrorCode::not_a_number);
  EXPECT_EQ(parse_integer("-2147483648", IntRange{}, v), ErrorCode::none);
  EXPECT_EQ(v, -2147483647 - 1);
  EXPECT_EQ(parse_integer("-2147483649", IntRange{}, v), ErrorCode::out_of_range);
}

}  // namespace
}  // namespace robuter::protocol
