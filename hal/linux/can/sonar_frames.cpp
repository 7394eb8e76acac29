// SPDX-License-Identifier: GPL-3.0-or-later
// Encoders and parsers of the ultrasonic nodes' frames (little-endian, like CANopen).
#include "hal/linux/can/sonar_frames.hpp"

#include "hal/linux/can/cia402.hpp"
#include "hal/linux/can/frame_bytes.hpp"

namespace robuter::hal::can::sonar {

namespace {
using bytes::frame;
using bytes::get16;
using bytes::put16;
}  // namespace

can_frame fire(std::uint8_t node, std::uint8_t mask, std::uint16_t timeout_ms, std::uint16_t sound_speed_m_s) {
  can_frame f = frame(kFire + node, 5);
  f.data[0] = mask;
  put16(&f.data[1], timeout_ms);
  put16(&f.data[3], sound_speed_m_s);
  return f;
}

can_frame ranges(std::uint8_t node, const std::array<std::uint16_t, 4>& mm) {
  can_frame f = frame(kRanges + node, 8);
  for (int i = 0; i < 4; ++i) put16(&f.data[2 * i], mm[i]);
  return f;
}

can_frame status(std::uint8_t node, std::uint8_t faulty_mask, std::uint8_t flags) {
  can_frame f = frame(kStatus + node, 2);
  f.data[0] = faulty_mask;
  f.data[1] = flags;
  return f;
}

bool parse_fire(const can_frame& f, FireRequest& out) {
  if (cia402::node_of(f, kFire) == 0 || f.len < 5) return false;
  out.mask = f.data[0];
  out.timeout_ms = get16(f.data + 1);
  out.sound_speed_m_s = get16(f.data + 3);
  return true;
}

bool parse_ranges(const can_frame& f, std::array<std::uint16_t, 4>& mm) {
  if (cia402::node_of(f, kRanges) == 0 || f.len < 8) return false;
  for (int i = 0; i < 4; ++i) mm[i] = get16(f.data + 2 * i);
  return true;
}

bool parse_status(const can_frame& f, std::uint8_t& faulty_mask, std::uint8_t& flags) {
  if (cia402::node_of(f, kStatus) == 0 || f.len < 2) return false;
  faulty_mask = f.data[0];
  flags = f.data[1];
  return true;
}

}  // namespace robuter::hal::can::sonar
