// SPDX-License-Identifier: GPL-3.0-or-later
// Proves the periodic path allocates nothing: every malloc of the kernel thread is counted
// while 10,000 steady-state ticks run.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "modules/heartbeat/heartbeat.hpp"
#include "tests/support/alloc_counter.hpp"

namespace robuter {
namespace {

constexpr Nanos kTick = 10 * kNanosPerMilli;

// A link-like process: drains a pipe when woken and logs what it read.
class PipeReader : public Process {
 public:
  explicit PipeReader(int fd) : fd_(fd) {}
  void run(Kernel& k) override {
    char buf[256];
    const auto n = read(fd_, buf, sizeof buf);
    if (n > 0) log::debug("read {} bytes at tick {}", n, k.tick());
  }

 private:
  int fd_;
};

// Logs every activation, at a level that is recorded.
class Chatty : public Process {
 public:
  void run(Kernel& k) override { log::info("tick {} value {:.2f} {}", k.tick(), 1.5, "text"); }
};

TEST(NoAlloc, TenThousandSteadyStateTicksAllocateNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  log::set_level(log::Level::debug);
  VirtualClock clock;
  Kernel k(clock, kTick);
  Blackboard bb;
  HeartbeatModule heartbeat(bb);
  int p[2];
  ASSERT_EQ(pipe2(p, O_NONBLOCK), 0);
  PipeReader reader(p[0]);
  Chatty chatty;
  const ProcessRow rows[] = {{"heartbeat", &heartbeat, 100, 0, 1, 1000},
                             {"reader", &reader, 2, 0, 3, 1000},
                             {"chatty", &chatty, 10, 5, 2, 1000}};
  ASSERT_FALSE(k.set_table(rows));
  ASSERT_TRUE(k.start());
  ASSERT_TRUE(k.watch_fd(p[0], &reader));
  for (int i = 0; i < 10; ++i) k.step();  // warm-up

  test::AllocCounter counter;
  for (int i = 0; i < 10'000; ++i) {
    if (i % 7 == 0) {
      ASSERT_EQ(write(p[1], "BO\r", 3), 3);
    }
    k.step();
  }
  const auto allocations = counter.count();
  k.shutdown();
  close(p[0]);
  close(p[1]);
  EXPECT_EQ(allocations, 0u);
  EXPECT_GE(k.stats(1).event_activations, 1000u);
  EXPECT_EQ(bb.heartbeat.reader().peek().beats, 101u);
  log::flush();
#endif
}

TEST(NoAlloc, TheCounterSeesAnAllocation) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc";
#else
  test::AllocCounter counter;
  void* (*volatile do_malloc)(std::size_t) = std::malloc;  // opaque: not elided
  void* p = do_malloc(32);
  std::free(p);
  auto* q = new int(3);
  asm volatile("" : : "g"(q) : "memory");  // the allocation escapes
  delete q;
  EXPECT_EQ(counter.count(), 2u);
#endif
}

}  // namespace
}  // namespace robuter
