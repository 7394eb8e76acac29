// SPDX-License-Identifier: GPL-3.0-or-later
// Proves the per-line path never touches the heap, by counting global operator new calls.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <string>

#include "protocol/codec/decoder.hpp"
#include "protocol/codec/link_codec.hpp"
#include "protocol/testing/fake_robot_port.hpp"

#if !defined(ROBUTER_SANITIZE)
namespace {
std::atomic<long> g_allocations{0};  // operator new calls since start
}  // namespace

// GCC 12 flags free() inside a replaced operator delete as mismatched; it is the pairing here.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

// Counting replacements of the global allocation functions (this test executable only).
void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace robuter::protocol {
namespace {

// Every message, valid and invalid, with every session option on and off.
const std::string kTraffic =
    "BO\rBU\rBV\rBC\rBT\rBP\rBF\rBD\rAM 10 10\rAM 10\rASN\rASF\rAYPA6000\rAC 0,0,0\r"
    "AW 100 200 9000\rAX\rAp\rAg\rAG\rAT\rAd\rAf\rUT111111111111111111111111\rUT1011\r"
    "UD5\rUN\rUSN\rUSS\rUt33\rUu1\rUu0\rZz\r\r\n\nB\rXE\rXR\rXK\rXV\rXS10\rXS0\rXB1\rZz\r"
    "AM 1 x\rAM 99999999999 1\rXL2\rBC\rXL1\rBC\rXL0\rXC1\rBC\rXC0*D9E3\rXB0\r" +
    std::string(5000, 'a') + "\r" + std::string("B\0C\xFF\r", 5) + "AM 1\x18" "0\r";

TEST(NoAlloc, PerLinePathDoesNotAllocate) {
  testing::FakeRobotPort port;
  LinkCodec codec;
  std::size_t replies = 0;
  std::size_t bytes_out = 0;
  const auto* data = reinterpret_cast<const std::uint8_t*>(kTraffic.data());
  // Warm up once (lazy statics, if any), then count.
  codec.feed(std::span(data, kTraffic.size()), port, [&](std::string_view) { ++replies; });
  codec.reset();
  replies = 0;
  const long before = g_allocations.load();
  for (int round = 0; round < 10; ++round) {
    codec.feed(std::span(data, kTraffic.size()), port, [&](std::string_view r) {
      ++replies;
      bytes_out += r.size();
    });
    codec.session().stream_period = 10;
    port.now += 10;
    if (auto s = codec.poll_stream(port)) bytes_out += s->size();
    codec.reset();
  }
  const long after = g_allocations.load();
  EXPECT_EQ(after - before, 0);
  EXPECT_GT(replies, 500u);
  EXPECT_GT(bytes_out, 0u);
}

TEST(NoAlloc, DecoderDoesNotAllocate) {
  const long before = g_allocations.load();
  std::size_t ok = 0;
  for (const char* line : {"AM 10 10", "UT111111111111111111111111", "AY x y", "Zz", "ASN"}) {
    ok += decode(line).error == ErrorCode::none ? 1 : 0;
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_EQ(ok, 4u);
}

TEST(NoAlloc, CounterWorks) {
  const long before = g_allocations.load();
  auto* p = new std::string(100, 'x');
  delete p;
  EXPECT_GE(g_allocations.load() - before, 1);
}

}  // namespace
}  // namespace robuter::protocol

#else
TEST(NoAlloc, SkippedUnderSanitizers) { GTEST_SKIP() << "sanitizers replace operator new"; }
#endif
