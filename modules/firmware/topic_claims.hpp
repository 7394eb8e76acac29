// SPDX-License-Identifier: GPL-3.0-or-later
// The start-up check of the single writer: every blackboard topic claimed exactly once.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "modules/topics.hpp"

namespace robuter {

// Every topic claimed exactly once, except those named in `absent` (topics whose owner this
// firmware does not compose), which must not be claimed at all. The message names each topic
// that breaks the rule and how many times it was claimed.
std::optional<std::string> topic_claims_error(const Blackboard& bb, std::span<const std::string_view> absent = {});

}  // namespace robuter
