// SPDX-License-Identifier: GPL-3.0-or-later
// Time sources of the kernel: a real monotonic clock and a virtual clock that tests step.
#pragma once

#include <poll.h>

#include <cstdint>
#include <span>

namespace robuter {

using Nanos = std::int64_t;  // nanoseconds on the clock's own monotonic time line

constexpr Nanos kNanosPerMicro = 1'000;
constexpr Nanos kNanosPerMilli = 1'000'000;
constexpr Nanos kNanosPerSecond = 1'000'000'000;

// What the kernel asks of time: read it, and wait for a deadline or a readable descriptor.
class Clock {
 public:
  virtual ~Clock() = default;
  // Current time in ns; monotonic.
  virtual Nanos now() = 0;
  // Waits until `deadline` or until one of `fds` has an event; returns the number of
  // descriptors with events (revents set), 0 when the deadline was reached, -1 when a
  // signal interrupted the wait (the caller then checks its stop flag).
  virtual int wait_until(Nanos deadline, std::span<pollfd> fds) = 0;
};

// CLOCK_MONOTONIC with absolute deadlines, so the tick never drifts however long it runs.
class RealClock final : public Clock {
 public:
  RealClock();
  Nanos now() override;
  int wait_until(Nanos deadline, std::span<pollfd> fds) override;
};

// A clock that only moves when told: tests and the simulator step it as fast as they like.
// Waiting never sleeps: ready descriptors are reported at once, otherwise time jumps to the
// deadline.
class VirtualClock final : public Clock {
 public:
  explicit VirtualClock(Nanos start = 0) : now_(start) {}
  Nanos now() override { return now_; }
  int wait_until(Nanos deadline, std::span<pollfd> fds) override;
  // Moves time forward by `dt` ns (a process under test "takes" time this way).
  void advance(Nanos dt) { now_ += dt; }

 private:
  Nanos now_;  // current virtual time, ns
};

// Real time scaled by a factor (the simulator's `--speed N`): N simulated seconds per second.
class ScaledClock final : public Clock {
 public:
  explicit ScaledClock(double factor);
  Nanos now() override;
  int wait_until(Nanos deadline, std::span<pollfd> fds) override;

 private:
  RealClock real_;     // the underlying wall clock
  Nanos origin_;       // real time at construction, ns
  double factor_;      // simulated ns per real ns
};

}  // namespace robuter
