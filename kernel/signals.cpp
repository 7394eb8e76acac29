// SPDX-License-Identifier: GPL-3.0-or-later
// Signal handlers: stop flags, user-signal bits, and the async-signal-safe fatal path.
#include "kernel/signals.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

namespace robuter::signals {

namespace {
volatile std::sig_atomic_t g_stop_signal = 0;  // the signal that asked for a stop
std::atomic<int> g_user_signals{0};             // bit 0 SIGUSR1, bit 1 SIGUSR2

struct Hook {
  FatalHook fn = nullptr;      // the emergency action
  void* ctx = nullptr;         // its object
  const char* what = nullptr;  // written after it ran
};
std::array<Hook, 4> g_hooks{};                   // filled at start-up only
volatile std::sig_atomic_t g_fatal_entered = 0;  // the hooks run once
alignas(16) char g_alt_stack[64 * 1024];         // the handler's stack (a stack overflow is a SIGSEGV too)

void say(const char* s) { (void)!::write(STDERR_FILENO, s, std::strlen(s)); }

int run_hooks(const char* signame) {
  int ran = 0;
  for (const Hook& h : g_hooks) {
    if (h.fn == nullptr) continue;
    h.fn(h.ctx);
    ++ran;
    say("robuterd: fatal signal ");
    say(signame);
    say(": ");
    say(h.what);
    say("\n");
  }
  return ran;
}

extern "C" void on_stop(int sig) { g_stop_signal = sig; }

extern "C" void on_user(int sig) { g_user_signals.fetch_or(sig == SIGUSR1 ? 1 : 2); }

// SA_RESETHAND | SA_NODEFER: the disposition is the default again, so the raise() at the end
// kills the process at once with the signal's own status (and core).
extern "C" void on_fatal(int sig) {
  if (!g_fatal_entered) {
    g_fatal_entered = 1;
    if (run_hooks(name(sig)) == 0) {
      say("robuterd: fatal signal ");
      say(name(sig));
      say(": no drive to stop\n");
    }
  }
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void set(int sig, void (*fn)(int), int flags) {
  struct sigaction sa {};
  sa.sa_handler = fn;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = flags;
  sigaction(sig, &sa, nullptr);
}
}  // namespace

void install() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) set(sig, on_stop, 0);
  for (int sig : {SIGUSR1, SIGUSR2}) set(sig, on_user, 0);
  ::signal(SIGPIPE, SIG_IGN);
  stack_t st{};
  st.ss_sp = g_alt_stack;
  st.ss_size = sizeof g_alt_stack;
  sigaltstack(&st, nullptr);
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) set(sig, on_fatal, SA_RESETHAND | SA_NODEFER | SA_ONSTACK);
}

int stop_signal() { return g_stop_signal; }

int take_user_signals() { return g_user_signals.load(std::memory_order_relaxed) ? g_user_signals.exchange(0) : 0; }

const char* name(int sig) {
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    case SIGQUIT: return "SIGQUIT";
    case SIGUSR1: return "SIGUSR1";
    case SIGUSR2: return "SIGUSR2";
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGABRT: return "SIGABRT";
    case SIGPIPE: return "SIGPIPE";
    default: return "signal";
  }
}

bool add_fatal_hook(FatalHook fn, void* ctx, const char* what) {
  for (Hook& h : g_hooks) {
    if (h.fn == nullptr) {
      h = Hook{fn, ctx, what};
      return true;
    }
  }
  return false;
}

void remove_fatal_hooks(void* ctx) {
  for (Hook& h : g_hooks)
    if (h.ctx == ctx) h = Hook{};
}

int run_fatal_hooks_for_test() { return run_hooks("(test)"); }

}  // namespace robuter::signals
