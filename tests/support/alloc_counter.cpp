// SPDX-License-Identifier: GPL-3.0-or-later
// Interposes malloc and friends (glibc allows it) to count the calling thread's allocations.
// Linked only into non-sanitized test programs: the sanitizers replace malloc themselves.
#include "tests/support/alloc_counter.hpp"

#include <cstddef>
#include <cstdlib>

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);
}

namespace {
thread_local bool t_armed = false;          // counting on this thread
thread_local std::uint64_t t_count = 0;     // allocations counted on this thread
// ROBUTER_ALLOC_TRAP=1 aborts at the first counted allocation, so a debugger shows who made it.
inline void note() {
  if (!t_armed) return;
  ++t_count;
  static const bool trap = [] {
    const char* v = std::getenv("ROBUTER_ALLOC_TRAP");
    return v && v[0] == '1';
  }();
  if (trap) __builtin_trap();
}
}  // namespace

extern "C" {
void* malloc(std::size_t n) {
  note();
  return __libc_malloc(n);
}
void* calloc(std::size_t a, std::size_t b) {
  note();
  return __libc_calloc(a, b);
}
void* realloc(void* p, std::size_t n) {
  note();
  return __libc_realloc(p, n);
}
void* memalign(std::size_t al, std::size_t n) {
  note();
  return __libc_memalign(al, n);
}
void* aligned_alloc(std::size_t al, std::size_t n) {
  note();
  return __libc_memalign(al, n);
}
int posix_memalign(void** out, std::size_t al, std::size_t n) {
  note();
  *out = __libc_memalign(al, n);
  return *out ? 0 : 12;
}
void free(void* p) { __libc_free(p); }
}

namespace robuter::test {
AllocCounter::AllocCounter() {
  t_count = 0;
  t_armed = true;
}
AllocCounter::~AllocCounter() { t_armed = false; }
std::uint64_t AllocCounter::count() const { return t_count; }
}  // namespace robuter::test
