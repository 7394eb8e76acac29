// SPDX-License-Identifier: GPL-3.0-or-later
// Lateness histogram arithmetic.
#include "kernel/stats.hpp"

namespace robuter {

void LatenessHistogram::record(Nanos late_ns) {
  if (late_ns < 0) late_ns = 0;
  const Nanos us = late_ns / kNanosPerMicro;
  std::size_t bin;
  if (us < kFineBins) {
    bin = static_cast<std::size_t>(us);
  } else if (us < kFineBins + Nanos{kCoarseBins} * 100) {
    bin = static_cast<std::size_t>(kFineBins + (us - kFineBins) / 100);
  } else {
    bin = bins_.size() - 1;
  }
  ++bins_[bin];
  ++count_;
  total_ns_ += late_ns;
  if (late_ns > max_ns_) max_ns_ = late_ns;
}

double LatenessHistogram::quantile_us(double q) const {
  if (count_ == 0) return 0.0;
  const auto target = static_cast<std::uint64_t>(q * static_cast<double>(count_ - 1)) + 1;
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < bins_.size(); ++i) {
    seen += bins_[i];
    if (seen >= target) {
      if (i < kFineBins) return static_cast<double>(i + 1);
      if (i + 1 < bins_.size()) return static_cast<double>(kFineBins + (i - kFineBins + 1) * 100);
      return max_us();
    }
  }
  return max_us();
}

double LatenessHistogram::mean_us() const {
  return count_ ? static_cast<double>(total_ns_) / static_cast<double>(count_) / 1000.0 : 0.0;
}

}  // namespace robuter
