// SPDX-License-Identifier: GPL-3.0-or-later
// Hand-off from the kernel's thread to a writer thread: one slot, never waited for; the drain loop.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <thread>

namespace robuter {

// One value handed from the kernel's thread (fill, publish: no allocation, no lock, no waiting)
// to another thread (take, release). If the taker still holds the last value, a new one is
// dropped and counted: the kernel never waits for a file. The value is sized at start-up
// through value().
template <class T>
class OneSlot {
 public:
  // Why: the allocation point (start-up, before any fill): the value's buffers.
  T& value() { return value_; }
  // Why: kernel side; the slot to fill, or null when it is taken (the value is dropped).
  T* try_fill() {
    int expected = kFree;
    if (state_.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) return &value_;
    dropped_.fetch_add(1, std::memory_order_relaxed);
    return nullptr;
  }
  // Why: kernel side; the slot filled by try_fill() is ready for the taker (or given back
  // unfilled: `filled` false).
  void publish(bool filled = true) {
    if (!filled) {
      state_.store(kFree, std::memory_order_release);
      return;
    }
    published_.fetch_add(1, std::memory_order_relaxed);
    state_.store(kReady, std::memory_order_release);
  }
  // Why: taker side; the value waiting, or null when none is.
  T* take() {
    int expected = kReady;
    if (state_.compare_exchange_strong(expected, kTaken, std::memory_order_acquire)) return &value_;
    return nullptr;
  }
  // Why: taker side; done with the value taken.
  void release() { state_.store(kFree, std::memory_order_release); }
  std::uint32_t published() const { return published_.load(std::memory_order_relaxed); }
  std::uint32_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  static constexpr int kFree = 0, kFilling = 1, kReady = 2, kTaken = 3;
  T value_;                                   // the one slot
  std::atomic<int> state_{kFree};             // who holds the slot
  std::atomic<std::uint32_t> published_{0};   // values handed over, count
  std::atomic<std::uint32_t> dropped_{0};     // values dropped (slot busy), count
};

// A writer's thread (robuterd): calls `drain` until it finds nothing, sleeps 10 ms, again, until
// stop(). Tests that step a virtual clock call the writer's drain between ticks instead.
class DrainThread {
 public:
  DrainThread() = default;
  ~DrainThread() { stop(); }
  DrainThread(const DrainThread&) = delete;
  DrainThread& operator=(const DrainThread&) = delete;
  // Why: starts the loop (no effect when running); `drain` returns true when it did some work.
  void start(std::function<bool()> drain) {
    if (thread_.joinable()) return;
    stop_ = false;
    thread_ = std::thread([this, drain = std::move(drain)] {
      while (!stop_.load()) {
        if (!drain()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    });
  }
  // Why: ends the loop and joins it (the caller drains what is left).
  void stop() {
    if (!thread_.joinable()) return;
    stop_ = true;
    thread_.join();
  }
  bool running() const { return thread_.joinable(); }

 private:
  std::thread thread_;             // the loop, or none
  std::atomic<bool> stop_{false};  // asks the loop to end
};

}  // namespace robuter
