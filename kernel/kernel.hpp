// SPDX-License-Identifier: GPL-3.0-or-later
// The cooperative periodic-process kernel: a validated table of processes run on a fixed tick.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <span>
#include <string>

#include "kernel/clock.hpp"
#include "kernel/process.hpp"
#include "kernel/stats.hpp"

namespace robuter {

class Kernel {
 public:
  static constexpr std::size_t kMaxProcesses = 32;      // rows in the process table
  static constexpr std::size_t kMaxWatches = 16;        // descriptors that can wake a process
  static constexpr int kMaxEventRunsPerTick = 8;        // runs per tick of a descriptor that stays readable
  static constexpr int kMaxTriggersPerTick = 3;         // bound on triggered activations per tick (a
                                                        // producer's own run and its two triggered ones)
  static constexpr int kMinPriority = 0;                // priority range accepted in a row
  static constexpr int kMaxPriority = 99;

  Kernel(Clock& clock, Nanos tick_ns);
  Kernel(const Kernel&) = delete;
  Kernel& operator=(const Kernel&) = delete;

  // Checks a table: names unique and non-empty, process set, period ≥ 1, offset < period,
  // priority in range, budget > 0 and within the period. Returns the first problem found.
  std::optional<std::string> validate(std::span<const ProcessRow> rows) const;
  // Validates and adopts `rows`; returns the problem when the table is refused.
  std::optional<std::string> set_table(std::span<const ProcessRow> rows);

  // Calls every init in table order; on a failure closes those already started, in reverse.
  bool start();
  // Runs one tick: serves descriptor events until the tick's deadline, then the due processes.
  void step();
  // Calls every close in reverse table order (once).
  void shutdown();
  // start(), step() until a stop is requested, shutdown(); returns the exit status.
  int run();

  // Asks the loop to end after the current activation (any module may call it).
  void request_stop() { stop_ = true; }
  bool stop_requested() const;
  // Installs robuterd's signal policy (kernel/signals.hpp): SIGINT, SIGTERM, SIGHUP and SIGQUIT
  // request a stop of every kernel in the process.
  static void install_signal_handlers();

  // Wakes `p` whenever `fd` is readable, between ticks; false when the watch table is full.
  bool watch_fd(int fd, Process* p);
  // Stops watching `fd` (a link that closed).
  void unwatch_fd(int fd);
  // Asks for one more activation of `p` before the current tick ends (after the process now
  // running): a consumer reacts to new data in the same tick instead of at its next period.
  // At most kMaxTriggersPerTick triggered runs per process per tick, and as many again after
  // each descriptor activation between ticks; a trigger beyond the bound is not lost but runs
  // first thing in the next tick (or the next activation between ticks).
  void trigger(Process* p);

  std::uint64_t tick() const { return tick_; }          // the tick being run (or next)
  Nanos tick_ns() const { return tick_ns_; }            // tick length, ns
  Nanos now() { return clock_.now(); }                  // kernel clock, ns
  Clock& clock() { return clock_; }
  std::size_t process_count() const { return count_; }
  const ProcessRow& row(std::size_t i) const { return rows_[i]; }
  const ProcessStats& stats(std::size_t i) const { return stats_[i]; }
  const LatenessHistogram& lateness() const { return lateness_; }
  std::uint64_t skipped_ticks() const { return skipped_ticks_; }
  // True when no row is past a due tick without having run (the loop is alive and on time);
  // what the drive-side watchdog (CAN heartbeat) and systemd's WATCHDOG=1 are sent on.
  bool rows_on_time() const;
  // Slips of every row plus ticks jumped over, since start: a consumer that saw it change since
  // its last look knows a row ran late in between.
  std::uint64_t late_events() const { return late_events_; }
  // Index of the process named `name`, or nullopt.
  std::optional<std::size_t> find(const char* name) const;
  // Prints the per-process statistics and the lateness distribution (not for the periodic path).
  void print_stats(std::FILE* out) const;

 private:
  // Logs SIGUSR1/SIGUSR2 received since the last look.
  void log_user_signals();
  // Runs process i now and records its execution time.
  void activate(std::size_t i, bool from_event);
  // Runs the triggered processes, by priority, until none is pending.
  void run_triggered();
  // A new trigger budget (a tick, an activation between ticks): the runs counted so far are
  // forgotten and the triggers deferred beyond the last budget become pending.
  void new_trigger_budget();
  // Serves descriptor events until `deadline` (or a stop request).
  void serve_events_until(Nanos deadline);
  // The first tick strictly after `t` at which row i is due.
  std::uint64_t next_due_after(std::size_t i, std::uint64_t t) const;

  struct Watch {
    int fd = -1;                  // watched descriptor
    Process* process = nullptr;   // process run when it is readable
    int stuck_runs = 0;           // runs this tick after which the descriptor was still readable
  };

  Clock& clock_;
  Nanos tick_ns_;                                     // tick length, ns
  std::array<ProcessRow, kMaxProcesses> rows_{};      // the adopted table, in table order
  std::array<ProcessStats, kMaxProcesses> stats_{};   // statistics per row
  std::array<std::uint64_t, kMaxProcesses> next_due_{};  // next tick each row is due
  std::array<std::uint8_t, kMaxProcesses> order_{};   // row indices by descending priority
  std::array<std::uint8_t, kMaxProcesses> pending_{}; // triggered activations wanted this tick
  std::array<std::uint8_t, kMaxProcesses> triggered_{};  // triggered activations run this tick
  std::array<std::uint8_t, kMaxProcesses> deferred_{};   // triggers beyond the bound: run at the next budget
  bool any_pending_ = false;
  std::size_t count_ = 0;                             // rows in the table
  std::size_t started_ = 0;                           // rows whose init succeeded
  std::array<Watch, kMaxWatches> watches_{};
  std::array<pollfd, kMaxWatches> pollfds_{};
  std::array<std::uint8_t, kMaxWatches> poll_map_{};  // pollfds_ slot → watches_ index
  LatenessHistogram lateness_;
  Nanos t0_ = 0;                                      // time of tick 0, ns
  std::uint64_t tick_ = 0;
  std::uint64_t skipped_ticks_ = 0;                   // ticks jumped over when far behind
  std::uint64_t late_events_ = 0;                     // slips plus skipped ticks, count
  bool stop_ = false;
  bool closed_ = false;
};

}  // namespace robuter
