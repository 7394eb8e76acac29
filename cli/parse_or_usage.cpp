// SPDX-License-Identifier: GPL-3.0-or-later
// parse_or_usage(): CLI11's parse, and the exit status of help, version and usage errors.
#include "cli/parse_or_usage.hpp"

#include <CLI/CLI.hpp>

namespace robuter::cli {

std::optional<int> parse_or_usage(CLI::App& app, int argc, const char* const* argv, UsageStatus on_error) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // app.exit prints: help and version on stdout (code 0), the error and its hint on stderr.
    const int code = app.exit(e);
    if (code == 0 || on_error == UsageStatus::cli11) return code;
    return 2;
  }
  return std::nullopt;
}

}  // namespace robuter::cli
