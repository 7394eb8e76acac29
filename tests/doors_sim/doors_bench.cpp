// SPDX-License-Identifier: GPL-3.0-or-later
// robuter_doors_bench: N seeded starts per world through AG + Ad on the simulated firmware;
// success rate, crossing times, and the reason of every failure (tools/bench/60-doors.sh);
// ROBUTER_EMERGENCY_RULE=seed|envelope picks the obstacle rule.
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "tools/robuter-doors-run/crossing_run.hpp"

int main(int argc, char** argv) {
  using namespace robuter::test;
  const int starts = argc > 1 ? std::atoi(argv[1]) : 100;
  // "noise": the stress sonar model and odometry noise; "realistic": the realistic one and odometry noise.
  const std::string model = argc > 2 ? argv[2] : "";
  const bool noise = model == "noise" || model == "realistic";
  std::vector<std::string> worlds;
  for (int i = 3; i < argc; ++i) worlds.push_back(argv[i]);
  if (worlds.empty()) worlds = {ROBUTER_WORLDS_DIR "/door90.toml", ROBUTER_WORLDS_DIR "/door100.toml"};
  int status = 0;
  for (const std::string& w : worlds) {
    int ok = 0, contacts = 0, not_stopped = 0;
    double total = 0.0, cross = 0.0, worst = 0.0;
    std::map<std::string, int> failures;
    for (int seed = 1; seed <= starts; ++seed) {
      CrossingSetup s = seeded_start(w, static_cast<std::uint64_t>(seed));
      s.odometry_noise = noise;
      if (noise) s.sonar_model = model == "realistic" ? robuter::sim::SonarPreset::realistic : robuter::sim::SonarPreset::stress;
      // The obstacle rule to compare (docs/SAFETY.md §13): ROBUTER_EMERGENCY_RULE=seed|envelope.
      if (const char* rule = std::getenv("ROBUTER_EMERGENCY_RULE")) s.config.emergency.rule = rule;
      const CrossingResult r = run_crossing(s);
      const bool success = r.doors == "crossed" && !r.contact && r.body_through;
      contacts += r.contact ? 1 : 0;
      not_stopped += r.stopped ? 0 : 1;
      if (success) {
        ++ok;
        total += r.total_s;
        cross += r.crossing_s;
        worst = std::max(worst, r.total_s);
      } else {
        const std::string why = r.doors.empty() ? "gate " + r.gate : "doors " + r.doors;
        ++failures[why + (r.contact ? " (contact)" : "")];
        std::printf("  %s seed %d (dx %+.2f m, heading %+.1f°): %s%s%s\n", w.substr(w.rfind('/') + 1).c_str(), seed,
                    s.dx_m, s.dheading_deg, why.c_str(), r.contact ? ", contact" : "", r.stopped ? ", stopped" : ", NOT stopped");
      }
    }
    const std::string name = w.substr(w.rfind('/') + 1);
    std::printf("%s: %d/%d crossed (%.1f %%)%s; mean AG→crossed %.1f s (Ad→crossed %.1f s), longest %.1f s; contacts %d; "
                "runs not ending stopped %d\n",
                name.c_str(), ok, starts, 100.0 * ok / starts, noise ? (model == "realistic" ? " with the realistic sonar model and odometry noise" : " with sonar (stress) and odometry noise") : "",
                ok ? total / ok : 0.0, ok ? cross / ok : 0.0, worst, contacts, not_stopped);
    for (const auto& [why, n] : failures) std::printf("  failures: %d × %s\n", n, why.c_str());
    if (not_stopped > 0) status = 1;
  }
  return status;
}
