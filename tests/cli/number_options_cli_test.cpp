// The options that take a count or an amount say what they expect and what they were given
// (src/cli/number_checks.hpp), not CLI11 2.1's "Value 0 not in range 0.000000 to 179769313486231570...000000" or
// "Value 99 not in range 0.000000 to 4.000000", and an unsigned limit is not wrapped from -1 to 2^64 - 1: exit 2,
// before anything runs.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/cli_runner.hpp"
#include "cli/number_checks.hpp"

namespace heliostand::testing {
namespace {

std::string check(const CLI::Validator& validator, std::string value) { return validator(value); }

TEST(NumberChecks, ACountIsAWholeNumberOfAtLeastOne) {
  for (const std::string good : {"1", "12", "007", "2500"}) EXPECT_EQ(check(whole_number_check(), good), "") << good;
  for (const std::string bad : {"0", "00", "-1", "+3", "1.5", "1e3", "abc", "", " 2", "2 "})
    EXPECT_EQ(check(whole_number_check(), bad), "a whole number >= 1 is expected, got " + bad) << bad;
}

TEST(NumberChecks, ALimitMayBeZeroButNeverNegative) {
  for (const std::string good : {"0", "1", "4000", "99999999999999999999999"})
    EXPECT_EQ(check(whole_number_check(0), good), "") << good;
  for (const std::string bad : {"-1", "1.5", "abc", ""})
    EXPECT_EQ(check(whole_number_check(0), bad), "a whole number >= 0 is expected, got " + bad) << bad;
}

TEST(NumberChecks, AnAmountUpToAMaximumIsAboveZeroFiniteAndIncludesTheMaximum) {
  for (const std::string good : {"1000", "0.5", "1e-3", "1e3"})
    EXPECT_EQ(check(positive_amount_check(1000), good), "") << good;
  for (const std::string bad : {"0", "-0", "-1", "1000.001", "1e160", "1e999", "inf", "nan", "abc", "", "1x", "3 "})
    EXPECT_EQ(check(positive_amount_check(1000), bad), "a number in (0, 1000] is expected, got " + bad) << bad;
}

TEST(NumberChecks, ACountWithinLimitsIncludesBoth) {
  for (const std::string good : {"1", "1000", "0500"}) EXPECT_EQ(check(whole_number_check(1, 1000), good), "") << good;
  for (const std::string bad : {"0", "1001", "-1", "1.5", "abc", "", "99999999999999999999"})
    EXPECT_EQ(check(whole_number_check(1, 1000), bad), "a whole number in 1..1000 is expected, got " + bad) << bad;
}

TEST(NumberChecks, AnAmountWithinLimitsIncludesBothAndIsFinite) {
  for (const std::string good : {"0", "4", "0.5", "2e0"}) EXPECT_EQ(check(amount_between_check(0, 4), good), "") << good;
  for (const std::string bad : {"-0.5", "4.5", "nan", "inf", "abc", "", "1x"})
    EXPECT_EQ(check(amount_between_check(0, 4), bad), "a number in 0..4 is expected, got " + bad) << bad;
  EXPECT_EQ(check(amount_between_check(0.25, 2.5), "3"), "a number in 0.25..2.5 is expected, got 3");
}

// Every option that carries one of the checks, through the program as a user runs it.
TEST(NumberOptionsCli, EachCountAndAmountOptionSaysWhatItExpectsAndWhatItGot) {
  const std::string tiny = source_path("stands/tiny/scenario.toml").string();
  const std::string out = (std::filesystem::path(HELIOSTAND_BINARY_DIR) / "test-output" / "number-options").string();
  const std::string count = "a whole number >= 1 is expected, got ";
  const std::string limit = "a whole number >= 0 is expected, got ";
  const std::string distance = "a number in (0, 1000] is expected, got ";  // the scenario's [light] limit
  struct Case {
    std::string arguments, refusal;
  };
  const std::vector<Case> cases = {
      {"--threads 0 check " + tiny, "--threads: " + count + "0"},
      {"grow " + tiny + " --out " + out + " --years 0", "--years: " + count + "0"},
      {"grow " + tiny + " --out " + out + " --checkpoint-every -1", "--checkpoint-every: " + count + "-1"},
      {"batch manifest.toml --jobs 1.5", "--jobs: " + count + "1.5"},
      {"batch manifest.toml --checkpoint-every abc", "--checkpoint-every: " + count + "abc"},
      {"bench stand " + tiny + " --years 0", "--years: " + count + "0"},
      {"bench light --balls 1e5", "--balls: " + count + "1e5"},
      {"bench light --balls 10 --subsample 0", "--subsample: " + count + "0"},
      {"bench light --balls 10 --reference-exact-max -1", "--reference-exact-max: " + limit + "-1"},
      {"bench light --balls 10 --reference-culled-max -1", "--reference-culled-max: " + limit + "-1"},
      {"bench light --balls 10 --opencl-exact-max 2.5", "--opencl-exact-max: " + limit + "2.5"},
      {"bench light --balls 10 --cutoff 0", "--cutoff: " + distance + "0"},
      {"bench light --balls 10 --cutoff 1e160", "--cutoff: " + distance + "1e160"},
      {"bench light --balls 10 --far-field-cell inf", "--far-field-cell: " + distance + "inf"},
      {"bench light --balls 10 --far-field-cell 1000.5", "--far-field-cell: " + distance + "1000.5"},
      {"bench light --balls 10 --evaluations 0", "--evaluations: a whole number in 1..1000 is expected, got 0"},
      {"bench light --balls 10 --far-field-hand-over 99", "--far-field-hand-over: a number in 0..4 is expected, got 99"},
      {"bench light --balls 10 --far-field-hand-over nan", "--far-field-hand-over: a number in 0..4 is expected, got nan"},
  };
  // (--balls 10: were a refusal to regress, the bench would run in a second, not for hours.)
  for (const Case& c : cases) {
    const CliResult run = run_cli(c.arguments);
    EXPECT_EQ(run.status, 2) << c.arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(c.refusal), std::string::npos) << c.arguments << "\n" << run.output;
    EXPECT_EQ(run.output.find("179769"), std::string::npos) << c.arguments << "\n" << run.output;
    EXPECT_EQ(run.output.find("0.000000"), std::string::npos) << c.arguments << "\n" << run.output;
  }
  EXPECT_FALSE(std::filesystem::exists(out)) << "a refused grow wrote its output folder";
}

}  // namespace
}  // namespace heliostand::testing
