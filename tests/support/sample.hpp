// SPDX-License-Identifier: GPL-3.0-or-later
// The sample sizes of the long simulated tests: one rule for the sanitizer tree's smaller samples.
#pragma once

namespace robuter::test {

// True in the ASan+UBSan tree (`make test-san`), where a simulated second costs about ten times
// more: there a long test runs a smaller sample of the same paths, looking for memory and UB
// errors; the figures (success rates, clearances, contacts) come from the normal tree's full
// sample and from `make bench`.
#if defined(ROBUTER_SANITIZE)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// `normal` in the normal tree, `sanitized` in the sanitizer tree.
constexpr int sample(int normal, int sanitized) { return kSanitized ? sanitized : normal; }

}  // namespace robuter::test
