// SPDX-License-Identifier: GPL-3.0-or-later
// The in-process pipe: two fixed rings, no locks (one thread: the kernel's).
#include "hal/sitl/byte_pipe.hpp"

#include <algorithm>

namespace robuter::hal {

// One direction: a ring of fixed capacity.
struct ByteRing {
  std::vector<std::uint8_t> buf;  // storage, sized at start-up
  std::size_t first = 0;          // index of the oldest byte
  std::size_t size = 0;           // bytes held

  std::size_t push(std::span<const std::uint8_t> in) {
    const std::size_t n = std::min(in.size(), buf.size() - size);
    for (std::size_t i = 0; i < n; ++i) buf[(first + size + i) % buf.size()] = in[i];
    size += n;
    return n;
  }
  std::size_t pop(std::span<std::uint8_t> out) {
    const std::size_t n = std::min(out.size(), size);
    for (std::size_t i = 0; i < n; ++i) out[i] = buf[(first + i) % buf.size()];
    first = (first + n) % buf.size();
    size -= n;
    return n;
  }
  void clear() { first = size = 0; }
};

class BytePipeState {
 public:
  explicit BytePipeState(std::size_t capacity) {
    for (auto& r : rings) r.buf.assign(std::max<std::size_t>(capacity, 1), 0);
  }
  ByteRing rings[2];      // rings[s]: written by side s, read by side 1 − s
  bool hung_up = false;   // unplugged (tests)
};

PipeEnd::PipeEnd(std::shared_ptr<BytePipeState> state, int side, std::string name)
    : state_(std::move(state)), side_(side), name_(std::move(name)) {}

IoResult PipeEnd::read(std::span<std::uint8_t> out) {
  if (state_->hung_up) return {0, true};
  return {state_->rings[1 - side_].pop(out), false};
}

IoResult PipeEnd::write(std::span<const std::uint8_t> in) {
  if (state_->hung_up) return {0, true};
  return {state_->rings[side_].push(in), false};
}

bool PipeEnd::connected() const { return !state_->hung_up; }

const char* PipeEnd::loss_reason() const { return state_->hung_up ? "unplugged" : nullptr; }

void PipeEnd::unplug() {
  state_->hung_up = true;
  for (auto& r : state_->rings) r.clear();
}

void PipeEnd::plug_in() {
  state_->hung_up = false;
  for (auto& r : state_->rings) r.clear();
}

std::pair<std::unique_ptr<PipeEnd>, std::unique_ptr<PipeEnd>> make_byte_pipe(std::string first_name,
                                                                              std::string second_name,
                                                                              std::size_t capacity) {
  auto state = std::make_shared<BytePipeState>(capacity);
  auto a = std::make_unique<PipeEnd>(state, 0, std::move(first_name));
  auto b = std::make_unique<PipeEnd>(std::move(state), 1, std::move(second_name));
  return {std::move(a), std::move(b)};
}

}  // namespace robuter::hal
