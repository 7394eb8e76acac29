// SPDX-License-Identifier: GPL-3.0-or-later
// A fixed byte ring holding a link's replies until the client reads them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace robuter {

template <std::size_t N>
class OutputRing {
 public:
  std::size_t free() const { return N - size_; }
  std::size_t size() const { return size_; }
  // Appends `text` whole, or nothing when it does not fit; true when appended.
  bool push(std::string_view text) {
    if (text.size() > free()) return false;
    for (char c : text) {
      buf_[(head_ + size_) % N] = static_cast<std::uint8_t>(c);
      ++size_;
    }
    return true;
  }
  // The longest contiguous run of queued bytes, oldest first.
  std::span<const std::uint8_t> front() const {
    const std::size_t run = head_ + size_ <= N ? size_ : N - head_;
    return {buf_.data() + head_, run};
  }
  // Drops `n` bytes from the front (they were written out).
  void pop(std::size_t n) {
    head_ = (head_ + n) % N;
    size_ -= n;
  }
  void clear() { head_ = size_ = 0; }

 private:
  std::array<std::uint8_t, N> buf_{};  // the bytes
  std::size_t head_ = 0;               // index of the oldest byte
  std::size_t size_ = 0;               // bytes queued
};

}  // namespace robuter
