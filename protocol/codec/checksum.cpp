// SPDX-License-Identifier: GPL-3.0-or-later
// CRC-16/CCITT-FALSE for the opt-in line checksums, table-driven.
#include "protocol/codec/checksum.hpp"

#include <array>

namespace robuter::protocol {
namespace {

// The 256-entry table of the 0x1021 polynomial, built at compile time.
constexpr std::array<std::uint16_t, 256> make_table() noexcept {
  std::array<std::uint16_t, 256> table{};
  for (unsigned i = 0; i < 256; ++i) {
    unsigned crc = i << 8;
    for (int bit = 0; bit < 8; ++bit) crc = (crc & 0x8000U) ? ((crc << 1) ^ 0x1021U) : (crc << 1);
    table[i] = static_cast<std::uint16_t>(crc & 0xFFFFU);
  }
  return table;
}

constexpr std::array<std::uint16_t, 256> kCrcTable = make_table();

// Value of one hex digit (either case), or -1.
int hex_value(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

// Byte-at-a-time table CRC: lines are short, so this is plenty.
std::uint16_t crc16(std::string_view bytes) noexcept {
  unsigned crc = 0xFFFFU;
  for (char ch : bytes) {
    const unsigned byte = static_cast<unsigned char>(ch);
    crc = ((crc << 8) ^ kCrcTable[((crc >> 8) ^ byte) & 0xFFU]) & 0xFFFFU;
  }
  return static_cast<std::uint16_t>(crc);
}

// The mark must be exactly kChecksumDigits from the end, so `*` may appear in an AY body.
bool strip_checksum(std::string_view line, std::string_view& body) noexcept {
  if (line.size() < kChecksumDigits + 1) return false;
  const std::size_t mark = line.size() - kChecksumDigits - 1;
  if (line[mark] != kChecksumMark) return false;
  unsigned given = 0;
  for (std::size_t i = mark + 1; i < line.size(); ++i) {
    const int v = hex_value(line[i]);
    if (v < 0) return false;
    given = (given << 4) | static_cast<unsigned>(v);
  }
  const std::string_view candidate = line.substr(0, mark);
  if (crc16(candidate) != given) return false;
  body = candidate;
  return true;
}

// Upper-case hex, most significant digit first.
void format_checksum(std::uint16_t crc, char (&out)[kChecksumDigits]) noexcept {
  constexpr char kDigits[] = "0123456789ABCDEF";
  for (std::size_t i = 0; i < kChecksumDigits; ++i) {
    const unsigned shift = static_cast<unsigned>(4 * (kChecksumDigits - 1 - i));
    out[i] = kDigits[(static_cast<unsigned>(crc) >> shift) & 0xFU];
  }
}

}  // namespace robuter::protocol
