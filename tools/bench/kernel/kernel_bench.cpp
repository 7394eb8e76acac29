// SPDX-License-Identifier: GPL-3.0-or-later
// Cost of the kernel itself: one tick of a seed-sized table on a virtual clock, and topic traffic.
#include <benchmark/benchmark.h>

#include "kernel/blackboard.hpp"
#include "kernel/kernel.hpp"

namespace robuter {
namespace {

struct Nop : Process {
  void run(Kernel&) override { benchmark::ClobberMemory(); }
};

// One tick with the seed's four processes (plus a heartbeat), all work removed.
void BM_KernelTick(benchmark::State& state) {
  VirtualClock clock;
  Kernel k(clock, 10 * kNanosPerMilli);
  Nop a, b, c, d, e;
  const ProcessRow rows[] = {{"read_sensors", &a, 4, 2, 2, 1000}, {"serial", &b, 2, 0, 3, 1000},
                             {"execute", &c, 10, 2, 4, 1000},     {"emergency", &d, 10, 4, 5, 1000},
                             {"heartbeat", &e, 100, 0, 1, 1000}};
  if (k.set_table(rows) || !k.start()) state.SkipWithError("table refused");
  for (auto _ : state) k.step();
  state.SetItemsProcessed(state.iterations());
  k.shutdown();
}
BENCHMARK(BM_KernelTick);

struct Ranges {
  std::uint16_t mm[24];  // ranges, mm
};
struct Owner;
struct Owner {
  explicit Owner(Topic<Ranges, Owner>& t) : w(t.writer()) {}
  Writer<Ranges> w;
};

// Publish one 24-range struct and copy it out in a reader.
void BM_TopicPublishCopy(benchmark::State& state) {
  Topic<Ranges, Owner> t;
  Owner o(t);
  Reader<Ranges> r = t.reader();
  Ranges v{};
  for (auto _ : state) {
    v.mm[0]++;
    o.w.publish(v);
    if (r.updated()) benchmark::DoNotOptimize(r.copy());
  }
}
BENCHMARK(BM_TopicPublishCopy);

}  // namespace
}  // namespace robuter

BENCHMARK_MAIN();
