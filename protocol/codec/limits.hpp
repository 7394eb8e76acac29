// SPDX-License-Identifier: GPL-3.0-or-later
// Fixed sizes of the Robuter text protocol: line length, sensor and sector counts, buffers.
#pragma once

#include <cstddef>
#include <cstdint>

#include "robot/ring_wiring.hpp"

namespace robuter::protocol {

inline constexpr std::size_t kMaxLineLength = 200;   // bytes before the terminator (seed MAX_LENGTH)
inline constexpr std::size_t kSensorCount = robot::kRingSensors;  // ultrasonic ring sensors
inline constexpr std::size_t kSectorCount = 72;      // pan-tilt sectors of 5 degrees
inline constexpr std::size_t kMaxIntParams = 3;      // most integers any message takes (AC, AW)
inline constexpr std::size_t kReplyCapacity = 2048;  // bytes of one reply line, tail included
                                                     // (XM's 41 x 41 map window needs ~1.8 kB)
inline constexpr std::size_t kMaxKernelProcesses = 16;  // processes listed by an XK reply
inline constexpr int kMapWindowSide = 41;            // cells per side of XM's map window
inline constexpr std::size_t kMaxTokenLength = 24;   // bytes of one port-supplied word in a reply
inline constexpr std::uint8_t kStopByte = 0x18;      // CAN: immediate stop, out of band
inline constexpr int kProtocolVersion = 1;           // reported by XV; 1 = seed + X extensions
inline constexpr std::uint32_t kMinStreamPeriod = 10;     // ticks (100 ms) between XS lines, at least
inline constexpr std::uint32_t kMaxStreamPeriod = 60000;  // ticks (10 min) between XS lines, at most

// A heading on the link, 0.01 degree, is in (-18000, 18000]: the one rule AC, AW, XG and XA's
// poses are admitted by (and a saved map pose is read by).
constexpr bool heading_in_range(std::int32_t theta) { return theta > -18000 && theta <= 18000; }

}  // namespace robuter::protocol
