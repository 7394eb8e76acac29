// SPDX-License-Identifier: GPL-3.0-or-later
// parse_or_usage(): every program's one rule for parsing its command line and leaving on help, version or a usage error.
#pragma once

#include <optional>

namespace CLI {
class App;
}

namespace robuter::cli {

// The status a program returns on a command-line error (an unknown option, a missing or
// malformed value, a check that fails).
enum class UsageStatus {
  two,    // 2, the project's usage status: robuterd, robuterctl, robuter-sim, robuter-can-nodes, robuter-doors-run
  cli11,  // CLI11's own code of the error, 105..114 (e.g. 109 for an unknown option): robuter-plan,
          // whose 2 means "no path" and 1 a broken input file (docs/PLANNER.md)
};

// Parses argv into app. Returns the status to leave main() with when the program must stop now,
// or nothing when it goes on: --help (and -h, a subcommand's --help) prints the help on stdout,
// status 0; a version flag set with set_version_flag prints the version on stdout, status 0; a
// command-line error prints CLI11's message and "Run with --help for more information." on stderr,
// nothing on stdout, status per `on_error`.
// Why one function: the six programs' parse / catch / exit code was the same five lines, and
// their usage errors must stay alike (tests/cli/usage_test.sh checks all six).
std::optional<int> parse_or_usage(CLI::App& app, int argc, const char* const* argv, UsageStatus on_error = UsageStatus::two);

}  // namespace robuter::cli
