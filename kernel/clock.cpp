// SPDX-License-Identifier: GPL-3.0-or-later
// Real, virtual and scaled clocks behind the kernel's Clock interface.
#include "kernel/clock.hpp"

#include <sys/prctl.h>
#include <time.h>

#include <cerrno>

namespace robuter {

namespace {

// Reads CLOCK_MONOTONIC as ns.
Nanos monotonic_now() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return Nanos{ts.tv_sec} * kNanosPerSecond + ts.tv_nsec;
}

// Splits a non-negative ns count into a timespec. time_t and long are 32 bits on armhf (Debian 12):
// the seconds of CLOCK_MONOTONIC (time since boot) or of a wait fit for 68 years, and the
// nanoseconds, below 10^9, always fit, so the narrowing is exact.
timespec to_timespec(Nanos ns) {
  timespec ts{};
  ts.tv_sec = static_cast<decltype(ts.tv_sec)>(ns / kNanosPerSecond);
  ts.tv_nsec = static_cast<decltype(ts.tv_nsec)>(ns % kNanosPerSecond);
  return ts;
}

// Polls `fds` without blocking; returns the number with events.
int poll_now(std::span<pollfd> fds) {
  if (fds.empty()) return 0;
  const int n = ::poll(fds.data(), fds.size(), 0);
  return n < 0 ? (errno == EINTR ? -1 : 0) : n;
}

}  // namespace

RealClock::RealClock() {
  // The default 50 µs timer slack would show as tick lateness; ask for the finest.
  prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
}

Nanos RealClock::now() { return monotonic_now(); }

int RealClock::wait_until(Nanos deadline, std::span<pollfd> fds) {
  for (;;) {
    const Nanos left = deadline - monotonic_now();
    if (left <= 0) return poll_now(fds);
    if (fds.empty()) {
      const timespec abs = to_timespec(deadline);
      const int rc = clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &abs, nullptr);
      if (rc == EINTR) return -1;
      continue;
    }
    const timespec rel = to_timespec(left);
    const int n = ::ppoll(fds.data(), fds.size(), &rel, nullptr);
    if (n < 0) return errno == EINTR ? -1 : 0;
    if (n > 0) return n;
  }
}

int VirtualClock::wait_until(Nanos deadline, std::span<pollfd> fds) {
  const int n = poll_now(fds);
  if (n != 0) return n;
  if (deadline > now_) now_ = deadline;
  return 0;
}

ScaledClock::ScaledClock(double factor) : origin_(monotonic_now()), factor_(factor) {}

Nanos ScaledClock::now() {
  return static_cast<Nanos>(static_cast<double>(monotonic_now() - origin_) * factor_);
}

int ScaledClock::wait_until(Nanos deadline, std::span<pollfd> fds) {
  const Nanos real_deadline = origin_ + static_cast<Nanos>(static_cast<double>(deadline) / factor_);
  return real_.wait_until(real_deadline, fds);
}

}  // namespace robuter
