// SPDX-License-Identifier: GPL-3.0-or-later
// The start-up check of the single writer (topic_claims.hpp).
#include "modules/firmware/topic_claims.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace robuter {

std::optional<std::string> topic_claims_error(const Blackboard& bb, std::span<const std::string_view> absent) {
  std::string bad;
  bb.for_each_topic([&](std::string_view name, const auto& topic) {
    const int want = std::find(absent.begin(), absent.end(), name) == absent.end() ? 1 : 0;
    if (topic.claims() != want)
      bad += fmt::format("{}{} claimed {} times (want {})", bad.empty() ? "" : "; ", name, topic.claims(), want);
  });
  if (bad.empty()) return std::nullopt;
  return "blackboard: " + bad;
}

}  // namespace robuter
