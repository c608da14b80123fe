// The operating system's part in the process (run/stand_benchmark.hpp), which `bench stand` reports as
// system_cpu_seconds and minor_page_faults. The kernel tells the system's CPU by where its clock ticks find the
// process, so a short run's few tens of ms there can be told as 0 s (BenchStandCli.ReportsTheRunAsJson's sub-second
// run was, once, in CI on 2026-12-03); here the process clears a gibibyte of fresh pages, some half a second of the
// system's work at this machine's 0.4-0.7 s a GiB, tens of ticks at any tick rate, which the account must show.
#include <gtest/gtest.h>
#include <sys/mman.h>

#include <cstddef>
#include <unistd.h>

#include "run/stand_benchmark.hpp"

namespace heliostand {
namespace {

// Maps `bytes` of fresh anonymous memory, writes one byte to each page (so that the system finds and clears it) and
// gives it back.
void touch_fresh_pages_once(std::size_t bytes) {
  void* memory = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(memory, MAP_FAILED);
  const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  auto* bytes_at = static_cast<volatile unsigned char*>(memory);
  for (std::size_t offset = 0; offset < bytes; offset += page) bytes_at[offset] = 1;
  ::munmap(memory, bytes);
}

TEST(SystemPart, ClearingFreshPagesShowsInTheSystemsCpuAndTheFaults) {
  const auto before = system_part_so_far();
  ASSERT_TRUE(before.has_value()) << "getrusage(RUSAGE_SELF) answers on Linux";
  constexpr std::size_t chunk = std::size_t{256} << 20;
  for (int round = 0; round < 4; ++round) touch_fresh_pages_once(chunk);
  const auto after = system_part_so_far();
  ASSERT_TRUE(after.has_value());
  EXPECT_GT(after->cpu_seconds, before->cpu_seconds) << "a gibibyte of fresh pages is the system's work";
  // Each fault brings in at most a huge page (2 MiB): at least 512 faults for the gibibyte.
  EXPECT_GE(after->minor_page_faults - before->minor_page_faults, long{4 * chunk / (std::size_t{2} << 20)});
}

}  // namespace
}  // namespace heliostand
