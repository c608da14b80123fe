// Fuzz-style: random mutations of valid surveys never crash the reader, and every rejection names the file and
// a line (issue: "a survey height of 1e308 crashes grow"). Deterministic: a fixed seed and a fixed number of
// mutations (a few seconds), so a failure reproduces; the failing text is printed.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "survey/read_survey.hpp"
#include "survey/survey_test_files.hpp"

namespace heliostand {
namespace {

std::string example_survey_head(int lines) {
  std::ifstream in(std::string(HELIOSTAND_SOURCE_DIR) + "/stands/sobetsu/survey.csv");
  std::string text, line;
  for (int i = 0; i < lines && std::getline(in, line); ++i) text += line + "\n";
  return text;
}

const std::vector<std::string>& seed_surveys() {
  static const std::vector<std::string> seeds{
      example_survey_head(16),
      "id;x;y;height_ft;dbh_mm;crown_ratio_pct;age;species;hollow\n"
      "a;1,5;2;50;210;45;40;todomatsu;1.4/315\n"
      "b;4;2,5;48,5;190;50;;todomatsu;\n"
      "c;7;8;;230;40;41;;0.4/270/0.16/0.30;3.1/45\n",
      "X\tY\tSpecies\tType\tDiam\tHeight\n10.3\t6.1\ttodomatsu\tSeedling\t0.2\t0.4\n9.3\t8.9\ttodomatsu\tSapling\t4.5\t5.2\n"
      "5.7\t6.1\ttodomatsu\tAdult\t15.8\t15.3\n12.0\t14.6\ttodomatsu\tSnag\t35.4\t28.7\n",
  };
  return seeds;
}

// Cells and fragments that have broken readers: extremes, non-numbers, separators, quotes, line breaks.
const std::vector<std::string> fragments{
    "1e308", "-1e308", "1e-320", "nan", "inf", "-0", "0", "+", "-", "1,5", "1;5", "\"", "\"\"", "\n", "\r\n", ",",
    ";", "\t", "999999999999999999999", "0x10", " ", "", "1/2/3/4/5", "//", "1e7", "130", "5001", "Seedling",
    "snag", "dbh_mm", "height (ft)", "\xEF\xBB\xBF", "\xff\xfe", "x", "y", "id"};

std::string mutate(std::string text, std::mt19937& random) {
  std::uniform_int_distribution<int> kind(0, 4);
  const int edits = 1 + static_cast<int>(random() % 2);
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = text.empty() ? 0 : random() % (text.size() + 1);
    const std::string& fragment = fragments[random() % fragments.size()];
    switch (kind(random)) {
      case 0: text.insert(at, fragment); break;                                       // insert
      case 1: text.erase(at, random() % 12); break;                                   // delete a span
      case 2: if (at < text.size()) text[at] = static_cast<char>(random() % 256); break;  // flip a byte
      case 3: {                                                                        // replace a cell
        const std::size_t end = text.find_first_of(",;\t\n", at);
        text.replace(at, (end == std::string::npos ? text.size() : end) - at, fragment);
        break;
      }
      default: {                                                                       // duplicate a line
        const std::size_t start = text.rfind('\n', at == 0 ? 0 : at - 1);
        const std::size_t from = start == std::string::npos ? 0 : start + 1;
        const std::size_t end = text.find('\n', from);
        if (end != std::string::npos) text.insert(end + 1, text.substr(from, end + 1 - from));
      }
    }
  }
  return text;
}

std::vector<SurveyReadOptions> option_sets() {
  std::vector<SurveyReadOptions> sets(3);
  sets[0].stand_age_years = 35;
  sets[1].stand_age_years = 30;
  sets[1].plot = PlotBounds{0, 0, 24, 20};
  sets[1].format.multi_stem = MultiStemPolicy::merge;
  sets[2].stand_age_years = 35;
  sets[2].format.multi_stem = MultiStemPolicy::separate;
  return sets;
}

TEST(SurveyFuzz, MutatedSurveysNeverCrashAndEveryRejectionNamesFileAndLine) {
  std::mt19937 random(20261123);
  const auto options = option_sets();
  const auto file = testing::write_test_file("fuzz.csv", "");
  const std::string label = file.string();
  int rejected = 0, accepted = 0;
  for (int i = 0; i < 1500; ++i) {
    const std::string& seed = seed_surveys()[i % seed_surveys().size()];
    const std::string text = mutate(seed, random);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    try {
      const Survey survey = read_survey(file, options[i % options.size()]);
      ++accepted;
      for (const SurveyRecord& tree : survey.trees) {
        ASSERT_TRUE(tree.height_m >= 0 && tree.height_m <= 130 && tree.dbh_cm <= 1500) << "mutation " << i << ":\n" << text;
      }
    } catch (const InputError& error) {
      ++rejected;
      for (const InputProblem& problem : error.problems()) {
        ASSERT_EQ(problem.file, label) << "mutation " << i << ":\n" << text;
        const bool whole_file = problem.reason.find("the survey is empty") != std::string::npos ||
                                problem.reason.find("no tree to grow") != std::string::npos;
        ASSERT_TRUE(problem.line >= 1 || whole_file)
            << "mutation " << i << " rejected without a line: " << problem.reason << "\n" << text;
      }
    } catch (const std::exception& error) {
      FAIL() << "mutation " << i << " threw " << error.what() << " instead of an InputError:\n" << text;
    }
  }
  // Both outcomes occur, so the mutations neither all break the file nor all leave it valid.
  EXPECT_GT(rejected, 150);
  EXPECT_GT(accepted, 150);
}

}  // namespace
}  // namespace heliostand
