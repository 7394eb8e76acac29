// SPDX-License-Identifier: GPL-3.0-or-later
// CiA 301/402 frames and state machine against bytes written out by hand from the specifications.
#include <gtest/gtest.h>
#include <linux/can/error.h>

#include <initializer_list>
#include <string>

#include "hal/linux/can/cia402.hpp"
#include "hal/linux/can/socketcan_transport.hpp"
#include "hal/linux/can/sonar_frames.hpp"

namespace robuter::hal::can {
namespace {

using namespace cia402;

// A frame written out by hand: id and payload bytes.
can_frame hand(canid_t id, std::initializer_list<std::uint8_t> bytes) {
  can_frame f{};
  f.can_id = id;
  f.len = static_cast<std::uint8_t>(bytes.size());
  int i = 0;
  for (std::uint8_t b : bytes) f.data[i++] = b;
  return f;
}

// "id#bytes" as candump prints it, for readable failures.
std::string text(const can_frame& f) {
  char buf[64];
  int n = std::snprintf(buf, sizeof buf, "%03X#", f.can_id);
  for (int i = 0; i < f.len; ++i) n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "%02X", f.data[i]);
  return buf;
}

#define EXPECT_FRAME(actual, expected) EXPECT_EQ(text(actual), text(expected))

// CiA 301 §7.2.8.3.1: NMT is COB-ID 0, two bytes: command specifier, node id (0 = all).
TEST(Cia301, NmtFramesByteExact) {
  EXPECT_FRAME(nmt(NmtCommand::start, 1), hand(0x000, {0x01, 0x01}));
  EXPECT_FRAME(nmt(NmtCommand::start, 0), hand(0x000, {0x01, 0x00}));
  EXPECT_FRAME(nmt(NmtCommand::stop, 2), hand(0x000, {0x02, 0x02}));
  EXPECT_FRAME(nmt(NmtCommand::enter_pre_operational, 3), hand(0x000, {0x80, 0x03}));
  EXPECT_FRAME(nmt(NmtCommand::reset_node, 1), hand(0x000, {0x81, 0x01}));
  EXPECT_FRAME(nmt(NmtCommand::reset_communication, 1), hand(0x000, {0x82, 0x01}));
  NmtCommand c{};
  std::uint8_t node = 9;
  ASSERT_TRUE(parse_nmt(hand(0x000, {0x01, 0x05}), c, node));
  EXPECT_EQ(c, NmtCommand::start);
  EXPECT_EQ(node, 5);
  EXPECT_FALSE(parse_nmt(hand(0x000, {0x03, 0x05}), c, node));  // no such command
  EXPECT_FALSE(parse_nmt(hand(0x000, {0x01}), c, node));        // too short
}

// SYNC is COB-ID 0x80 without data; heartbeat 0x700 + id, one byte: 0 boot-up, 4 stopped,
// 5 operational, 0x7F pre-operational.
TEST(Cia301, SyncAndHeartbeatByteExact) {
  EXPECT_FRAME(sync(), hand(0x080, {}));
  EXPECT_FRAME(heartbeat(1, NmtState::operational), hand(0x701, {0x05}));
  EXPECT_FRAME(heartbeat(2, NmtState::pre_operational), hand(0x702, {0x7F}));
  EXPECT_FRAME(heartbeat(0x10, NmtState::boot_up), hand(0x710, {0x00}));
  EXPECT_FRAME(heartbeat(127, NmtState::stopped), hand(0x77F, {0x04}));
  NmtState s{};
  ASSERT_TRUE(parse_heartbeat(hand(0x701, {0x85}), s));  // toggle bit ignored
  EXPECT_EQ(s, NmtState::operational);
  EXPECT_FALSE(parse_heartbeat(hand(0x701, {0x06}), s));  // no such state
  EXPECT_FALSE(parse_heartbeat(hand(0x701, {}), s));
  EXPECT_FALSE(parse_heartbeat(hand(0x700, {0x05}), s));  // node 0 does not exist
  EXPECT_EQ(node_of(hand(0x77F, {0x05}), kHeartbeat), 127);
  EXPECT_EQ(node_of(hand(0x780, {0x05}), kHeartbeat), 0);
}

// Expedited SDO download (CiA 301 §7.2.4.3.3): ccs=1, e=1, s=1, n = 4 − size: 0x2F one byte,
// 0x2B two, 0x23 four; index little-endian, sub-index, data. Answer 0x60; abort 0x80 + code.
TEST(Cia301, SdoDownloadByteExact) {
  EXPECT_FRAME(sdo_download(1, 0x6060, 0, 3, 1), hand(0x601, {0x2F, 0x60, 0x60, 0x00, 0x03, 0x00, 0x00, 0x00}));
  EXPECT_FRAME(sdo_download(2, 0x1017, 0, 100, 2), hand(0x602, {0x2B, 0x17, 0x10, 0x00, 0x64, 0x00, 0x00, 0x00}));
  EXPECT_FRAME(sdo_download(1, 0x60FF, 0, 0x12345678, 4),
               hand(0x601, {0x23, 0xFF, 0x60, 0x00, 0x78, 0x56, 0x34, 0x12}));
  EXPECT_FRAME(sdo_download_ack(1, 0x6060, 0), hand(0x581, {0x60, 0x60, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_FRAME(sdo_abort(1, 0x6060, 0, 0x06090030), hand(0x581, {0x80, 0x60, 0x60, 0x00, 0x30, 0x00, 0x09, 0x06}));
  SdoMessage m;
  ASSERT_TRUE(parse_sdo(hand(0x581, {0x80, 0x17, 0x10, 0x00, 0x00, 0x00, 0x02, 0x06}), kSdoResponse, m));
  EXPECT_EQ(m.command, 0x80);
  EXPECT_EQ(m.index, 0x1017);
  EXPECT_EQ(m.data, 0x06020000u);
  EXPECT_FALSE(parse_sdo(hand(0x581, {0x60, 0x17, 0x10}), kSdoResponse, m));  // SDO frames are 8 bytes
}

// PDOs as mapped in docs/CAN.md: RPDO1 0x200+id = controlword (u16) + target velocity (i32);
// TPDO1 0x180+id = statusword (u16) + velocity actual (i32); TPDO2 0x280+id = position (i32).
TEST(Cia402, PdoEncodingByteExact) {
  EXPECT_FRAME(rpdo1(1, 0x000F, 1000), hand(0x201, {0x0F, 0x00, 0xE8, 0x03, 0x00, 0x00}));
  EXPECT_FRAME(rpdo1(2, 0x0007, -1000), hand(0x202, {0x07, 0x00, 0x18, 0xFC, 0xFF, 0xFF}));
  EXPECT_FRAME(rpdo1(1, 0x0080, 0), hand(0x201, {0x80, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_FRAME(tpdo1(1, 0x0637, 500), hand(0x181, {0x37, 0x06, 0xF4, 0x01, 0x00, 0x00}));
  EXPECT_FRAME(tpdo2(2, 0x12345678), hand(0x282, {0x78, 0x56, 0x34, 0x12}));
  EXPECT_FRAME(tpdo2(2, -2), hand(0x282, {0xFE, 0xFF, 0xFF, 0xFF}));

  std::uint16_t w = 0;
  std::int32_t v = 0;
  ASSERT_TRUE(parse_tpdo1(hand(0x181, {0x37, 0x06, 0x18, 0xFC, 0xFF, 0xFF}), w, v));
  EXPECT_EQ(w, 0x0637);
  EXPECT_EQ(v, -1000);
  ASSERT_TRUE(parse_rpdo1(hand(0x201, {0x0F, 0x00, 0xE8, 0x03, 0x00, 0x00}), w, v));
  EXPECT_EQ(w, 0x000F);
  EXPECT_EQ(v, 1000);
  std::int32_t p = 0;
  ASSERT_TRUE(parse_tpdo2(hand(0x281, {0x00, 0x00, 0x00, 0x80}), p));
  EXPECT_EQ(p, INT32_MIN);
  EXPECT_FALSE(parse_tpdo1(hand(0x181, {0x37, 0x06, 0x18, 0xFC, 0xFF}), w, v));  // 5 bytes
  can_frame rtr = hand(0x181, {0x37, 0x06, 0, 0, 0, 0});
  rtr.can_id |= CAN_RTR_FLAG;
  EXPECT_FALSE(parse_tpdo1(rtr, w, v));
  can_frame ext = hand(0x181, {0x37, 0x06, 0, 0, 0, 0});
  ext.can_id |= CAN_EFF_FLAG;
  EXPECT_FALSE(parse_tpdo1(ext, w, v));
}

// EMCY 0x80 + id: error code (u16), error register (u8), five manufacturer bytes.
TEST(Cia301, EmcyByteExact) {
  EXPECT_FRAME(emcy(1, 0x2310, 0x03), hand(0x081, {0x10, 0x23, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_FRAME(emcy(2, 0x0000, 0x00), hand(0x082, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}));
  std::uint16_t code = 0;
  std::uint8_t reg = 0;
  ASSERT_TRUE(parse_emcy(hand(0x081, {0x30, 0x73, 0x81, 0, 0, 0, 0, 0}), code, reg));
  EXPECT_EQ(code, 0x7330);  // sensor (resolver) fault
  EXPECT_EQ(reg, 0x81);
  EXPECT_FALSE(parse_emcy(hand(0x080, {0x30, 0x73, 0x81, 0, 0, 0, 0, 0}), code, reg));  // that is SYNC
}

// The CiA 402 statusword table, one row per state (x = don't care filled both ways).
TEST(Cia402, StatuswordTable) {
  EXPECT_EQ(decode_statusword(0x0000), State::not_ready_to_switch_on);  // xxxx xxxx x0xx 0000
  EXPECT_EQ(decode_statusword(0x0230), State::not_ready_to_switch_on);
  EXPECT_EQ(decode_statusword(0x0040), State::switch_on_disabled);      // x1xx 0000
  EXPECT_EQ(decode_statusword(0x0270), State::switch_on_disabled);
  EXPECT_EQ(decode_statusword(0x0021), State::ready_to_switch_on);      // x01x 0001
  EXPECT_EQ(decode_statusword(0x0231), State::ready_to_switch_on);
  EXPECT_EQ(decode_statusword(0x0023), State::switched_on);             // x01x 0011
  EXPECT_EQ(decode_statusword(0x0233), State::switched_on);
  EXPECT_EQ(decode_statusword(0x0027), State::operation_enabled);       // x01x 0111
  EXPECT_EQ(decode_statusword(0x0637), State::operation_enabled);
  EXPECT_EQ(decode_statusword(0x0007), State::quick_stop_active);       // x00x 0111
  EXPECT_EQ(decode_statusword(0x0217), State::quick_stop_active);
  EXPECT_EQ(decode_statusword(0x000F), State::fault_reaction_active);   // x0xx 1111
  EXPECT_EQ(decode_statusword(0x023F), State::fault_reaction_active);
  EXPECT_EQ(decode_statusword(0x0008), State::fault);                   // x0xx 1000
  EXPECT_EQ(decode_statusword(0x0218), State::fault);
  EXPECT_EQ(decode_statusword(0x0048), State::fault);  // outside the table, fault bit set: a fault
  for (State s : {State::not_ready_to_switch_on, State::switch_on_disabled, State::ready_to_switch_on,
                  State::switched_on, State::operation_enabled, State::quick_stop_active,
                  State::fault_reaction_active, State::fault})
    EXPECT_EQ(decode_statusword(encode_statusword(s)), s) << word(s);
  EXPECT_EQ(encode_statusword(State::operation_enabled), 0x0237);
}

// Device control commands: shutdown 0x06, switch on 0x07, enable operation 0x0F, disable
// voltage 0x00, quick stop 0x02, disable operation 0x07, fault reset 0x80 (rising edge).
TEST(Cia402, ControlwordTransitions) {
  EXPECT_EQ(apply_controlword(State::switch_on_disabled, 0x06, 0), State::ready_to_switch_on);   // 2
  EXPECT_EQ(apply_controlword(State::switch_on_disabled, 0x0F, 0), State::switch_on_disabled);   // no jump
  EXPECT_EQ(apply_controlword(State::ready_to_switch_on, 0x07, 0x06), State::switched_on);       // 3
  EXPECT_EQ(apply_controlword(State::ready_to_switch_on, 0x0F, 0x06), State::operation_enabled); // 3+4
  EXPECT_EQ(apply_controlword(State::ready_to_switch_on, 0x00, 0x06), State::switch_on_disabled);// 7
  EXPECT_EQ(apply_controlword(State::switched_on, 0x0F, 0x07), State::operation_enabled);        // 4
  EXPECT_EQ(apply_controlword(State::switched_on, 0x06, 0x07), State::ready_to_switch_on);       // 6
  EXPECT_EQ(apply_controlword(State::switched_on, 0x02, 0x07), State::switch_on_disabled);       // 10
  EXPECT_EQ(apply_controlword(State::operation_enabled, 0x07, 0x0F), State::switched_on);        // 5
  EXPECT_EQ(apply_controlword(State::operation_enabled, 0x06, 0x0F), State::ready_to_switch_on); // 8
  EXPECT_EQ(apply_controlword(State::operation_enabled, 0x00, 0x0F), State::switch_on_disabled); // 9
  EXPECT_EQ(apply_controlword(State::operation_enabled, 0x02, 0x0F), State::quick_stop_active);  // 11
  EXPECT_EQ(apply_controlword(State::operation_enabled, 0x0F, 0x0F), State::operation_enabled);
  EXPECT_EQ(apply_controlword(State::quick_stop_active, 0x00, 0x02), State::switch_on_disabled); // 12
  EXPECT_EQ(apply_controlword(State::fault, 0x80, 0x00), State::switch_on_disabled);             // 15
  EXPECT_EQ(apply_controlword(State::fault, 0x80, 0x80), State::fault);  // no edge, no reset
  EXPECT_EQ(apply_controlword(State::fault, 0x0F, 0x00), State::fault);
}

// The host's walk: one command per confirmed state, servo off parks in "switched on".
TEST(Cia402, HostControlwordSequence) {
  State s = State::switch_on_disabled;
  std::uint16_t prev = 0;
  const std::uint16_t expected[] = {0x06, 0x07, 0x0F, 0x0F};
  for (std::uint16_t want : expected) {
    const std::uint16_t cw = next_controlword(s, true, false);
    EXPECT_EQ(cw, want) << word(s);
    s = apply_controlword(s, cw, prev);
    prev = cw;
  }
  EXPECT_EQ(s, State::operation_enabled);
  EXPECT_EQ(next_controlword(State::operation_enabled, false, false), 0x07);
  EXPECT_EQ(next_controlword(State::switched_on, false, false), 0x07);
  EXPECT_EQ(next_controlword(State::fault, false, true), 0x80);
  EXPECT_EQ(next_controlword(State::fault, true, false), 0x00);
  EXPECT_EQ(next_controlword(State::quick_stop_active, true, false), 0x00);
}

// docs/CAN.md frame set of the ultrasonic nodes.
TEST(SonarFrames, ByteExact) {
  EXPECT_FRAME(sonar::fire(0x10, 0x0F, 33, 300), hand(0x210, {0x0F, 0x21, 0x00, 0x2C, 0x01}));
  EXPECT_FRAME(sonar::fire(0x17, 0x03, 15, 335), hand(0x217, {0x03, 0x0F, 0x00, 0x4F, 0x01}));
  EXPECT_FRAME(sonar::ranges(0x11, {1000, 0, 4950, 258}),
               hand(0x191, {0xE8, 0x03, 0x00, 0x00, 0x56, 0x13, 0x02, 0x01}));
  EXPECT_FRAME(sonar::status(0x12, 0x04, sonar::kStatusBusy), hand(0x292, {0x04, 0x01}));
  sonar::FireRequest r;
  ASSERT_TRUE(sonar::parse_fire(hand(0x210, {0x05, 0x21, 0x00, 0x2C, 0x01}), r));
  EXPECT_EQ(r.mask, 0x05);
  EXPECT_EQ(r.timeout_ms, 33);
  EXPECT_EQ(r.sound_speed_m_s, 300);
  std::array<std::uint16_t, 4> mm{};
  EXPECT_FALSE(sonar::parse_ranges(hand(0x190, {0xE8, 0x03}), mm));
}

// linux/can/error.h: CAN_ERR_CRTL (0x04) with data[1] 0x10/0x20 RX/TX passive, 0x04/0x08 RX/TX
// warning, 0x40 back to active; CAN_ERR_BUSOFF (0x40); CAN_ERR_RESTARTED (0x100).
TEST(SocketCan, ErrorFramesGiveTheBusState) {
  const auto err = [](canid_t id, std::uint8_t d1) {
    can_frame f = hand(CAN_ERR_FLAG | id, {0x00, d1, 0, 0, 0, 0, 0, 0});
    return f;
  };
  EXPECT_EQ(apply_error_frame(BusState::active, err(0x004, 0x20)), BusState::passive);
  EXPECT_EQ(apply_error_frame(BusState::active, err(0x004, 0x10)), BusState::passive);
  EXPECT_EQ(apply_error_frame(BusState::active, err(0x004, 0x08)), BusState::warning);
  EXPECT_EQ(apply_error_frame(BusState::passive, err(0x004, 0x40)), BusState::active);
  EXPECT_EQ(apply_error_frame(BusState::active, err(0x040, 0x00)), BusState::off);
  EXPECT_EQ(apply_error_frame(BusState::off, err(0x100, 0x00)), BusState::active);
  EXPECT_EQ(apply_error_frame(BusState::warning, err(0x008, 0x00)), BusState::warning);  // protocol error: no change
  EXPECT_EQ(apply_error_frame(BusState::passive, hand(0x181, {0x40, 0x00})), BusState::passive);  // a data frame
}

// This machine's kernel has no AF_CAN: opening fails with a message naming the missing family
// and the docs; on a kernel with CAN, a missing interface is named instead.
TEST(SocketCan, OpenFailsWithAClearMessage) {
  std::string err;
  auto t = SocketCanTransport::open("nocan7", err);
  ASSERT_EQ(t, nullptr);
  const bool no_family = err.find("AF_CAN") != std::string::npos && err.find("docs/CAN.md") != std::string::npos;
  const bool no_device = err.find("no such network interface") != std::string::npos;
  EXPECT_TRUE(no_family || no_device) << err;
  EXPECT_NE(err.find("'nocan7'"), std::string::npos) << err;
  EXPECT_EQ(SocketCanTransport::open("a-name-far-too-long-for-linux", err), nullptr);
  EXPECT_NE(err.find("1 to 15 characters"), std::string::npos) << err;
  const std::string m = socketcan_error("can0", "socket(PF_CAN, SOCK_RAW, CAN_RAW)", EAFNOSUPPORT);
  EXPECT_NE(m.find("AF_CAN"), std::string::npos);
  EXPECT_NE(m.find("docs/CAN.md"), std::string::npos);
}

}  // namespace
}  // namespace robuter::hal::can
