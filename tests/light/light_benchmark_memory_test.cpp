// The light benchmark's memory estimate for a synthetic canopy (light/light_benchmark.hpp): 1 GiB + 2 KiB a ball,
// saturating rather than wrapping for a count no machine holds. `bench light` refuses a count above the usable
// memory with it (tests/cli/bench_memory_cli_test.cpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "light/light_benchmark.hpp"

namespace heliostand {
namespace {

constexpr std::uint64_t gib = 1024ull * 1024ull * 1024ull;

TEST(LightBenchmarkMemory, IsOneGibibytePlusTwoKibibytesABall) {
  EXPECT_EQ(synthetic_canopy_memory_bytes(0), gib);
  EXPECT_EQ(synthetic_canopy_memory_bytes(100000), gib + 100000ull * 2048ull);
  EXPECT_EQ(synthetic_canopy_memory_bytes(1000000), gib + 1000000ull * 2048ull);
}

TEST(LightBenchmarkMemory, SaturatesForACountNoMachineHolds) {
  constexpr auto largest = std::numeric_limits<std::uint64_t>::max();
  EXPECT_EQ(synthetic_canopy_memory_bytes(std::numeric_limits<std::size_t>::max()), largest);
  EXPECT_EQ(synthetic_canopy_memory_bytes(std::size_t{1} << 60), largest);  // 2^71 bytes
  EXPECT_LT(synthetic_canopy_memory_bytes(std::size_t{1} << 40), largest);
}

}  // namespace
}  // namespace heliostand
