// `heliostand bench light --evaluations N`: the default solver (OpenCL culled + far field) lights each canopy N
// times in a row with one solver. The first evaluation is the row's, as without the flag; the later ones, which find
// the solver's kept buffers made (as every year after the first of a run does), are listed after it. Zero
// evaluations is bad input, refused before any JSON is written.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/bench_run.hpp"
#include "cli/cli_runner.hpp"
#include "compute/device_choice.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

const std::string small = " --balls 300 --subsample 50 --reference-exact-max 300 --reference-culled-max 0";

}  // namespace

TEST(BenchLightEvaluationsCli, LaterEvaluationsAreListedAfterTheFirst) {
  if (!compute::opencl_device_exists()) GTEST_SKIP() << "no OpenCL device: the default solver's row is not run";
  const fs::path folder = scratch_folder("bench-light-evaluations");
  const BenchRun three = run_bench(folder, "three.json", "light" + small + " --evaluations 3");
  ASSERT_EQ(three.cli.status, 0) << three.cli.output;
  const auto row = three.json.at("stands").at(0).at("opencl_culled_far_field");
  ASSERT_TRUE(row.contains("later_evaluations")) << row.dump(1);
  const auto& later = row.at("later_evaluations");
  ASSERT_EQ(later.size(), 2u) << row.dump(1);
  for (const auto& evaluation : later) {
    EXPECT_GT(evaluation.at("setup_seconds").get<double>(), 0.0) << evaluation.dump();
    EXPECT_GE(evaluation.at("seconds").get<double>(), evaluation.at("setup_seconds").get<double>())
        << evaluation.dump();
    EXPECT_GE(evaluation.at("setup_seconds").get<double>(),
              evaluation.at("search_seconds").get<double>() + evaluation.at("far_field_seconds").get<double>())
        << evaluation.dump();
  }
  EXPECT_TRUE(row.contains("error_vs_reference_exact")) << "the first evaluation is still the row's";

  const BenchRun one = run_bench(folder, "one.json", "light" + small);
  ASSERT_EQ(one.cli.status, 0) << one.cli.output;
  const auto first_only = one.json.at("stands").at(0);
  EXPECT_FALSE(first_only.at("opencl_culled_far_field").contains("later_evaluations")) << "one evaluation by default";
}

namespace {

// `bench light` with `flags` is a usage error (exit 2) whose message holds each of `named`, and nothing is reported:
// no JSON on stdout and no -o file.
void expect_refused_before_any_json(const std::string& test_name, const std::string& flags,
                                    const std::vector<std::string>& named) {
  const fs::path folder = scratch_folder(test_name);
  fs::create_directories(folder);
  const fs::path json = folder / "light.json";
  const CliResult refused = run_cli("bench light" + small + flags + " -o " + json.string() + " -q");
  EXPECT_EQ(refused.status, 2) << refused.output;
  for (const std::string& text : named) EXPECT_NE(refused.output.find(text), std::string::npos) << refused.output;
  EXPECT_EQ(refused.output.find("\"benchmark\""), std::string::npos) << "no JSON on stdout: " << refused.output;
  EXPECT_FALSE(fs::exists(json));
}

}  // namespace

TEST(BenchLightEvaluationsCli, ZeroEvaluationsIsRefusedBeforeAnyJson) {
  expect_refused_before_any_json("bench-light-evaluations-zero", " --device none --evaluations 0", {"--evaluations"});
}

// The later evaluations are the OpenCL solver's: with --device none there is none, so asking for more than one is
// a usage error rather than a flag that silently does nothing.
TEST(BenchLightEvaluationsCli, SeveralEvaluationsWithoutTheOpenCLSolverAreRefused) {
  expect_refused_before_any_json("bench-light-evaluations-none", " --device none --evaluations 2",
                                 {"--evaluations", "--device none"});
  const CliResult one = run_cli("bench light" + small + " --device none --evaluations 1 -q");
  EXPECT_EQ(one.status, 0) << "one evaluation is what --device none runs anyway: " << one.output;
}

}  // namespace heliostand::testing
