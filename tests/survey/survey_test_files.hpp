#pragma once
// Writes small survey files for tests into GoogleTest's temporary folder.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.hpp"
#include "folders_removed_at_exit.hpp"
#include "survey/read_survey.hpp"

namespace heliostand::testing {

// One folder per test and process: CTest runs the tests of one program in parallel processes (ctest -j), and
// tests that share a file name ("bad.csv") would otherwise read each other's files. Whoever names it may make it, so
// it is deleted when the process exits: it carries the process id, and without this each run left ~100 behind.
inline std::filesystem::path test_file_folder() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test_name = test ? std::string(test->test_suite_name()) + "." + test->name() : "no-test";
  const auto folder = std::filesystem::path(::testing::TempDir()) / "heliostand_inputs" /
                      (test_name + "-" + std::to_string(::getpid()));
  folders_removed_at_exit().add(folder);
  return folder;
}

inline std::filesystem::path write_test_file(const std::string& name, const std::string& text) {
  const auto dir = test_file_folder();
  const auto path = dir / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The formatted problem lines of an InputError thrown by `action`, or a test failure if none is thrown.
template <class Action>
std::vector<std::string> input_problems(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    std::vector<std::string> lines;
    for (const auto& p : error.problems()) lines.push_back(p.format(error.field_kind()));
    return lines;
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

// A survey of a stand of the given age, with no plot bounds given.
inline SurveyReadOptions stand_of_age(double age = 35) {
  SurveyReadOptions options;
  options.stand_age_years = age;
  return options;
}

// A survey of a 30 m × 30 m plot with its corner at the origin.
inline SurveyReadOptions plot_30x30(double stand_age = 35) {
  SurveyReadOptions options = stand_of_age(stand_age);
  options.plot = PlotBounds{0, 0, 30, 30};
  return options;
}

// The problems of reading `text` as the survey file `name` with `options`, the temporary path shown as "s.csv".
inline std::vector<std::string> survey_problems(const std::string& name, const std::string& text,
                                                const SurveyReadOptions& options) {
  const auto file = write_test_file(name, text);
  auto lines = input_problems([&] { read_survey(file, options); });
  for (auto& line : lines)
    if (line.rfind(file.string(), 0) == 0) line = "s.csv" + line.substr(file.string().size());
  return lines;
}

}  // namespace heliostand::testing
