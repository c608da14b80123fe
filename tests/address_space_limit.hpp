#pragma once
// A process that may start no more threads, for death tests of the code that starts them: its address space capped
// (setrlimit RLIMIT_AS) a little above what it maps now, so that a thread's stack (megabytes) no longer fits. The
// per-user limit of processes (`ulimit -u`, as on shared clusters) would say the same, but does not bind root, and
// these tests run as root on CI. Call only in a death test's child: the cap is for the rest of the process's life.
// (Not under AddressSanitizer, which reserves terabytes of address space: see address_sanitizer.hpp.)
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>
#include <thread>

#include "address_sanitizer.hpp"
#include "scoped_environment.hpp"

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

// Expects `same_as_threaded()` to hold in a death test's child that can start no thread (its address space capped
// 4 MiB above what it maps, less than a thread's stack; glibc's stack cache off, set here before the child starts).
// The child exits 2 where a thread could still start, so a cap that did not bite fails the test rather than passing
// it. Call it last in a test: the child runs the test again up to here, the threaded answer included. Skips under
// AddressSanitizer.
template <typename Check>
void expect_where_no_thread_can_start(Check same_as_threaded) {
  if (address_sanitizer) GTEST_SKIP() << "ASan reserves terabytes of address space: no limit on it can be set";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const ScopedEnvironment no_stack_cache("GLIBC_TUNABLES", without_thread_stack_cache());
  EXPECT_EXIT(
      {
        limit_address_space(4u << 20);
        const bool same = same_as_threaded();
        std::_Exit(a_thread_can_start() ? 2 : same ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace heliostand::testing
