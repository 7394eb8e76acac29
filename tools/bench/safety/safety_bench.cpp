// SPDX-License-Identifier: GPL-3.0-or-later
// Safety bench: reaction and ring latency of seeded trials, and the stopped scan time, before/after the watch schedule.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/safety_sim/reaction.hpp"
#include "tests/safety_sim/scan_time.hpp"
#include "tests/safety_sim/support.hpp"

using robuter::Config;
using robuter::test::safety_sim::core_config;
using robuter::test::safety_sim::measure_scan_time;
using robuter::test::safety_sim::percentile;
using robuter::test::safety_sim::random_trial;
using robuter::test::safety_sim::ReactionResult;
using robuter::test::safety_sim::ReactionTrial;
using robuter::test::safety_sim::run_trial;
using robuter::test::safety_sim::ScanTime;
using robuter::test::safety_sim::seed_ring_config;

namespace {

constexpr double kTickMs = 10.0;  // the kernel's default tick

// Speed bands of the latency figures, cm/s (inclusive).
struct Band {
  int lo, hi;  // cm/s
};
constexpr Band kBands[] = {{10, 30}, {31, 55}, {56, 80}};

// Prints min / p50 / p99 / max of a sample in ticks and ms.
void print_distribution(const std::string& what, std::vector<std::int64_t> v) {
  std::sort(v.begin(), v.end());
  if (v.empty()) {
    std::printf("  %-44s no samples\n", what.c_str());
    return;
  }
  const auto p50 = percentile(v, 0.50), p99 = percentile(v, 0.99);
  std::printf("  %-44s n=%zu  min %lld  p50 %lld  p99 %lld  max %lld ticks  (%.0f / %.0f / %.0f / %.0f ms)\n",
              what.c_str(), v.size(), static_cast<long long>(v.front()), static_cast<long long>(p50),
              static_cast<long long>(p99), static_cast<long long>(v.back()), static_cast<double>(v.front()) * kTickMs,
              static_cast<double>(p50) * kTickMs, static_cast<double>(p99) * kTickMs,
              static_cast<double>(v.back()) * kTickMs);
}

// One configuration's trials; true when every trial ran, tripped, was measured and reacted
// within a tick of the read.
bool run_set(const char* name, const Config& cfg, int trials, bool verbose) {
  std::vector<std::int64_t> reaction, detection, ring, sighting, reaction_by_kind[2], by_band[std::size(kBands)],
      ring_by_band[std::size(kBands)], sighting_by_band[std::size(kBands)];
  std::vector<double> clearance;
  int not_tripped = 0, not_measured = 0, contacts = 0, failed = 0;
  for (int i = 0; i < trials; ++i) {
    const bool teleport = i % 2 == 1;  // half approach, half appearing obstacles
    const ReactionTrial t = random_trial(static_cast<std::uint64_t>(i / 2 + 1), teleport);
    const ReactionResult r = run_trial(t, cfg);
    if (!r.ran) {
      ++failed;
      std::fprintf(stderr, "trial %d: %s\n", i, r.error.c_str());
      continue;
    }
    if (!r.tripped) ++not_tripped;
    if (r.contact) ++contacts;
    if (r.read_tick == 0 || r.stop_tick == 0) {
      ++not_measured;
      continue;
    }
    if (verbose)
      std::printf("    %-8s seed %3d  AM %4d  dist %.2f m  lateral %+.2f  angle %+5.1f  size %.2f  sensor %2d %4d mm  "
                  "safety %4u mm  body->read %3lld  sensor->read %3lld\n",
                  teleport ? "teleport" : "approach", i / 2 + 1, t.left, t.distance, t.lateral, t.box_angle,
                  t.box_size, r.sensor, r.range_mm, r.safety_mm, static_cast<long long>(r.detection_ticks()),
                  static_cast<long long>(r.ring_ticks()));
    reaction.push_back(r.reaction_ticks());
    reaction_by_kind[teleport ? 1 : 0].push_back(r.reaction_ticks());
    detection.push_back(r.detection_ticks());
    ring.push_back(r.ring_ticks());
    if (r.seen_tick != 0) sighting.push_back(r.sighting_ticks());
    const int speed = std::abs(t.left);
    for (std::size_t b = 0; b < std::size(kBands); ++b) {
      if (speed < kBands[b].lo || speed > kBands[b].hi) continue;
      by_band[b].push_back(r.detection_ticks());
      ring_by_band[b].push_back(r.ring_ticks());
      if (r.seen_tick != 0) sighting_by_band[b].push_back(r.sighting_ticks());
    }
    clearance.push_back(r.clearance_at_rest_mm);
  }
  std::printf("%s:\n", name);
  print_distribution("range read -> zero speed at the drive", reaction);
  print_distribution("  approaching", reaction_by_kind[0]);
  print_distribution("  appearing", reaction_by_kind[1]);
  print_distribution("body within the limit -> a reading under it", detection);
  for (std::size_t b = 0; b < std::size(kBands); ++b)
    print_distribution(fmt::format("  {}-{} cm/s", kBands[b].lo, kBands[b].hi), by_band[b]);
  print_distribution("body within the limit -> a reading that sees it", sighting);
  for (std::size_t b = 0; b < std::size(kBands); ++b)
    print_distribution(fmt::format("  {}-{} cm/s", kBands[b].lo, kBands[b].hi), sighting_by_band[b]);
  print_distribution("a sensor could read it under -> it did", ring);
  for (std::size_t b = 0; b < std::size(kBands); ++b)
    print_distribution(fmt::format("  {}-{} cm/s", kBands[b].lo, kBands[b].hi), ring_by_band[b]);
  if (!clearance.empty()) {
    std::sort(clearance.begin(), clearance.end());
    std::printf("  clearance at rest: min %.0f mm, median %.0f mm, max %.0f mm\n", clearance.front(),
                clearance[clearance.size() / 2], clearance.back());
  }
  std::printf("  not tripped %d, unmeasured %d, contacts %d, failed to run %d\n", not_tripped, not_measured, contacts,
              failed);
  const bool met = !reaction.empty() && *std::max_element(reaction.begin(), reaction.end()) <= 1;
  std::printf("  target: zero speed at the drive within 1 tick (10 ms) of the read: %s\n", met ? "met" : "NOT met");
  return met && failed == 0 && not_measured == 0 && not_tripped == 0;
}

// USS and USN of a stopped robot in the default lab with UT all ones, UD3, Ut33.
void print_scan_time(const char* name, const Config& cfg) {
  const ScanTime s = measure_scan_time(cfg);
  if (!s.error.empty()) {
    std::printf("  %-8s full scan: %s\n", name, s.error.c_str());
    return;
  }
  std::printf("  %-8s USS %d ticks, USN %d ticks\n", name, s.scan_ticks, s.node_ticks);
}

}  // namespace

int main(int argc, char** argv) {
  const int trials = argc > 1 ? std::max(2, std::atoi(argv[1])) : 200;
  const char* v = std::getenv("ROBUTER_BENCH_SAFETY_VERBOSE");
  const bool verbose = v != nullptr && *v != '\0' && *v != '0';
  const Config before = seed_ring_config(core_config());
  const Config after = core_config();
  std::printf("safety reaction: %d seeded trials per ring schedule (speeds 10-80 cm/s, forward and backward, boxes\n"
              "0.4-1.0 m at ±15°; half approached from 0.2-3 m beyond the safety distance, half appearing inside it)\n",
              trials);
  const bool ok_before = run_set("before ([sonar] schedule = \"seed\", us row period 4)", before, trials, verbose);
  const bool ok_after = run_set("after (defaults: watch schedule, us row period 1)", after, trials, verbose);
  std::printf("full 24-sensor scan, stopped, default lab, UT all ones, UD3, Ut33 (target USS <= 35 ticks):\n");
  print_scan_time("before", before);
  print_scan_time("after", after);
  return ok_before && ok_after ? 0 : 1;
}
