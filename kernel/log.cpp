// SPDX-License-Identifier: GPL-3.0-or-later
// The log ring (single producer: the kernel thread) and its drain thread.
#include "kernel/log.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <thread>


namespace robuter::log {

namespace {

struct Record {
  std::uint64_t tick;                      // kernel tick when written
  Level level;                             // severity
  std::uint8_t len;                        // bytes used in text
  char text[detail::kMessageBytes];        // message, not NUL-terminated
};

constexpr std::size_t kSlots = 256;        // ring capacity, records (power of two)

std::array<Record, kSlots> g_ring;                 // the records
std::atomic<std::uint64_t> g_head{0};              // next slot the producer writes
std::atomic<std::uint64_t> g_tail{0};              // next slot the consumer reads
std::atomic<std::uint64_t> g_dropped{0};
std::atomic<std::uint64_t> g_tick{0};
std::atomic<Level> g_level{Level::info};
std::FILE* g_sink = stderr;
std::mutex g_drain_mutex;                          // one drainer at a time (thread or flush)
std::thread g_thread;
std::atomic<bool> g_running{false};
bool g_journal = false;                            // the sink is systemd's journal: "<N>" priority prefixes

// syslog priorities (sd-daemon.h SD_ERR, SD_WARNING, SD_INFO, SD_DEBUG) for journald's stream parser.
const char* journal_prefix(Level l) {
  switch (l) {
    case Level::error: return "<3>";
    case Level::warn: return "<4>";
    case Level::info: return "<6>";
    case Level::debug: return "<7>";
    case Level::off: break;
  }
  return "<6>";
}

// systemd sets $JOURNAL_STREAM to "device:inode" of the stream it connected to stdout/stderr
// (systemd.exec(5)); the sink is the journal when its descriptor is that very stream.
bool is_journal(std::FILE* sink) {
  const char* js = std::getenv("JOURNAL_STREAM");
  struct stat st {};
  if (js == nullptr || sink == nullptr || ::fstat(fileno(sink), &st) != 0) return false;
  unsigned long long dev = 0, ino = 0;
  if (std::sscanf(js, "%llu:%llu", &dev, &ino) != 2) return false;
  return static_cast<unsigned long long>(st.st_dev) == dev && static_cast<unsigned long long>(st.st_ino) == ino;
}

// Writes every queued record to the sink (outside the periodic path).
void drain() {
  std::lock_guard<std::mutex> lock(g_drain_mutex);
  auto tail = g_tail.load(std::memory_order_relaxed);
  const auto head = g_head.load(std::memory_order_acquire);
  for (; tail != head; ++tail) {
    const Record& r = g_ring[tail % kSlots];
    const std::string_view level_word = word(r.level);
    std::fprintf(g_sink, "%s[%8llu] %-5.*s %.*s\n", g_journal ? journal_prefix(r.level) : "",
                 static_cast<unsigned long long>(r.tick), static_cast<int>(level_word.size()), level_word.data(),
                 static_cast<int>(r.len), r.text);
  }
  g_tail.store(tail, std::memory_order_release);
  std::fflush(g_sink);
  const auto lost = g_dropped.exchange(0);
  if (lost) std::fprintf(g_sink, "[log] %llu records dropped (ring full)\n", static_cast<unsigned long long>(lost));
}

}  // namespace


void set_level(Level l) { g_level.store(l, std::memory_order_relaxed); }
Level level() { return g_level.load(std::memory_order_relaxed); }
void set_tick(std::uint64_t tick) { g_tick.store(tick, std::memory_order_relaxed); }
std::uint64_t dropped() { return g_dropped.load(); }

void detail::push(Level l, const char* text, std::size_t len) {
  const auto head = g_head.load(std::memory_order_relaxed);
  if (head - g_tail.load(std::memory_order_acquire) >= kSlots) {
    g_dropped.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  Record& r = g_ring[head % kSlots];
  r.tick = g_tick.load(std::memory_order_relaxed);
  r.level = l;
  r.len = static_cast<std::uint8_t>(len);
  std::memcpy(r.text, text, len);
  g_head.store(head + 1, std::memory_order_release);
}

void start(std::FILE* sink) {
  if (g_running.exchange(true)) return;
  g_sink = sink;
  g_journal = is_journal(sink);
  g_thread = std::thread([] {
    while (g_running.load()) {
      drain();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
}

void stop() {
  if (g_running.exchange(false)) g_thread.join();
  drain();
}

void flush() { drain(); }

}  // namespace robuter::log
