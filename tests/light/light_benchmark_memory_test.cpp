// The light benchmark's memory estimate for a synthetic canopy (light/light_benchmark.hpp): 1 GiB + 2 KiB a ball,
// and twice the far-field table's cap above its default 512 MB, saturating rather than wrapping for a count no machine
// holds. `bench light` refuses a count or a cap above the usable memory with it (tests/cli/bench_memory_cli_test.cpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "light/light_benchmark.hpp"

namespace heliostand {
namespace {

constexpr std::uint64_t gib = 1024ull * 1024ull * 1024ull;
const LightParameters light_at_default_cap{};

LightParameters with_cap(double cap_mb, bool exact = false) {
  LightParameters p;
  p.far_field_table_mb = cap_mb;
  p.exact = exact;
  return p;
}

TEST(LightBenchmarkMemory, IsOneGibibytePlusTwoKibibytesABall) {
  EXPECT_EQ(synthetic_canopy_memory_bytes(0, light_at_default_cap), gib);
  EXPECT_EQ(synthetic_canopy_memory_bytes(100000, light_at_default_cap), gib + 100000ull * 2048ull);
  EXPECT_EQ(synthetic_canopy_memory_bytes(1000000, light_at_default_cap), gib + 1000000ull * 2048ull);
  EXPECT_EQ(synthetic_canopy_memory_formula(light_at_default_cap), "1 GiB + 2 KiB a ball");
}

// The OpenCL solver keeps the table in two layouts, each up to the cap; the fixed gibibyte holds them at the default.
TEST(LightBenchmarkMemory, ACapAboveTheDefaultCountsTwice) {
  EXPECT_EQ(synthetic_canopy_memory_bytes(100000, with_cap(8512)), gib + 100000ull * 2048ull + 16000000000ull);
  EXPECT_EQ(synthetic_canopy_memory_formula(with_cap(8512)),
            "1 GiB + 2 KiB a ball + twice the far-field table's cap above 512 MB");
  EXPECT_EQ(synthetic_canopy_memory_bytes(100000, with_cap(64)), gib + 100000ull * 2048ull) << "below: none";
  EXPECT_EQ(synthetic_canopy_memory_formula(with_cap(64)), "1 GiB + 2 KiB a ball");
  EXPECT_EQ(synthetic_canopy_memory_bytes(100000, with_cap(8512, true)), gib + 100000ull * 2048ull)
      << "the exact light has no far field";
}

TEST(LightBenchmarkMemory, SaturatesForACountNoMachineHolds) {
  constexpr auto largest = std::numeric_limits<std::uint64_t>::max();
  EXPECT_EQ(synthetic_canopy_memory_bytes(std::numeric_limits<std::size_t>::max(), light_at_default_cap), largest);
  EXPECT_EQ(synthetic_canopy_memory_bytes(std::size_t{1} << 60, light_at_default_cap), largest);  // 2^71 bytes
  EXPECT_LT(synthetic_canopy_memory_bytes(std::size_t{1} << 40, light_at_default_cap), largest);
}

}  // namespace
}  // namespace heliostand
