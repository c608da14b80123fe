// The benchmarks refuse work far beyond the machine before doing any of it, as `grow` does: exit 2, the estimate in the
// message, no JSON on stdout and no -o file. The largest count --balls reads, 2^64 - 1, is beyond every machine, so
// this needs no memory limit, and its estimate must saturate rather than wrap (light/light_benchmark.hpp). Were the
// refusal lost, the count fails at once (the canopy's reserve throws) instead of filling the machine, as a mistyped
// 10^11 would. Likewise the largest cap --far-field-table-mb takes, 10^6 MB (the scenario key's limit), is twice a
// terabyte in the estimate: refused under that flag on every machine. The refusals under a given limit (`ulimit -v`:
// `bench stand`, `bench light --stand` and `--balls 100000`) are tests/scripts/hostile_input.cmake's.
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

// A cap that alone takes the canopy beyond the machine is refused under its flag, for the synthetic canopies and for a
// --stand whose cap the flag replaced (before the stand is established); a canopy too large at any cap, under --balls.
TEST(BenchMemoryCli, AFarFieldCapBeyondEveryMachineIsRefusedUnderItsFlag) {
  const fs::path folder = scratch_folder("bench-memory-table");
  fs::create_directories(folder);
  const fs::path json = folder / "light.json";
  const std::string cap = " --far-field-table-mb 1000000 -o " + json.string();

  const CliResult synthetic = run_cli(quick_reference_light_bench + cap);
  EXPECT_EQ(synthetic.status, 2) << synthetic.output;
  EXPECT_NE(synthetic.output.find("--far-field-table-mb: a far-field table of up to 1000000 MB brings 300 leaf balls "
                                  "to about "),
            std::string::npos)
      << synthetic.output;
  EXPECT_NE(synthetic.output.find("(1 GiB + 2 KiB a ball + twice the far-field table's cap above 512 MB, "
                                  "docs/performance.md \"Memory\"), more than the "),
            std::string::npos)
      << synthetic.output;
  EXPECT_EQ(synthetic.output.find("bench light: 300 balls"), std::string::npos) << synthetic.output;
  EXPECT_EQ(synthetic.output.find("\"benchmark\""), std::string::npos) << synthetic.output;

  const CliResult stand = run_cli("bench light --stand " + tiny_bench_stand.string() + " --device none" + cap);
  EXPECT_EQ(stand.status, 2) << stand.output;
  EXPECT_NE(stand.output.find("--far-field-table-mb: " + tiny_bench_stand.string() + ": a far-field table of up to "
                              "1000000 MB brings the run to about "),
            std::string::npos)
      << stand.output;
  EXPECT_EQ(stand.output.find("established"), std::string::npos) << "refused before the stand is established";

  const CliResult both = run_cli("bench light --balls 18446744073709551615 --device none" + cap);
  EXPECT_EQ(both.status, 2) << both.output;
  EXPECT_NE(both.output.find("--balls: 18446744073709551615 leaf balls need about "), std::string::npos)
      << "too large at any cap: the count is named, not the cap: " << both.output;
  EXPECT_FALSE(fs::exists(json)) << "no JSON for any of them";
}

}  // namespace
}  // namespace heliostand::testing
