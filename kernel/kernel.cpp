// SPDX-License-Identifier: GPL-3.0-or-later
// The kernel's table validation, lifecycle and tick loop.
#include "kernel/kernel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <csignal>
#include <cstring>

#include "kernel/log.hpp"
#include "kernel/signals.hpp"

namespace robuter {

Kernel::Kernel(Clock& clock, Nanos tick_ns) : clock_(clock), tick_ns_(tick_ns) {}

std::optional<std::string> Kernel::validate(std::span<const ProcessRow> rows) const {
  if (rows.empty()) return std::string("process table is empty");
  if (rows.size() > kMaxProcesses)
    return fmt::format("process table has {} rows; at most {}", rows.size(), kMaxProcesses);
  if (tick_ns_ <= 0) return std::string("tick length must be positive");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ProcessRow& r = rows[i];
    const std::string who = fmt::format("process row {} ('{}')", i, r.name ? r.name : "");
    if (r.name == nullptr || r.name[0] == '\0') return fmt::format("process row {}: empty name", i);
    for (std::size_t j = 0; j < i; ++j)
      if (std::strcmp(rows[j].name, r.name) == 0) return who + ": name used twice";
    if (r.process == nullptr) return who + ": no process";
    if (r.period < 1) return who + ": period must be at least 1 tick";
    if (r.offset >= r.period)
      return fmt::format("{}: offset {} must be less than the period {}", who, r.offset, r.period);
    if (r.priority < kMinPriority || r.priority > kMaxPriority)
      return fmt::format("{}: priority {} outside {}..{}", who, r.priority, kMinPriority, kMaxPriority);
    if (r.budget_us == 0) return who + ": time budget must be positive";
    const Nanos period_ns = static_cast<Nanos>(r.period) * tick_ns_;
    if (static_cast<Nanos>(r.budget_us) * kNanosPerMicro > period_ns)
      return fmt::format("{}: budget {} µs exceeds its period of {} µs", who, r.budget_us,
                         period_ns / kNanosPerMicro);
  }
  return std::nullopt;
}

std::optional<std::string> Kernel::set_table(std::span<const ProcessRow> rows) {
  if (auto err = validate(rows)) return err;
  count_ = rows.size();
  std::copy(rows.begin(), rows.end(), rows_.begin());
  for (std::size_t i = 0; i < count_; ++i) {
    order_[i] = static_cast<std::uint8_t>(i);
    stats_[i] = {};
    next_due_[i] = rows_[i].offset;
  }
  // Stable: rows of equal priority keep table order.
  std::stable_sort(order_.begin(), order_.begin() + static_cast<std::ptrdiff_t>(count_),
                   [this](std::uint8_t a, std::uint8_t b) { return rows_[a].priority > rows_[b].priority; });
  return std::nullopt;
}

bool Kernel::start() {
  for (started_ = 0; started_ < count_; ++started_) {
    if (!rows_[started_].process->init(*this)) {
      log::error("kernel: init of '{}' failed; stopping", rows_[started_].name);
      shutdown();
      return false;
    }
  }
  t0_ = clock_.now();
  tick_ = 0;
  closed_ = false;
  return true;
}

bool Kernel::stop_requested() const { return stop_ || signals::stop_signal() != 0; }

void Kernel::install_signal_handlers() { signals::install(); }

bool Kernel::watch_fd(int fd, Process* p) {
  for (auto& w : watches_) {
    if (w.fd == fd) { w.process = p; return true; }
  }
  for (auto& w : watches_) {
    if (w.fd < 0) { w = Watch{fd, p, 0}; return true; }
  }
  return false;
}

void Kernel::unwatch_fd(int fd) {
  for (auto& w : watches_)
    if (w.fd == fd) w = Watch{};
}

void Kernel::trigger(Process* p) {
  for (std::size_t i = 0; i < count_; ++i) {
    if (rows_[i].process != p) continue;
    if (triggered_[i] < kMaxTriggersPerTick) {
      pending_[i] = 1;
      any_pending_ = true;
    } else {
      deferred_[i] = 1;  // not lost: the next budget runs it first
    }
  }
}

void Kernel::new_trigger_budget() {
  triggered_.fill(0);
  for (std::size_t i = 0; i < count_; ++i) {
    if (!deferred_[i]) continue;
    deferred_[i] = 0;
    pending_[i] = 1;
    any_pending_ = true;
  }
}

void Kernel::run_triggered() {
  while (any_pending_ && !stop_requested()) {
    any_pending_ = false;
    for (std::size_t k = 0; k < count_; ++k) {
      const std::size_t i = order_[k];
      if (!pending_[i]) continue;
      pending_[i] = 0;
      ++triggered_[i];
      activate(i, true);
      break;  // re-scan from the highest priority: the run may have triggered others
    }
    for (std::size_t i = 0; i < count_; ++i) any_pending_ = any_pending_ || pending_[i];
  }
}

std::optional<std::size_t> Kernel::find(const char* name) const {
  for (std::size_t i = 0; i < count_; ++i)
    if (std::strcmp(rows_[i].name, name) == 0) return i;
  return std::nullopt;
}

void Kernel::activate(std::size_t i, bool from_event) {
  const Nanos begin = clock_.now();
  rows_[i].process->run(*this);
  const Nanos spent = clock_.now() - begin;
  stats_[i].record(spent, static_cast<Nanos>(rows_[i].budget_us) * kNanosPerMicro);
  if (from_event) ++stats_[i].event_activations;
}

void Kernel::serve_events_until(Nanos deadline) {
  for (auto& w : watches_) w.stuck_runs = 0;
  for (;;) {
    if (clock_.now() >= deadline) return;  // the tick is due: events never delay it
    std::size_t n = 0;
    for (std::size_t k = 0; k < watches_.size(); ++k) {
      const Watch& w = watches_[k];
      if (w.fd < 0 || w.stuck_runs >= kMaxEventRunsPerTick) continue;
      pollfds_[n] = pollfd{w.fd, POLLIN, 0};
      poll_map_[n] = static_cast<std::uint8_t>(k);
      ++n;
    }
    const int ready = clock_.wait_until(deadline, std::span<pollfd>(pollfds_.data(), n));
    if (stop_requested()) return;
    if (ready < 0) continue;   // interrupted by a signal that was not a stop
    if (ready == 0) return;    // the tick is due
    for (std::size_t s = 0; s < n; ++s) {
      if (pollfds_[s].revents == 0) continue;
      Watch& w = watches_[poll_map_[s]];
      // Each event activation has its own trigger budget: what it triggers runs now, however
      // many triggered runs the last tick used.
      new_trigger_budget();
      for (std::size_t i = 0; i < count_; ++i) {
        if (rows_[i].process == w.process) { activate(i, true); break; }
      }
      // A process that left its descriptor readable (it cannot take more now, or it does not
      // read at all) is not woken again by it more than a few times per tick.
      pollfd again{w.fd, POLLIN, 0};
      if (w.fd >= 0 && ::poll(&again, 1, 0) > 0) ++w.stuck_runs;
      else w.stuck_runs = 0;
      run_triggered();
      if (stop_requested()) return;
    }
  }
}

std::uint64_t Kernel::next_due_after(std::size_t i, std::uint64_t t) const {
  const std::uint64_t period = rows_[i].period, offset = rows_[i].offset;
  if (t < offset) return offset;
  return offset + ((t - offset) / period + 1) * period;
}

// SIGUSR1/SIGUSR2 are only logged (kernel/signals.hpp): once per tick, and at the stop.
void Kernel::log_user_signals() {
  if (const int user = signals::take_user_signals()) {
    if (user & 1) log::info("kernel: SIGUSR1 received: ignored");
    if (user & 2) log::info("kernel: SIGUSR2 received: ignored");
  }
}

void Kernel::step() {
  log_user_signals();
  Nanos deadline = t0_ + static_cast<Nanos>(tick_) * tick_ns_;
  serve_events_until(deadline);
  if (stop_requested()) return;
  const Nanos started = clock_.now();
  lateness_.record(started - deadline);
  // Far behind (a long stall): jump to the current tick rather than run a burst of old ones.
  const Nanos behind = (started - deadline) / tick_ns_;
  if (behind >= 1) {
    tick_ += static_cast<std::uint64_t>(behind);
    skipped_ticks_ += static_cast<std::uint64_t>(behind);
    late_events_ += static_cast<std::uint64_t>(behind);
  }
  log::set_tick(tick_);
  new_trigger_budget();
  for (std::size_t k = 0; k < count_; ++k) {
    run_triggered();
    const std::size_t i = order_[k];
    if (tick_ < next_due_[i]) continue;
    const Nanos due_at = t0_ + static_cast<Nanos>(next_due_[i]) * tick_ns_;
    const Nanos period_ns = static_cast<Nanos>(rows_[i].period) * tick_ns_;
    if (clock_.now() - due_at >= period_ns) {
      ++stats_[i].slips;
      ++late_events_;
    }
    activate(i, false);
    next_due_[i] = next_due_after(i, tick_);
    if (stop_requested()) break;
  }
  run_triggered();
  ++tick_;
}

bool Kernel::rows_on_time() const {
  for (std::size_t i = 0; i < count_; ++i)
    if (tick_ > next_due_[i]) return false;
  return true;
}

void Kernel::shutdown() {
  if (closed_) return;
  closed_ = true;
  for (std::size_t i = started_; i-- > 0;) rows_[i].process->close(*this);
  started_ = 0;
}

int Kernel::run() {
  if (!start()) return 1;
  while (!stop_requested()) step();
  log_user_signals();
  shutdown();
  return 0;
}

void Kernel::print_stats(std::FILE* out) const {
  fmt::print(out, "{:<12} {:>6} {:>6} {:>4} {:>9} {:>10} {:>8} {:>10} {:>10} {:>8} {:>6}\n", "process",
             "period", "offset", "prio", "budget_us", "runs", "events", "mean_us", "max_us", "overruns",
             "slips");
  for (std::size_t i = 0; i < count_; ++i) {
    const ProcessRow& r = rows_[i];
    const ProcessStats& s = stats_[i];
    fmt::print(out, "{:<12} {:>6} {:>6} {:>4} {:>9} {:>10} {:>8} {:>10.1f} {:>10.1f} {:>8} {:>6}\n", r.name,
               r.period, r.offset, r.priority, r.budget_us, s.activations, s.event_activations,
               static_cast<double>(s.mean_ns()) / 1e3, static_cast<double>(s.max_ns) / 1e3, s.overruns,
               s.slips);
  }
  fmt::print(out, "tick {} µs: {} ticks, lateness p50 {:.0f} µs, p99 {:.0f} µs, max {:.1f} µs, mean {:.1f} µs, "
                  "skipped {}\n",
             tick_ns_ / kNanosPerMicro, lateness_.count(), lateness_.quantile_us(0.5),
             lateness_.quantile_us(0.99), lateness_.max_us(), lateness_.mean_us(), skipped_ticks_);
}

}  // namespace robuter
