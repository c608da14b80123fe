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
    EXPECT_NE(message.find("key 'stand.survey': 8 trees need about 1.0 GiB"), std::string::npos) << message;
    EXPECT_NE(message.find("than the 1.0 GiB"), std::string::npos) << message;
  }
}

// What `grow`, `bench stand` and `bench light --stand` call: the estimate against this machine's usable memory. The
// eight trees of stands/tiny fit any machine the tests run on (the refusal itself, under `ulimit -v`:
// tests/scripts/hostile_input.cmake).
TEST(MemoryEstimate, AStandThisMachineHoldsIsNotRefused) {
  EXPECT_NO_THROW(refuse_run_beyond_this_machine(tiny_scenario()));
}

}  // namespace
}  // namespace heliostand
