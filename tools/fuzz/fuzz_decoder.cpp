// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: framing + decoding of arbitrary bytes (no port, no replies).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string_view>

#include "protocol/codec/decoder.hpp"
#include "protocol/codec/line_assembler.hpp"

using namespace robuter::protocol;

namespace {

// Invariants of one decode: an error, or a row whose id matches and a sane parameter count.
void check(std::string_view line) {
  const Decoded d = decode(line);
  if (d.error == ErrorCode::none) {
    if (d.row == nullptr || d.row->id != d.command.id) std::abort();
    if (d.command.int_count > kMaxIntParams) std::abort();
    if (d.row->schema.kind == SchemaKind::text &&
        (d.command.text.data() < line.data() ||
         d.command.text.data() + d.command.text.size() > line.data() + line.size())) {
      std::abort();
    }
  } else if (d.row != nullptr) {
    std::abort();
  }
}

}  // namespace

// The whole input through the assembler, each line decoded; the raw input decoded too.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  LineAssembler assembler;
  std::size_t lines = 0;
  assembler.feed(std::span(data, size), [&](const FrameEvent& e) {
    if (e.kind == FrameEvent::Kind::line) {
      if (e.line.size() > LineAssembler::MAX_LENGTH) std::abort();
      for (char c : e.line) {
        if (c < 0x20 || c > 0x7E) std::abort();
      }
      check(e.line);
      ++lines;
    }
  });
  if (assembler.pending() > LineAssembler::MAX_LENGTH + 1) std::abort();
  check(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
