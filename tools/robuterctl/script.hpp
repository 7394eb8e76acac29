// Conformance scripts: `> send`, `< expect`, and `!` directives, run against a live link.
#pragma once

#include <cstdio>
#include <string>

#include "tools/robuterctl/client.hpp"

namespace robuter::ctl {

// What running a script found.
struct ScriptResult {
  int checks = 0;     // expectations met
  int failures = 0;   // expectations not met (the script stops at the first)
};

// Runs the script file `path` over `client`, reporting to `out`.
ScriptResult run_script(Client& client, const std::string& path, std::FILE* out);

}  // namespace robuter::ctl
