#pragma once
// A process that may start no more threads, for death tests of the code that starts them: its address space capped
// (setrlimit RLIMIT_AS) a little above what it maps now, so that a thread's stack (megabytes) no longer fits. The
// per-user limit of processes (`ulimit -u`, as on shared clusters) would say the same, but does not bind root, and
// these tests run as root on CI. Call only in a death test's child: the cap is for the rest of the process's life.
// (Not under AddressSanitizer, which reserves terabytes of address space: see address_sanitizer.hpp.)
#include <sys/resource.h>
#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>
#include <thread>

namespace heliostand::testing {

// Leaves this process `headroom` bytes of address space beyond what it maps now; exits with status 3 where the cap
// cannot be set.
inline void limit_address_space(std::size_t headroom) {
  std::size_t pages = 0;
  std::ifstream("/proc/self/statm") >> pages;
  const rlim_t limit = pages * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE)) + headroom;
  const rlimit both{limit, limit};
  if (pages == 0 || ::setrlimit(RLIMIT_AS, &both) != 0) std::_Exit(3);
}

// GLIBC_TUNABLES with glibc's cache of thread stacks turned off, for a death test whose child starts threads before
// the cap (to compute what the same work gives on threads): glibc keeps the stacks of threads that ended (up to
// 40 MiB) and gives them to new threads, which then start under any cap. Set it in the parent before EXPECT_EXIT
// (tests/scoped_environment.hpp); the child, started anew from this binary, reads it. Tunables already set are kept.
inline std::string without_thread_stack_cache() {
  const char* before = std::getenv("GLIBC_TUNABLES");
  return (before != nullptr && *before != '\0' ? std::string(before) + ":" : std::string()) +
         "glibc.pthread.stack_cache_size=0";
}

// Whether one more thread can start now: a test under the cap asks it to show that the cap bit.
inline bool a_thread_can_start() {
  try {
    std::thread([] {}).join();
    return true;
  } catch (const std::system_error&) {
    return false;
  }
}

}  // namespace heliostand::testing
