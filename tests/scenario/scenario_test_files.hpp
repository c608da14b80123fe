#pragma once
// A scenario and its survey written side by side into a fresh temporary folder.
#include <filesystem>
#include <string>

#include "scenario/scenario.hpp"
#include "survey/survey_test_files.hpp"

namespace heliostand::testing {

// The repository's stands/ folder: the example stands and the deliberately bad files of stands/bad.
inline const std::filesystem::path stands = std::filesystem::path(HELIOSTAND_SOURCE_DIR) / "stands";

// Four trees on a 10 m x 10 m plot (0.01 ha = 400 stems/ha), ids 1-4.
inline const std::string four_tree_survey =
    "id,x,y,height,dbh,crown_radius,crown_base\n"
    "1,2,2,9,12,1,4\n"
    "2,7,2,10,13,1.1,4.2\n"
    "3,2,7,8,11,0.9,3.8\n"
    "4,7,7,9.5,12.5,1,4\n";

inline const std::string minimal_stand =
    "[stand]\n"
    "survey = \"survey.csv\"\n"
    "age_at_survey = 20\n"
    "x_min = 0\n"
    "y_min = 0\n"
    "x_max = 10\n"
    "y_max = 10\n"
    "\n"
    "[run]\n"
    "years = 10\n";  // 10 lines: text appended starts on line 11

inline std::filesystem::path write_scenario(const std::string& name, const std::string& toml,
                                            const std::string& survey = four_tree_survey) {
  write_test_file(name + "/survey.csv", survey);
  return write_test_file(name + "/scenario.toml", toml);
}

// The problems of loading `toml` (with `survey`) as formatted lines, the folder stripped from the paths
// ("scenario.toml:12: key 'a.b': reason"); a test failure if loading succeeds.
inline std::vector<std::string> scenario_problems(const std::string& name, const std::string& toml,
                                                  const std::string& survey = four_tree_survey) {
  const auto file = write_scenario(name, toml, survey);
  auto lines = input_problems([&] { load_scenario(file); });
  const std::string folder = file.parent_path().string() + "/";
  for (auto& line : lines)
    for (auto at = line.find(folder); at != std::string::npos; at = line.find(folder)) line.erase(at, folder.size());
  return lines;
}

}  // namespace heliostand::testing
