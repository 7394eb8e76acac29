// SPDX-License-Identifier: GPL-3.0-or-later
// robuterd's signal policy: clean stops, ignored signals, and the emergency stop on a fatal signal.
#pragma once

namespace robuter::signals {

// SIGINT, SIGTERM, SIGHUP (the terminal or ssh session that started robuterd went away) and
// SIGQUIT request a clean stop (motors stopped, servo off, links closed, exit 0); SIGUSR1 and
// SIGUSR2 are logged and otherwise ignored; SIGPIPE is ignored (a client that goes away is an
// error return). SIGSEGV, SIGBUS, SIGFPE, SIGILL and SIGABRT run the fatal hooks (below), write
// one line to stderr, then take their default action (core dump, status 128 + n). No SA_RESTART:
// a signal interrupts the kernel's idle wait.
void install();
// The signal that asked for a stop, or 0.
int stop_signal();
// User signals received since the last call: bit 0 SIGUSR1, bit 1 SIGUSR2.
int take_user_signals();
// A short name: "SIGHUP", "SIGSEGV", … ("signal" for others).
const char* name(int sig);

// An emergency hook run from the fatal-signal handler: it must be async-signal-safe (no
// allocation, no lock, no stdio: plain stores, write(), sendto()). `what` is static text written
// to stderr after it ran ("drive stopped: …").
using FatalHook = void (*)(void* ctx);
// Registers a hook at start-up; false when the table (4) is full.
bool add_fatal_hook(FatalHook fn, void* ctx, const char* what);
// Removes the hooks of `ctx` (its owner is going away).
void remove_fatal_hooks(void* ctx);
// Runs the hooks as the handler would (tests), returns how many ran.
int run_fatal_hooks_for_test();

}  // namespace robuter::signals
