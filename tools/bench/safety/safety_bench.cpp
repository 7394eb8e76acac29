// Reaction-time bench: range read to zero speed at the drive, seeded trials on the simulated firmware.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/safety_sim/reaction.hpp"

using robuter::test::safety_sim::percentile;
using robuter::test::safety_sim::random_trial;
using robuter::test::safety_sim::ReactionResult;
using robuter::test::safety_sim::ReactionTrial;
using robuter::test::safety_sim::run_trial;

namespace {

constexpr double kTickMs = 10.0;  // the kernel's default tick

// Prints min / p50 / p99 / max of a sample in ticks and ms.
void print_distribution(const char* what, std::vector<std::int64_t> v) {
  std::sort(v.begin(), v.end());
  if (v.empty()) {
    std::printf("  %-40s no samples\n", what);
    return;
  }
  const auto p50 = percentile(v, 0.50), p99 = percentile(v, 0.99);
  std::printf("  %-40s n=%zu  min %lld  p50 %lld  p99 %lld  max %lld ticks  (%.0f / %.0f / %.0f / %.0f ms)\n", what,
              v.size(), static_cast<long long>(v.front()), static_cast<long long>(p50), static_cast<long long>(p99),
              static_cast<long long>(v.back()), static_cast<double>(v.front()) * kTickMs,
              static_cast<double>(p50) * kTickMs, static_cast<double>(p99) * kTickMs,
              static_cast<double>(v.back()) * kTickMs);
}

}  // namespace

int main(int argc, char** argv) {
  const int trials = argc > 1 ? std::max(2, std::atoi(argv[1])) : 200;
  std::vector<std::int64_t> reaction, detection, reaction_by_kind[2];
  std::vector<double> clearance;
  int not_tripped = 0, not_measured = 0, contacts = 0, failed = 0;
  for (int i = 0; i < trials; ++i) {
    const bool teleport = i % 2 == 1;  // half approach, half appearing obstacles
    const ReactionTrial t = random_trial(static_cast<std::uint64_t>(i / 2 + 1), teleport);
    const ReactionResult r = run_trial(t);
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
    reaction.push_back(r.reaction_ticks());
    reaction_by_kind[teleport ? 1 : 0].push_back(r.reaction_ticks());
    detection.push_back(r.detection_ticks());
    clearance.push_back(r.clearance_at_rest_mm);
  }
  std::printf("safety reaction: %d seeded trials (speeds 10-80 cm/s, forward and backward, boxes 0.4-1.0 m at ±15°;\n"
              "half approached from 0.2-3 m beyond the safety distance, half appearing inside it)\n",
              trials);
  print_distribution("range read -> zero speed at the drive", reaction);
  print_distribution("  approaching", reaction_by_kind[0]);
  print_distribution("  appearing", reaction_by_kind[1]);
  print_distribution("body within the limit -> range read", detection);
  if (!clearance.empty()) {
    std::sort(clearance.begin(), clearance.end());
    std::printf("  clearance at rest: min %.0f mm, median %.0f mm, max %.0f mm\n", clearance.front(),
                clearance[clearance.size() / 2], clearance.back());
  }
  std::printf("  not tripped %d, unmeasured %d, contacts %d, failed to run %d\n", not_tripped, not_measured, contacts,
              failed);
  const bool met = !reaction.empty() && *std::max_element(reaction.begin(), reaction.end()) <= 1;
  std::printf("target: zero speed at the drive within 1 tick (10 ms) of the read: %s\n", met ? "met" : "NOT met");
  return met && failed == 0 && not_measured == 0 && not_tripped == 0 ? 0 : 1;
}
