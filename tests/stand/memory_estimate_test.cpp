// The up-front memory estimate (stand/memory_estimate.hpp): its formula, and a refusal that names the figures.
#include <gtest/gtest.h>

#include "core/input_error.hpp"
#include "scenario/scenario.hpp"
#include "stand/memory_estimate.hpp"

namespace heliostand {
namespace {

constexpr std::uint64_t mib = 1024ull * 1024ull;
constexpr std::uint64_t gib = 1024ull * mib;

Scenario tiny_scenario() {
  return load_scenario(std::filesystem::path(HELIOSTAND_SOURCE_DIR) / "stands/tiny/scenario.toml");
}

TEST(MemoryEstimate, IsOneGibibytePlusAPerTreeFigure) {
  const MemoryEstimate estimate = estimate_run_memory(tiny_scenario());
  EXPECT_EQ(estimate.trees, 8u);
  EXPECT_EQ(estimate.bytes, gib + 8 * mib * 7 / 4);  // 1 GiB + 8 × 1.75 MiB
}

TEST(MemoryEstimate, AStandBeyondTheMachineIsRefusedWithTheEstimate) {
  const Scenario scenario = tiny_scenario();
  const MemoryEstimate estimate = estimate_run_memory(scenario);
  EXPECT_NO_THROW(refuse_beyond_memory(scenario, estimate, 64 * gib));
  EXPECT_NO_THROW(refuse_beyond_memory(scenario, estimate, estimate.bytes));
  try {
    refuse_beyond_memory(scenario, estimate, gib);
    FAIL() << "an estimate above the usable memory must be refused";
  } catch (const InputError& error) {
    const std::string message = error.problems().at(0).format(error.field_kind());
    EXPECT_NE(message.find("key 'stand.survey': 8 trees need about 1.0 GiB (1 GiB + 1.75 MiB per tree, "
                           "docs/performance.md \"Memory\")"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("than the 1.0 GiB"), std::string::npos) << message;
  }
}

// A far-field table allowed more than its default 512 MB counts twice what it may add (the OpenCL solver's two
// layouts); the exact light has no table, and a smaller cap takes nothing off the fixed gibibyte.
TEST(MemoryEstimate, AFarFieldTableAllowedMoreThanItsDefaultCountsTwice) {
  Scenario scenario = tiny_scenario();
  const std::uint64_t stand = gib + 8 * mib * 7 / 4;
  scenario.light.far_field_table_mb = 3000;
  EXPECT_EQ(estimate_run_memory(scenario).far_field_table_bytes, 2 * 2'488'000'000ull);
  EXPECT_EQ(estimate_run_memory(scenario).bytes, stand + 2 * 2'488'000'000ull);
  scenario.light.exact = true;
  EXPECT_EQ(estimate_run_memory(scenario).bytes, stand);
  scenario.light.exact = false;
  scenario.light.far_field_table_mb = 100;
  EXPECT_EQ(estimate_run_memory(scenario).bytes, stand);
}

// A cap the machine cannot hold is refused under its own key; a stand too large even without it, under the survey's.
TEST(MemoryEstimate, ATableCapBeyondTheMachineIsRefusedUnderItsOwnKey) {
  Scenario scenario = tiny_scenario();
  scenario.light.far_field_table_mb = 1e6;  // the scenario's limit
  const MemoryEstimate estimate = estimate_run_memory(scenario);
  const auto refusal = [&](std::uint64_t usable) -> std::string {
    try {
      refuse_beyond_memory(scenario, estimate, usable);
    } catch (const InputError& error) {
      return error.problems().at(0).format(error.field_kind());
    }
    return "";
  };
  const std::string cap = refusal(24 * gib);
  EXPECT_NE(cap.find("key 'light.far_field_table_mb': a far-field table of up to 1000000 MB brings the run to about "
                     "1862.7 GiB (1 GiB + 1.75 MiB per tree + twice the far-field table's cap above 512 MB, "
                     "docs/performance.md \"Memory\")"),
            std::string::npos)
      << cap;
  EXPECT_NE(cap.find("than the 24.0 GiB"), std::string::npos) << cap;
  const std::string stand = refusal(gib);
  EXPECT_NE(stand.find("key 'stand.survey': 8 trees need about 1862.7 GiB (1 GiB + 1.75 MiB per tree + twice the "
                       "far-field table's cap above 512 MB"),
            std::string::npos)
      << stand;
}

// What `grow`, `bench stand` and `bench light --stand` call: the estimate against this machine's usable memory. The
// eight trees of stands/tiny fit any machine the tests run on (the refusal itself, under `ulimit -v`:
// tests/scripts/hostile_input.cmake).
TEST(MemoryEstimate, AStandThisMachineHoldsIsNotRefused) {
  EXPECT_NO_THROW(refuse_run_beyond_this_machine(tiny_scenario()));
}

}  // namespace
}  // namespace heliostand
