// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a file robuterd was given (configuration, world, map): a regular file of bounded size, or a reason.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace robuter {

inline constexpr std::size_t kMaxInputFileBytes = 1024 * 1024;  // largest file robuterd reads, bytes (1 MB)

// Reads all of `path` into `out`. Refuses, with the reason as one phrase ("is a folder", "is not
// a regular file (a character device)", "is larger than 1 MB (2147483648 bytes)", "cannot open:
// No such file or directory"), anything but a regular file of at most `max_bytes` — so a folder,
// /dev/zero or a FIFO never hangs or fills memory at start-up.
std::optional<std::string> read_input_file(const std::string& path, std::string& out,
                                           std::size_t max_bytes = kMaxInputFileBytes);

}  // namespace robuter
