#pragma once
// The scenario of the tiny stand as the tests that grow it write it: stands/tiny's eight surveyed trees on their
// 10 m x 10 m plot at age 20, and whatever tables the test chooses after [stand]. One writer, so that the tests
// (command-line and unit tests alike) grow the same stand and a change to it is made once. Beside it, stands/tiny's
// own scenario (its thinning and all) with a far-field cap put under [light], for the tests of that cap.
#include <filesystem>
#include <fstream>
#include <string>

#include "read_text.hpp"

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

// stands/tiny's scenario.toml and survey copied into `folder` (made if missing), with `far_field_table_mb = cap_mb`
// (whole megabytes) as the first line of [light]: a cap a test sets beyond what the machine or the device holds.
inline std::filesystem::path write_tiny_stand_with_far_field_cap(const std::filesystem::path& folder, int cap_mb) {
  const std::filesystem::path tiny = std::filesystem::path(HELIOSTAND_SOURCE_DIR) / "stands/tiny";
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(tiny / "survey.csv", folder / "survey.csv");
  std::string scenario = read_text(tiny / "scenario.toml");
  scenario.replace(scenario.find("[light]\n"), 8, "[light]\nfar_field_table_mb = " + std::to_string(cap_mb) + "\n");
  std::ofstream(folder / "scenario.toml") << scenario;
  return folder / "scenario.toml";
}

}  // namespace heliostand::testing
