// SPDX-License-Identifier: GPL-3.0-or-later
// Opt-in line checksums (XC1): CRC-16/CCITT-FALSE written as `*HHHH` at the end of a line.
#pragma once

#include <cstdint>
#include <string_view>

namespace robuter::protocol {

inline constexpr char kChecksumMark = '*';           // separates a line from its checksum
inline constexpr std::size_t kChecksumDigits = 4;    // hex digits after the mark

// CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF) of `bytes`.
std::uint16_t crc16(std::string_view bytes) noexcept;

// Splits `line` = body '*' HHHH and checks the CRC of body; on success sets `body`.
bool strip_checksum(std::string_view line, std::string_view& body) noexcept;

// Writes the 4 upper-case hex digits of `crc` to `out`.
void format_checksum(std::uint16_t crc, char (&out)[kChecksumDigits]) noexcept;

}  // namespace robuter::protocol
