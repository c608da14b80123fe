// The benchmarks refuse work far beyond the machine before doing any of it, as `grow` does: exit 2, the estimate in
// the message, no JSON on stdout and no -o file. The largest count --balls reads, 2^64 - 1, is beyond every machine,
// so this needs no memory limit, and its estimate must saturate rather than wrap (light/light_benchmark.hpp).
// Were the refusal lost, the count fails at once (the canopy's reserve throws) instead of filling the machine, as a
// mistyped 10^11 would. The refusals under a given limit (`ulimit -v`: `bench stand`, `bench light --stand` and
// `--balls 100000`) are tests/scripts/hostile_input.cmake's.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_runner.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

TEST(BenchMemoryCli, ACanopyBeyondEveryMachineIsRefusedBeforeAnyCanopyIsMade) {
  const fs::path folder = scratch_folder("bench-memory-balls");
  fs::create_directories(folder);  // so that only the refusal can leave the -o file unwritten
  const fs::path json = folder / "light.json";
  // Beside a canopy the machine holds (the quick benchmark's 300 balls), and after it: nothing runs, not even that.
  const CliResult refused = run_cli(quick_reference_light_bench + " --balls 18446744073709551615 -o " + json.string());
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("--balls: 18446744073709551615 leaf balls need about 17179869184.0 GiB (1 GiB + 2 KiB "
                                "a ball, docs/performance.md \"Memory\")"),
            std::string::npos)
      << refused.output;
  EXPECT_EQ(refused.output.find("\"benchmark\""), std::string::npos) << "no JSON on stdout: " << refused.output;
  EXPECT_EQ(refused.output.find("bench light: 300 balls"), std::string::npos) << "no canopy made: " << refused.output;
  EXPECT_FALSE(fs::exists(json));
}

}  // namespace
}  // namespace heliostand::testing
