// SPDX-License-Identifier: GPL-3.0-or-later
// The ultrasonic nodes' CAN frame set (docs/CAN.md): fire with mask, ranges back, node status. Pure.
#pragma once

#include <linux/can.h>

#include <array>
#include <cstdint>

namespace robuter::hal::can::sonar {

// COB-IDs (add the node id): the predefined connection set's PDO slots, so a sonar node is an
// ordinary CANopen node (NMT start, heartbeat) beside the drives.
inline constexpr canid_t kFire = 0x200;     // host → node: fire (RPDO1 slot)
inline constexpr canid_t kRanges = 0x180;   // node → host: the four ranges (TPDO1 slot)
inline constexpr canid_t kStatus = 0x280;   // node → host: node status (TPDO2 slot)

// Status flags (byte 1 of a status frame).
inline constexpr std::uint8_t kStatusBusy = 1u << 0;  // a firing is in progress

// Fire: [mask][timeout_ms u16][sound_speed_m_s u16], 5 bytes. Bit i of mask = transducer i.
can_frame fire(std::uint8_t node, std::uint8_t mask, std::uint16_t timeout_ms, std::uint16_t sound_speed_m_s);
// Ranges: four u16, mm (0 = not fired or no echo within the time-out), 8 bytes.
can_frame ranges(std::uint8_t node, const std::array<std::uint16_t, 4>& mm);
// Status: [faulty transducers mask][flags], 2 bytes.
can_frame status(std::uint8_t node, std::uint8_t faulty_mask, std::uint8_t flags);

// A fire request as a node reads it.
struct FireRequest {
  std::uint8_t mask = 0;              // transducers to fire, bit i = index i
  std::uint16_t timeout_ms = 0;       // echo time-out, ms
  std::uint16_t sound_speed_m_s = 0;  // speed of sound to convert echo times, m/s
};
bool parse_fire(const can_frame& f, FireRequest& out);
bool parse_ranges(const can_frame& f, std::array<std::uint16_t, 4>& mm);
bool parse_status(const can_frame& f, std::uint8_t& faulty_mask, std::uint8_t& flags);

}  // namespace robuter::hal::can::sonar
