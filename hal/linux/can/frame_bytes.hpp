// SPDX-License-Identifier: GPL-3.0-or-later
// Little-endian byte packing of CAN frames (CANopen's byte order), shared by every frame encoder.
#pragma once

#include <linux/can.h>

#include <cstdint>

namespace robuter::hal::can::bytes {

// Why: every encoder starts from a zeroed standard frame with its id and length.
inline can_frame frame(canid_t id, std::uint8_t len) {
  can_frame f{};
  f.can_id = id;
  f.len = len;
  return f;
}
// Why: CANopen puts multi-byte values least significant byte first.
inline void put16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
inline void put32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
inline std::uint16_t get16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }
inline std::uint32_t get32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

}  // namespace robuter::hal::can::bytes
