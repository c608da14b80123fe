// What the simulated year writes (stand/stand_year.hpp): stand_table.csv in every year, trees.csv only in output
// years, and an output year's stand table measures the very trees trees.csv lists.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "io/csv_test_reader.hpp"
#include "io/stand_output.hpp"
#include "io/temp_folder.hpp"
#include "light/reference_light_solver.hpp"
#include "read_text.hpp"
#include "stand/stand.hpp"
#include "stand/stand_year.hpp"

namespace heliostand {
namespace {

constexpr std::uint64_t output_seed = 3;

StandTree planted(int id, const char* species, glm::dvec3 position) {
  ConiferTree tree(SpeciesParameters{}, TreeCalibration{}, position, output_seed, id);
  tree.grow_to_age(8);
  return StandTree{id, std::to_string(id + 1), species, std::move(tree)};
}

std::vector<std::map<std::string, std::string>> read_rows(const std::filesystem::path& file) {
  const auto records = testing::parse_csv(testing::read_text(file));
  std::vector<std::map<std::string, std::string>> rows;
  for (std::size_t r = 1; r < records.size(); ++r) {
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < records[0].size(); ++c) row[records[0][c]] = records[r].at(c);
    rows.push_back(row);
  }
  return rows;
}

// A 10 m × 10 m plot (one tree is 100 stems/ha) of two firs and a larch; the larch (tree "2") is thinned at 22.
std::vector<StandTree> three_trees() {
  std::vector<StandTree> trees;
  trees.push_back(planted(0, "todomatsu", {2, 2, 0}));
  trees.push_back(planted(1, "karamatsu", {6, 3, 0}));
  trees.push_back(planted(2, "todomatsu", {4, 7, 0}));
  return trees;
}

Stand stand_thinning_the_larch_at_22() {
  const ThinningEvent thin_larch{{22}, ThinningRule{ThinningMethod::ids, {"2"}, {}, {}}, "first thinning", true};
  return Stand(0.01, 20, three_trees(), {thin_larch});
}

// A coarse sky keeps the reference solver quick.
ReferenceLightSolver coarse_sky_solver() {
  LightParameters sky;
  sky.sky_bands = 4;
  sky.sky_sectors = 8;
  return ReferenceLightSolver(sky);
}

TEST(StandYearOutput, StandTableEveryYearTreesOnlyInOutputYears) {
  testing::TempFolder tmp("stand_year_output");
  Stand stand = stand_thinning_the_larch_at_22();
  ReferenceLightSolver solver = coarse_sky_solver();
  StageClock clock;
  StandOutput output({tmp.path() / "run", false, 100.0, false});
  StandYear simulated_year(stand, solver, solver, nullptr, &output, {output_seed, 1.0, 4, 3}, clock);  // written at 0, 3, 4
  for (int year = 0; year <= 4; ++year) simulated_year.run(year);
  output.finish(RunManifest{});

  const auto table = read_rows(tmp.path() / "run" / "stand_table.csv");
  ASSERT_EQ(table.size(), 5u * 3) << "ages 20..24, each the whole stand, karamatsu and todomatsu";
  std::map<std::pair<int, std::string>, std::map<std::string, std::string>> by_age;
  for (const auto& row : table) by_age[{std::stoi(row.at("stand_age")), row.at("species")}] = row;
  EXPECT_EQ(by_age.at({22, "karamatsu"}).at("removed_stems_per_ha"), "100.000") << "thinned in a year not written";
  EXPECT_EQ(by_age.at({23, "karamatsu"}).at("stems_per_ha"), "0.000");
  EXPECT_EQ(by_age.at({22, "all"}).at("year_index"), "2");

  std::set<int> written;
  double volume_at_23 = 0;
  for (const auto& tree : read_rows(tmp.path() / "run" / "trees.csv")) {
    written.insert(std::stoi(tree.at("stand_age")));
    if (tree.at("stand_age") == "23" && tree.at("status") == "alive") volume_at_23 += std::stod(tree.at("volume_m3"));
  }
  EXPECT_EQ(written, (std::set<int>{20, 23, 24}));
  EXPECT_NEAR(std::stod(by_age.at({23, "all"}).at("volume_m3_per_ha")), volume_at_23 / 0.01, 0.01)
      << "the stand table measures the trees trees.csv lists";
}

// Step 9 (memory): a tree thinned in a year that is not written keeps its crown until the next output year has
// written it as removed, with the crown it had; then it gives the crown back.
TEST(StandYearOutput, AGoneTreeGivesBackItsCrownOnceWritten) {
  testing::TempFolder tmp("stand_year_release");
  Stand stand = stand_thinning_the_larch_at_22();
  ReferenceLightSolver solver = coarse_sky_solver();
  StageClock clock;
  StandOutput output({tmp.path() / "run", false, 100.0, false});
  StandYear simulated_year(stand, solver, solver, nullptr, &output, {output_seed, 1.0, 4, 3}, clock);  // written at 0, 3, 4
  for (int year = 0; year <= 2; ++year) simulated_year.run(year);
  const ConiferTree& larch = stand.trees()[1].conifer;
  ASSERT_FALSE(stand.trees()[1].alive()) << "thinned at 22";
  ASSERT_FALSE(larch.crown_released()) << "age 23 writes it";
  const double crown_base = larch.crown_base_m(), crown_radius = larch.crown_radius_m();
  const std::size_t shoots = larch.shoots().size();
  EXPECT_GT(shoots, 0u);

  simulated_year.run(3);
  EXPECT_TRUE(larch.crown_released());
  EXPECT_TRUE(larch.shoots().empty());
  EXPECT_FALSE(stand.trees()[0].conifer.crown_released()) << "living trees keep theirs";
  simulated_year.run(4);
  output.finish(RunManifest{});

  std::vector<std::map<std::string, std::string>> larch_rows;
  for (const auto& row : read_rows(tmp.path() / "run" / "trees.csv"))
    if (row.at("label") == "2" && row.at("status") != "alive") larch_rows.push_back(row);
  ASSERT_EQ(larch_rows.size(), 1u) << "written as removed once, at 23";
  EXPECT_EQ(larch_rows[0].at("stand_age"), "23");
  EXPECT_NEAR(std::stod(larch_rows[0].at("crown_base_m")), crown_base, 1e-3);
  EXPECT_NEAR(std::stod(larch_rows[0].at("crown_radius_m")), crown_radius, 1e-3);
}

// Without outputs nothing reads a gone tree again: its crown goes at the end of the year it leaves.
TEST(StandYearOutput, WithoutOutputsAGoneTreeGivesBackItsCrownAtOnce) {
  Stand stand = stand_thinning_the_larch_at_22();
  ReferenceLightSolver solver = coarse_sky_solver();
  StageClock clock;
  StandYear simulated_year(stand, solver, solver, nullptr, nullptr, {output_seed, 1.0, 4, 3}, clock);
  for (int year = 0; year <= 1; ++year) simulated_year.run(year);
  EXPECT_FALSE(stand.trees()[1].conifer.crown_released());
  simulated_year.run(2);
  EXPECT_TRUE(stand.trees()[1].conifer.crown_released());
  EXPECT_FALSE(stand.trees()[0].conifer.crown_released());
}

}  // namespace
}  // namespace heliostand
