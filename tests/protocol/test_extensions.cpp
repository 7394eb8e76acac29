// SPDX-License-Identifier: GPL-3.0-or-later
// The X extensions: emergency, re-enable, kernel figures, version, stream, verbose errors,
// checksums and the reply terminator.
#include <gtest/gtest.h>

#include <string>

#include "protocol/codec/checksum.hpp"
#include "protocol/codec/handlers.hpp"
#include "protocol/codec/stream_encoder.hpp"
#include "tests/protocol/codec_harness.hpp"

namespace robuter::protocol::testing {
namespace {

// A line with its checksum appended, as an XC1 client sends it.
std::string with_crc(std::string_view body) {
  char hex[kChecksumDigits];
  format_checksum(crc16(body), hex);
  return std::string(body) + "*" + std::string(hex, kChecksumDigits);
}

TEST(Extensions, XE) {
  Harness h;
  EXPECT_EQ(h.ask("XE"), "E 0 0 none 7 1523 100 envelope 0");
  h.port.emerg = {false, true, EmergencyCause::obstacle, kDetectBumper | kDetectComm};
  EXPECT_EQ(h.ask("XE"), "E 0 1 obstacle 5 1523 100 envelope 0");
  h.port.emerg = {true, false, EmergencyCause::none, 7};
  EXPECT_EQ(h.ask("XE"), "E 1 0 none 7 1523 100 envelope 0");
  h.port.emerg.cause = EmergencyCause::comm_loss;
  EXPECT_EQ(h.ask("XE").substr(0, 18), "E 1 0 comm-loss 7 ");
  // The envelope's fields follow the clock: granted share, rule, protective stop.
  h.port.emerg = {false, false, EmergencyCause::none, 7, 0, true, true};
  EXPECT_EQ(h.ask("XE"), "E 0 0 none 7 1523 0 envelope 1");
  h.port.emerg = {false, false, EmergencyCause::none, 7, 40, false, false};
  EXPECT_EQ(h.ask("XE"), "E 0 0 none 7 1523 40 seed 0");
}

TEST(Extensions, CauseNames) {
  EXPECT_EQ(word(EmergencyCause::bumper), "bumper");
  EXPECT_EQ(word(EmergencyCause::stop_byte), "stop-byte");
  EXPECT_EQ(word(EmergencyCause::other), "other");
  EXPECT_EQ(word(EmergencyCause::heartbeat_lost), "heartbeat-lost");
  EXPECT_EQ(word(EmergencyCause::bus_passive), "bus-error-passive");
  EXPECT_EQ(word(EmergencyCause::bus_off), "bus-off");
}

TEST(Extensions, XR) {
  Harness h;
  EXPECT_EQ(h.ask("XR"), "ack");
  EXPECT_EQ(h.port.reenables, 1);
  h.port.result = PortResult::refused_emergency;
  h.codec.session().verbose_errors = true;
  EXPECT_EQ(h.ask("XR"), "error 7 refused-emergency");
}

TEST(Extensions, XK) {
  Harness h;
  EXPECT_EQ(h.ask("XK"),
            "K 1000 180 42 3 serial 100 0 0 12 40 emergency 50 1 2 30 95 execute 50 0 0 20 60 "
            "1523");
  h.port.process_count = 0;
  EXPECT_EQ(h.ask("XK"), "K 1000 180 42 0 1523");
}

TEST(Extensions, XKSanitisesNames) {
  Harness h;
  h.port.process_count = 1;
  h.port.processes[0].name = "a b*c";
  EXPECT_EQ(h.ask("XK").substr(0, 20), "K 1000 180 42 1 a_b_");
  h.port.processes[0].name = "";
  EXPECT_EQ(h.ask("XK").substr(0, 17), "K 1000 180 42 1 -");
}

TEST(Extensions, XV) {
  Harness h;
  EXPECT_EQ(h.ask("XV"),
            "V robuterd 0.1.0 proto 1 caps "
            "stop,emergency,reenable,kernel,stream,verbose,checksum,terminator,pantilt,gate,doors");
  h.port.feature_bits = kFeaturePassThrough | kFeatureGoTo;
  const std::string r = h.ask("XV");
  EXPECT_EQ(r.substr(r.find("terminator")), "terminator,passthrough,goto");
}

TEST(Extensions, XBVerboseErrors) {
  Harness h;
  EXPECT_EQ(h.ask("Zz"), "error");
  EXPECT_EQ(h.ask("XB1"), "ack");
  EXPECT_EQ(h.ask("Zz"), "error 1 unknown-command");
  EXPECT_EQ(h.ask("AM 10"), "error 2 bad-parameter-count");
  EXPECT_EQ(h.ask("AM 1 x"), "error 3 not-a-number");
  EXPECT_EQ(h.ask("AM 1 5000"), "error 4 out-of-range");
  EXPECT_EQ(h.feed(std::string(300, 'a') + "\r"),
            std::vector<std::string>{"error 5 line-too-long\r"});
  EXPECT_EQ(h.feed(std::string("B\0C\r", 4)), std::vector<std::string>{"error 6 bad-byte\r"});
  h.port.motion_result = PortResult::refused_emergency;
  EXPECT_EQ(h.ask("AM 1 1"), "error 7 refused-emergency");
  EXPECT_EQ(h.ask("AYx"), "error 8 not-permitted");
  EXPECT_EQ(h.ask("B"), "error 9 line-too-short");
  EXPECT_EQ(h.ask("UT1011"), "error 10 bad-parameter");
  h.port.has_pan_tilt = false;
  EXPECT_EQ(h.ask("BP"), "error 12 unavailable");
  h.port.result = PortResult::busy;
  EXPECT_EQ(h.ask("AW 0 0 0"), "error 13 busy");
  EXPECT_EQ(h.ask("XB0"), "ack");
  EXPECT_EQ(h.ask("Zz"), "error");
  EXPECT_EQ(h.ask("XB2"), "error");
}

TEST(Extensions, XSStreaming) {
  Harness h;
  EXPECT_FALSE(h.codec.poll_stream(h.port).has_value());
  EXPECT_EQ(h.ask("XS 5"), "error");
  EXPECT_EQ(h.ask("XS60001"), "error");
  EXPECT_EQ(h.ask("XS 50"), "ack");
  EXPECT_EQ(h.codec.session().stream_period, 50u);
  auto line = h.codec.poll_stream(h.port);
  ASSERT_TRUE(line.has_value());
  EXPECT_EQ(*line, "@ 1204 -3 12 1 10 10 0 1523\r");
  h.port.now += 49;
  EXPECT_FALSE(h.codec.poll_stream(h.port).has_value());
  h.port.now += 1;
  h.port.emerg.latched = true;
  line = h.codec.poll_stream(h.port);
  ASSERT_TRUE(line.has_value());
  EXPECT_EQ(*line, "@ 1204 -3 12 1 10 10 2 1573\r");
  EXPECT_EQ(h.ask("XS0"), "ack");
  EXPECT_FALSE(h.codec.poll_stream(h.port).has_value());
}

TEST(Extensions, StreamDoesNotDisturbAReply) {
  Harness h;
  h.ask("XS10");
  std::vector<std::string> seen;
  const std::string bytes = "BC\r";
  h.codec.feed(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()),
               h.port, [&](std::string_view reply) {
                 auto s = h.codec.poll_stream(h.port);
                 seen.emplace_back(reply);
                 if (s) seen.emplace_back(*s);
               });
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0], "C 1523\r");
  EXPECT_EQ(seen[1].substr(0, 2), "@ ");
}

TEST(Extensions, EmergencyFieldOfStream) {
  EXPECT_EQ(stream_emergency_field({true, true, EmergencyCause::bumper, 0}), 3);
  EXPECT_EQ(stream_emergency_field({}), 0);
  EmergencyStatus protective;
  protective.protective = true;
  EXPECT_EQ(stream_emergency_field(protective), 4);
}

TEST(Extensions, XLTerminator) {
  Harness h;
  EXPECT_EQ(h.feed("XL1\r"), std::vector<std::string>{"ack\r"});  // old terminator for XL
  EXPECT_EQ(h.feed("BC\r"), std::vector<std::string>{"C 1523\n"});
  EXPECT_EQ(h.feed("XL2\n"), std::vector<std::string>{"ack\n"});
  EXPECT_EQ(h.feed("BC\n"), std::vector<std::string>{"C 1523\r\n"});
  EXPECT_EQ(h.feed("XL0\r\n"), std::vector<std::string>{"ack\r\n"});
  EXPECT_EQ(h.feed("BC\r"), std::vector<std::string>{"C 1523\r"});
  EXPECT_EQ(h.feed("XL3\r"), std::vector<std::string>{"error\r"});
}

TEST(Extensions, Crc16KnownValue) {
  EXPECT_EQ(crc16("123456789"), 0x29B1);  // CRC-16/CCITT-FALSE check value
  EXPECT_EQ(crc16(""), 0xFFFF);
}

TEST(Extensions, StripChecksum) {
  std::string_view body;
  const std::string line = with_crc("BC");
  EXPECT_TRUE(strip_checksum(line, body));
  EXPECT_EQ(body, "BC");
  std::string lower = with_crc("BC");
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  EXPECT_FALSE(strip_checksum(lower, body));  // "bc" has another CRC
  std::string good = with_crc("BC");
  for (std::size_t i = 3; i < good.size(); ++i) {
    good[i] = static_cast<char>(std::tolower(static_cast<unsigned char>(good[i])));
  }
  EXPECT_TRUE(strip_checksum(good, body));  // hex digits in either case
  EXPECT_FALSE(strip_checksum("BC", body));
  EXPECT_FALSE(strip_checksum("BC*12", body));
  EXPECT_FALSE(strip_checksum("BC*12G4", body));
  EXPECT_FALSE(strip_checksum("BC 1234", body));
}

TEST(Extensions, XCChecksums) {
  Harness h;
  EXPECT_EQ(h.ask("XC1"), "ack");  // reply in the mode the line came in
  EXPECT_EQ(h.ask("BC"), with_crc("error"));
  EXPECT_EQ(h.ask(with_crc("BC")), with_crc("C 1523"));
  std::string corrupted = with_crc("AM 10 10");
  corrupted[3] = '9';
  EXPECT_EQ(h.ask(corrupted), with_crc("error"));
  EXPECT_EQ(h.port.motion_requests, 0);
  EXPECT_EQ(h.ask(with_crc("AM 10 10")), with_crc("ack"));
  EXPECT_EQ(h.port.motion_requests, 1);
  EXPECT_EQ(h.ask(with_crc("XB1")), with_crc("ack"));
  EXPECT_EQ(h.ask("BC"), with_crc("error 11 bad-checksum"));
  EXPECT_EQ(h.ask(with_crc("AY a*b")), with_crc("error 8 not-permitted"));
  EXPECT_EQ(h.port.passed(), " a*b");
  EXPECT_EQ(h.feed(std::string(250, 'x') + "\r"), std::vector<std::string>{
                                                      with_crc("error 5 line-too-long") + "\r"});
  EXPECT_EQ(h.ask("XC0"), with_crc("error 11 bad-checksum"));  // turning off needs one too
  EXPECT_EQ(h.ask(with_crc("XC0")), with_crc("ack"));
  EXPECT_EQ(h.ask("BC"), "C 1523");
}

TEST(Extensions, ChecksumExampleOfTheDocs) {
  Harness h;
  EXPECT_EQ(h.ask("XC1"), "ack");
  EXPECT_EQ(h.ask("BC*0E06"), "C 1523*B39B");
  EXPECT_EQ(h.ask("AM 10 10*8EB4"), "ack*E373");
  EXPECT_EQ(h.ask("AM 90 10*8EB4"), "error*7733");
  EXPECT_EQ(h.ask("BC"), "error*7733");
  EXPECT_EQ(h.ask("XC0*553F"), "ack*E373");
  EXPECT_EQ(h.ask("BC"), "C 1523");
  EXPECT_EQ(h.port.motion_requests, 1);
}

TEST(Extensions, StreamLinesCarryChecksums) {
  Harness h;
  h.codec.session().checksums = true;
  h.codec.session().stream_period = 10;
  const auto line = h.codec.poll_stream(h.port);
  ASSERT_TRUE(line.has_value());
  EXPECT_EQ(*line, with_crc("@ 1204 -3 12 1 10 10 0 1523") + "\r");
}

TEST(Extensions, ResetRestoresSeedBehaviour) {
  Harness h;
  h.ask("XB1");
  h.ask("XS100");
  h.feed("AM 1");
  h.codec.reset();
  EXPECT_EQ(h.codec.session().stream_period, 0u);
  EXPECT_EQ(h.ask("Zz"), "error");
}

}  // namespace
}  // namespace robuter::protocol::testing
