// SPDX-License-Identifier: GPL-3.0-or-later
// Reply assembly and parsing for the pan-tilt unit; fixed buffers, no allocation.
#include "modules/ptu/ptu_replies.hpp"

#include <charconv>

namespace robuter::ptu {

bool ReplyAssembler::push(std::uint8_t b) {
  if (done_) {
    len_ = 0;
    bad_ = false;
    done_ = false;
  }
  if (b == '\r' || b == '\n') {
    if (len_ == 0 && !bad_) return false;  // the LF of CR LF, blank lines
    bad_done_ = bad_;
    done_ = true;
    return true;
  }
  if (b < 0x20 || b > 0x7e) bad_ = true;
  if (len_ < buf_.size()) buf_[len_++] = static_cast<char>(b);
  else bad_ = true;
  return false;
}

void ReplyAssembler::clear() {
  len_ = 0;
  bad_ = false;
  done_ = false;
}

// Why the last integer after '*': terse replies are "* <n>", verbose ones put words before the
// number and units after it ("* Target Pan speed is 1500 positions/sec").
Reply parse_reply(std::string_view line) {
  Reply r;
  const std::size_t star = line.find('*');
  const std::size_t bang = line.find('!');
  if (bang != std::string_view::npos && (star == std::string_view::npos || bang < star)) {
    r.kind = ReplyKind::refused;
    return r;
  }
  if (star == std::string_view::npos) return r;
  r.kind = ReplyKind::ok;
  std::string_view rest = line.substr(star + 1);
  std::size_t i = 0;
  while (i < rest.size()) {
    const bool sign = (rest[i] == '-' || rest[i] == '+') && i + 1 < rest.size() && rest[i + 1] >= '0' && rest[i + 1] <= '9';
    if (!sign && !(rest[i] >= '0' && rest[i] <= '9')) {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < rest.size() && rest[j] >= '0' && rest[j] <= '9') ++j;
    const char* first = rest.data() + i + (rest[i] == '+' ? 1 : 0);
    std::int32_t v = 0;
    const auto res = std::from_chars(first, rest.data() + j, v);
    if (res.ec == std::errc()) r.number = v;
    else r.kind = ReplyKind::garbage;  // a number too large for the unit
    i = j;
  }
  return r;
}

std::size_t format_command(char* out, std::size_t size, std::string_view text, std::optional<std::int32_t> n) {
  std::size_t len = 0;
  if (text.size() + 1 > size) return 0;
  for (char c : text) out[len++] = c;
  if (n) {
    const auto res = std::to_chars(out + len, out + size, *n);
    if (res.ec != std::errc()) return 0;
    len = static_cast<std::size_t>(res.ptr - out);
  }
  if (len >= size) return 0;
  out[len++] = '\r';
  return len;
}

}  // namespace robuter::ptu
