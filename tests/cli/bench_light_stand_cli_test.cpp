// `heliostand bench light --stand SCENARIO` as a user runs it: a real stand's leaf balls, established as `grow`
// establishes them, lit by the four solvers with the scenario's own [light]; the command-line light flags replace
// the scenario's values only when given; a bad scenario is refused before any JSON is written.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/bench_run.hpp"
#include "compute/device_choice.hpp"
#include "scenario/scenario.hpp"
#include "stand/establishment.hpp"
#include "tiny_stand_scenario.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

using testing::tiny_bench_stand;

BenchRun bench_light(const fs::path& folder, const std::string& arguments) {
  return run_bench(folder, "light.json", "light " + arguments);
}

// The leaf balls of the stand `grow` starts from: establish_stand's trees, counted here without the command.
std::size_t established_leaf_balls(const fs::path& scenario_file) {
  EstablishmentReport report;
  std::size_t balls = 0;
  for (const StandTree& tree : establish_stand(load_scenario(scenario_file), report))
    if (tree.alive()) balls += tree.conifer.leaf_balls().size();
  return balls;
}

double mean_abs_error(const nlohmann::json& row, const char* solver) {
  return row.at(solver).at("error_vs_reference_exact").at("mean_abs_light").get<double>();
}

// The trees of stands/tiny on its 10 m plot, a scenario in `folder` with a coarse sky and the given [light] lines
// after it (from line 13 on).
fs::path tiny_scenario(const fs::path& folder, const std::string& light_lines) {
  return write_tiny_stand_scenario(folder,
                                   "[run]\nyears = 1\n[light]\nsky_bands = 8\nsky_sectors = 16\n" + light_lines);
}

// Only the reference solvers on a few balls: enough to see the parameters a row used.
const std::string parameters_only = " --device none --reference-exact-max 0 --reference-culled-max 0 --subsample 4";

}  // namespace

// The stand's row holds every leaf ball of the established stand, and the solvers agree as they do on synthetic
// canopies: OpenCL exact is the reference's answer; culled + far field (the default solver) is within the goal of
// issue 16, mean |Δlight| ≤ 0.01, on this small stand whose far field is a few metres of neighbours.
TEST(BenchLightStandCli, RowIsTheEstablishedStandLitByEverySolver) {
  const bool opencl = compute::opencl_device_exists();
  const BenchRun bench =
      bench_light(scratch_folder("bench-light-stand"),
                  "--stand " + tiny_bench_stand.string() + " --device " + (opencl ? "opencl" : "none"));
  ASSERT_EQ(bench.cli.status, 0) << bench.cli.output;
  const auto& stands = bench.json.at("stands");
  ASSERT_EQ(stands.size(), 1u) << "--stand alone runs no synthetic stand";
  const auto& row = stands.at(0);
  EXPECT_EQ(row.at("stand"), tiny_bench_stand.string());
  EXPECT_EQ(row.at("trees"), 8);
  EXPECT_EQ(row.at("balls").get<std::size_t>(), established_leaf_balls(tiny_bench_stand));
  EXPECT_EQ(row.at("plot_m"), 10.0);
  EXPECT_EQ(row.at("parameters").at("sky_bands"), 8) << "the scenario's [light]";
  EXPECT_EQ(row.at("parameters").at("sky"), "overcast") << "a stand's sky unless [light] says otherwise";
  EXPECT_EQ(row.at("error_measured_on").at("whole_stand"), true) << "below --reference-exact-max: every ball";
  EXPECT_EQ(row.at("error_measured_on").at("balls"), row.at("balls"));
  EXPECT_LT(mean_abs_error(row, "reference_culled"), 0.01) << bench.json.dump(1);
  EXPECT_EQ(row.at("reference_culled").at("far_field_cell_m"), 1.0) << "the asked cell: far under the table cap";
  EXPECT_EQ(row.at("reference_exact").at("far_field_cell_m"), 0.0) << "exact: no far field";
  if (!opencl) GTEST_SKIP() << "no OpenCL device: the OpenCL rows were not run";
  EXPECT_EQ(row.at("opencl_culled_far_field").at("far_field_cell_m"), 1.0);
  EXPECT_LT(mean_abs_error(row, "opencl_exact"), 1e-5) << bench.json.dump(1);
  EXPECT_LT(mean_abs_error(row, "opencl_culled_far_field"), 0.01) << bench.json.dump(1);
  // The two culled solvers read the same candidate lists and far-field table: the same answers to float precision.
  const auto& opencl_culled = row.at("opencl_culled_far_field").at("error_vs_reference_exact");
  const auto& reference_culled = row.at("reference_culled").at("error_vs_reference_exact");
  EXPECT_NEAR(opencl_culled.at("mean_light_bias").get<double>(), reference_culled.at("mean_light_bias").get<double>(), 1e-5);
  EXPECT_NEAR(opencl_culled.at("mean_angle_degrees").get<double>(), reference_culled.at("mean_angle_degrees").get<double>(), 0.01);
}

// A light flag given on the command line replaces the scenario's value; one not given leaves it. The synthetic
// stands (--balls, combined with --stand) keep the command's own values.
TEST(BenchLightStandCli, GivenFlagsOverrideTheScenario) {
  const fs::path folder = scratch_folder("bench-light-stand-flags");
  // its own cut-off, 5 m, not the command's default (3 m): which value a row used shows
  const fs::path scenario =
      tiny_scenario(folder, "cutoff_m = 5.0\nfar_field_hand_over_cells = 0.5\nfar_field_table_mb = 256\n");

  const BenchRun own = bench_light(folder / "own", "--stand " + scenario.string() + parameters_only);
  ASSERT_EQ(own.cli.status, 0) << own.cli.output;
  const auto& own_parameters = own.json.at("stands").at(0).at("parameters");
  EXPECT_EQ(own_parameters.at("cutoff_m"), 5.0) << "no --cutoff: the scenario's";
  EXPECT_EQ(own_parameters.at("far_field_bias_correction"), true) << "not in the scenario: the default";
  EXPECT_EQ(own_parameters.at("periodic"), false);
  EXPECT_EQ(own_parameters.at("far_field_hand_over_cells"), 0.5) << "no --far-field-hand-over: the scenario's";
  EXPECT_EQ(own_parameters.at("far_field_table_mb"), 256.0) << "no --far-field-table-mb: the scenario's";

  const BenchRun given = bench_light(folder / "given", "--balls 200 --stand " + scenario.string() +
                                                           " --cutoff 2 --far-field-hand-over 0.75" +
                                                           " --far-field-table-mb 600" +
                                                           " --no-far-field-bias-correction --periodic" +
                                                           parameters_only);
  ASSERT_EQ(given.cli.status, 0) << given.cli.output;
  const auto& stands = given.json.at("stands");
  ASSERT_EQ(stands.size(), 2u) << "one synthetic stand, then the scenario's";
  EXPECT_FALSE(stands.at(0).contains("stand"));
  EXPECT_EQ(stands.at(0).at("balls"), 200);
  const auto& given_parameters = stands.at(1).at("parameters");
  EXPECT_EQ(given_parameters.at("cutoff_m"), 2.0) << "--cutoff 2 replaces the scenario's 5 m";
  EXPECT_EQ(given_parameters.at("far_field_bias_correction"), false) << "--no-far-field-bias-correction";
  EXPECT_EQ(given_parameters.at("periodic"), true);
  EXPECT_EQ(given_parameters.at("far_field_hand_over_cells"), 0.75) << "--far-field-hand-over replaces the scenario's";
  EXPECT_EQ(given_parameters.at("far_field_table_mb"), 600.0) << "--far-field-table-mb replaces the scenario's";
  EXPECT_EQ(given_parameters.at("far_field_cell_m"), 1.0) << "not given: the scenario's (the default)";
  EXPECT_EQ(given_parameters.at("sky_bands"), 8) << "not a flag: always the scenario's";
  EXPECT_EQ(given.json.at("parameters").at("cutoff_m"), 2.0) << "the synthetic stands' parameters";
  EXPECT_EQ(given.json.at("parameters").at("far_field_table_mb"), 600.0);
}

// A scenario in a folder named in a legacy encoding (Latin-1 "café": byte 0xe9, not UTF-8): the row names it with that
// byte replaced by U+FFFD, and the file is still JSON that a reader takes. Written by hand, the byte went out as it was
// and the file was not valid JSON.
TEST(BenchLightStandCli, AScenarioPathNotInUtf8StillGivesValidJson) {
  const fs::path folder = scratch_folder("bench-light-stand-latin1");
  const fs::path scenario = tiny_scenario(folder / "caf\xe9", "");
  const BenchRun bench = bench_light(folder / "out", "--stand '" + scenario.string() + "'" + parameters_only);
  ASSERT_EQ(bench.cli.status, 0) << bench.cli.output;
  EXPECT_EQ(bench.json.at("stands").at(0).at("stand"), (folder / "caf\xef\xbf\xbd" / "scenario.toml").string());
}

// A missing or bad scenario: the scenario reader's message (file, line, key, reason), exit 2, and no JSON at all,
// not even for the synthetic stands asked for beside it.
TEST(BenchLightStandCli, BadScenarioIsRefusedBeforeAnyJson) {
  const fs::path folder = scratch_folder("bench-light-stand-bad");
  const fs::path missing = folder / "no_such_scenario.toml";
  const fs::path json = folder / "light.json";
  const CliResult absent = run_cli("bench light --stand " + missing.string() + " -o " + json.string());
  EXPECT_EQ(absent.status, 2) << absent.output;
  EXPECT_NE(absent.output.find(missing.string()), std::string::npos) << absent.output;
  EXPECT_FALSE(fs::exists(json)) << "no JSON file";

  const fs::path bad = tiny_scenario(folder / "bad", "cutoff_m = -1.0\n");
  const CliResult refused =
      run_cli("bench light --balls 200 --stand " + bad.string() + parameters_only + " -o " + json.string());
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find(bad.string() + ":13"), std::string::npos) << "file and line: " << refused.output;
  EXPECT_NE(refused.output.find("key 'light.cutoff_m'"), std::string::npos) << refused.output;
  EXPECT_EQ(refused.output.find("\"benchmark\""), std::string::npos) << "no JSON on stdout: " << refused.output;
  EXPECT_FALSE(fs::exists(json)) << "no JSON file";
}

}  // namespace heliostand::testing
