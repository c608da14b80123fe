#pragma once
// The scenario of the tiny stand as the tests that grow it write it: stands/tiny's eight surveyed trees on their
// 10 m x 10 m plot at age 20, and whatever tables the test chooses after [stand]. One writer, so that the tests
// (command-line and unit tests alike) grow the same stand and a change to it is made once.
#include <filesystem>
#include <fstream>
#include <string>

namespace heliostand::testing {

// A scenario in `folder` (made if missing) on stands/tiny's survey, copied beside it, with `after_stand` (the tables
// after [stand]) saying what the test grows. [stand] takes lines 1 to 7, so `after_stand` begins at line 8: a test
// of the scenario reader's message, which names the line, counts on it (bench_light_stand_cli_test).
inline std::filesystem::path write_tiny_stand_scenario(const std::filesystem::path& folder,
                                                       const std::string& after_stand) {
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(std::filesystem::path(HELIOSTAND_SOURCE_DIR) / "stands/tiny/survey.csv",
                             folder / "survey.csv");
  std::ofstream(folder / "scenario.toml")
      << "[stand]\nsurvey = \"survey.csv\"\nage_at_survey = 20\nx_min = 0.0\ny_min = 0.0\nx_max = 10.0\ny_max = 10.0\n"
      << after_stand;
  return folder / "scenario.toml";
}

}  // namespace heliostand::testing
