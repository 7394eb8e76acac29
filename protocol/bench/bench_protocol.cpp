// SPDX-License-Identifier: GPL-3.0-or-later
// Throughput of the protocol codec on a realistic command mix: decode only, framing + decode,
// and the whole link path (framing, decode, fake port, reply formatting).
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "protocol/codec/decoder.hpp"
#include "protocol/codec/line_assembler.hpp"
#include "protocol/codec/link_codec.hpp"
#include "protocol/testing/fake_robot_port.hpp"

namespace {

using namespace robuter::protocol;

// A client's traffic as a navigation program sends it: mostly speeds and posture/range polls,
// some configuration, a few mistakes. 20 lines.
constexpr std::array<std::string_view, 20> kMix = {
    "AM 10 10", "BO", "AM 12,8", "BV", "AM -5 5", "BO", "BU", "AM 0 0", "BC", "AM 15 15",
    "BO", "ASN", "UT111111111111111111111111", "BV", "AC 0,0,0", "AM 10", "UN", "Zz",
    "AM 20 18", "BP"};

// The mix as one CR-terminated byte stream.
std::string mix_bytes() {
  std::string s;
  for (std::string_view line : kMix) {
    s += line;
    s += '\r';
  }
  return s;
}

// decode() alone, one line at a time.
void BM_Decode(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    Decoded d = decode(kMix[i]);
    benchmark::DoNotOptimize(d);
    i = (i + 1) % kMix.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_Decode);

// Bytes → lines → decoded commands.
void BM_FrameAndDecode(benchmark::State& state) {
  const std::string bytes = mix_bytes();
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  LineAssembler assembler;
  for (auto _ : state) {
    assembler.feed(std::span(data, bytes.size()), [](const FrameEvent& e) {
      if (e.kind == FrameEvent::Kind::line) {
        Decoded d = decode(e.line);
        benchmark::DoNotOptimize(d);
      }
    });
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kMix.size()));
}
BENCHMARK(BM_FrameAndDecode);

// The whole per-line path with a fake port: what the serial module pays per line.
void BM_LinkCodec(benchmark::State& state) {
  const std::string bytes = mix_bytes();
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  testing::FakeRobotPort port;
  LinkCodec codec;
  std::size_t out = 0;
  for (auto _ : state) {
    codec.feed(std::span(data, bytes.size()), port, [&](std::string_view r) { out += r.size(); });
  }
  benchmark::DoNotOptimize(out);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kMix.size()));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}
BENCHMARK(BM_LinkCodec);

}  // namespace

BENCHMARK_MAIN();
