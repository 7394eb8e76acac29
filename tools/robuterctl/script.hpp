// SPDX-License-Identifier: GPL-3.0-or-later
// Conformance scripts: `> send`, `< expect`, and `!` directives, run against a live link.
#pragma once

#include <cstdio>
#include <string>

#include "tools/robuterctl/client.hpp"

namespace robuter::ctl {

// What running a script found.
struct ScriptResult {
  int checks = 0;         // expectations met
  int failures = 0;       // expectations not met (the script stops at the first unless keep_going)
  bool interrupted = false;  // Ctrl-C ended it
};

struct ScriptOptions {
  bool keep_going = false;  // go on after a failed expectation
};

// Runs the script file `path` over `client`, reporting to `out`. Status-stream lines (`@ …`) are
// skipped by an expectation that does not itself start with `@`: they are never replies.
ScriptResult run_script(Client& client, const std::string& path, std::FILE* out, const ScriptOptions& options = {});

// Leaves the robot stopped after a script: `AM 0 0` then `ASF` (never the stop byte, which would
// latch an emergency), with checksums when the script left them on. Returns what it did, for
// the report.
std::string leave_stopped(Client& client);

}  // namespace robuter::ctl
