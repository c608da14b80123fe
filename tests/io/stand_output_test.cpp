#include "io/stand_output.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "io/csv_test_reader.hpp"
#include "io/file_size_limit.hpp"
#include "io/synthetic_stand.hpp"
#include "io/temp_folder.hpp"
#include "read_text.hpp"

namespace heliostand {
namespace {
namespace fs = std::filesystem;

using testing::read_text;

bool has_temporaries(const fs::path& root) {
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().filename().string().find(".tmp") != std::string::npos) return true;
  }
  return false;
}

RunManifest example_manifest() {
  RunManifest m;
  m.command_line = "heliostand grow stands/tiny.toml --out \"run 1\"";
  m.scenario_path = "stands/tiny.toml";
  m.seed = 18446744073709551615ull;  // the largest seed must survive JSON
  m.device = "reference";
  m.started_utc = utc_now_iso8601();
  m.finished_utc = m.started_utc;
  m.first_stand_age = 10;
  m.last_stand_age = 15;
  m.wall_seconds = 1.25;
  m.stage_seconds = {{"grow", 0.5}, {"light", 0.75}};
  m.finished_on_hardware_threads = 2;
  m.finished_on_processor = {"AMD EPYC", 26, 2, {"avx2", "avx512f"}};
  m.finished_on_pages = {"glibc.malloc.hugetlb=1", std::nullopt};
  return m;
}

// The synthetic stand in year `year` of a run that starts at stand age 10: the Karamatsu "A,2" is thinned in
// year 2 (gone from then on), the Todomatsu "B \"3\"" dies in year 4 (still standing, dead).
testing::SyntheticStand stand_in_year(int year) {
  auto stand = testing::make_synthetic_stand(10 + year, year);
  if (year >= 4) stand.snapshot.trees[2].status = TreeStatus::dead;
  if (year >= 2) stand.snapshot.trees.erase(stand.snapshot.trees.begin() + 1);
  return stand;
}

// stand_table.csv as column → value, per (stand age, species).
std::map<std::pair<int, std::string>, std::map<std::string, std::string>> stand_rows(const fs::path& file) {
  const auto records = testing::parse_csv(read_text(file));
  std::map<std::pair<int, std::string>, std::map<std::string, std::string>> rows;
  for (std::size_t r = 1; r < records.size(); ++r) {
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < records[0].size() && c < records[r].size(); ++c) row[records[0][c]] = records[r][c];
    rows[{std::stoi(row.at("stand_age")), row.at("species")}] = row;
  }
  return rows;
}

// Five simulated years on the 100 m² synthetic plot (one tree = 100 stems/ha), written in years 0 and 5.
class StandOutputRun : public ::testing::Test {
 protected:
  StandOutputRun() : tmp_("stand_output"), root_(tmp_.path() / "run") {}

  void run_two_output_years(StandOutput& out) {
    const TreeEvent thinned{12, 2, "A,2", "karamatsu", TreeEventKind::removed, "thinning", "thinning:low",
                            20.0, 14.0, 0.2};
    const TreeEvent died{14, 3, "B \"3\"", "todomatsu", TreeEventKind::died, "suppression", "suppression",
                         8.0, 6.0, 0.05};
    for (int year = 0; year <= 5; ++year) {
      if (year == 2) out.record_events(std::vector{thinned});
      if (year == 4) out.record_events(std::vector{died});
      const auto stand = stand_in_year(year);
      out.write_stand_rows(inventory_of(stand.snapshot));
      if (year == 0 || year == 5) out.write_year(stand.snapshot);
    }
  }

  testing::TempFolder tmp_;
  fs::path root_;
};

TEST_F(StandOutputRun, WritesTheTablesTheVtkSeriesAndRunJsonLast) {
  {
    StandOutput out({root_, false, 100.0});
    run_two_output_years(out);
    EXPECT_FALSE(fs::exists(root_ / "run.json")) << "run.json must only appear when the run is finished";
    EXPECT_TRUE(fs::exists(root_ / "stand.pvd")) << "the series must be viewable while the run goes on";
    out.finish(example_manifest());
  }
  EXPECT_FALSE(has_temporaries(root_));

  const auto json = nlohmann::json::parse(read_text(root_ / "run.json"));  // throws if not valid JSON
  EXPECT_EQ(json["format_version"], 1);
  EXPECT_EQ(json["seed"].get<std::uint64_t>(), 18446744073709551615ull);
  EXPECT_EQ(json["command_line"], "heliostand grow stands/tiny.toml --out \"run 1\"");
  EXPECT_EQ(json["stage_seconds"]["light"], 0.75);
  EXPECT_EQ(json["finished_on"], nlohmann::json::parse(R"({"hardware_threads": 2, "processor": {"model_name":
      "AMD EPYC", "cpu_family": 26, "model": 2, "vector_extensions": ["avx2", "avx512f"]}, "pages": {"glibc_tunables":
      "glibc.malloc.hugetlb=1", "transparent_huge_pages": null}})"));
  const auto files = json["output_files"].get<std::vector<std::string>>();
  for (const char* expected : {"stand.pvd", "stand/stand_age_0010.vtm", "stand/stand_age_0015.vtm",
                               "stand_table.csv", "trees.csv", "events.csv", "run.json"}) {
    EXPECT_NE(std::find(files.begin(), files.end(), expected), files.end()) << expected;
  }
  for (const std::string& file : files) EXPECT_TRUE(fs::is_regular_file(root_ / file)) << file;
  const auto manifest_time = fs::last_write_time(root_ / "run.json");
  for (const std::string& file : files) EXPECT_LE(fs::last_write_time(root_ / file), manifest_time) << file;
}

TEST_F(StandOutputRun, StandTableHasTheWholeStandThenEachSpeciesEveryYearWithThatYearsFlows) {
  {
    StandOutput out({root_, false, 100.0});  // 0.01 ha: one tree is 100 stems/ha
    run_two_output_years(out);
    out.finish(example_manifest());
  }
  const auto records = testing::parse_csv(read_text(root_ / "stand_table.csv"));
  ASSERT_EQ(records.size(), 1u + 6 * 3) << "six years, each the whole stand and two species";
  for (const auto& record : records) EXPECT_EQ(record.size(), records[0].size());
  EXPECT_EQ((std::vector<std::string>{records[1][2], records[2][2], records[3][2]}),
            (std::vector<std::string>{"all", "karamatsu", "todomatsu"}));

  const auto rows = stand_rows(root_ / "stand_table.csv");
  EXPECT_EQ(rows.at({10, "all"}).at("year_index"), "0");
  EXPECT_EQ(rows.at({10, "all"}).at("stems_per_ha"), "300.000");
  EXPECT_EQ(rows.at({10, "karamatsu"}).at("stems_per_ha"), "100.000");
  EXPECT_EQ(rows.at({10, "all"}).at("cai_m3_per_ha"), "") << "no year before the survey";
  // Year 2: the Karamatsu is thinned, in its own row and the stand's, not in the Todomatsu's.
  EXPECT_EQ(rows.at({12, "all"}).at("removed_stems_per_ha"), "100.000");
  EXPECT_EQ(rows.at({12, "all"}).at("removed_basal_area_m2_per_ha"), "3.142");  // π (0.10 m)² / 0.01 ha
  EXPECT_EQ(rows.at({12, "all"}).at("removed_volume_m3_per_ha"), "20.000");     // 0.2 m³ / 0.01 ha
  EXPECT_EQ(rows.at({12, "karamatsu"}).at("removed_stems_per_ha"), "100.000");
  EXPECT_EQ(rows.at({12, "todomatsu"}).at("removed_stems_per_ha"), "0.000");
  EXPECT_EQ(rows.at({13, "all"}).at("removed_stems_per_ha"), "0.000") << "a flow is its year's only";
  EXPECT_EQ(rows.at({14, "all"}).at("dead_suppression_stems_per_ha"), "100.000");
  EXPECT_EQ(rows.at({14, "todomatsu"}).at("dead_stems_per_ha"), "100.000");
  // Year 5, age 15: one tree alive (8 m tall, 0.064 m³); production keeps the 0.2 m³ cut and the 0.05 m³ dead.
  const auto& last = rows.at({15, "all"});
  EXPECT_EQ(last.at("year_index"), "5");
  EXPECT_EQ(last.at("stems_per_ha"), "100.000");
  EXPECT_EQ(last.at("top_height_m"), "8.000");
  EXPECT_EQ(last.at("hg_m"), "8.000");
  EXPECT_EQ(last.at("total_production_m3_per_ha"), "31.400");  // 6.4 + 20 + 5
  EXPECT_EQ(last.at("mai_m3_per_ha"), "2.093");               // 31.4 / 15
  const auto& gone = rows.at({15, "karamatsu"});
  EXPECT_EQ(gone.at("stems_per_ha"), "0.000");
  EXPECT_EQ(gone.at("qmd_cm"), "") << "no living Karamatsu: no mean diameter";
  EXPECT_EQ(gone.at("total_production_m3_per_ha"), "20.000");
}

TEST_F(StandOutputRun, TreesAndEventsTablesRoundTripTheirLabels) {
  {
    StandOutput out({root_, false, 100.0});
    run_two_output_years(out);
    out.finish(example_manifest());
  }
  const auto trees = testing::parse_csv(read_text(root_ / "trees.csv"));
  ASSERT_EQ(trees.size(), 1u + 3 + 2);  // header, 3 trees at age 10, 2 at age 15
  EXPECT_EQ(trees[2][2], "A,2");
  EXPECT_EQ(trees[3][2], "B \"3\"");
  EXPECT_EQ(trees[5][5], "dead");
  const auto leaf_balls = std::find(trees[0].begin(), trees[0].end(), "leaf_balls") - trees[0].begin();
  ASSERT_LT(static_cast<std::size_t>(leaf_balls), trees[0].size());
  EXPECT_EQ(trees[1][leaf_balls], std::to_string(testing::synthetic_ball_count(6)));
  const auto age = std::find(trees[0].begin(), trees[0].end(), "age") - trees[0].begin();
  EXPECT_EQ(trees[1][age], "12") << "a whole number of years (the synthetic tree of height 6 is 12 years old)";
  const auto events = testing::parse_csv(read_text(root_ / "events.csv"));
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[1], (std::vector<std::string>{"12", "2", "A,2", "karamatsu", "removed", "thinning",
                                                 "thinning:low", "20.00", "14.000", "0.2000"}));
  EXPECT_EQ(events[2][4], "died");
  EXPECT_EQ(events[2][5], "suppression");
}

TEST_F(StandOutputRun, AnAbortedRunKeepsItsTablesButHasNoRunJson) {
  try {
    StandOutput out({root_, false, 100.0});
    run_two_output_years(out);
    throw std::runtime_error("simulated crash");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(root_ / "run.json"));
  EXPECT_TRUE(fs::exists(root_ / "stand_table.csv"));
  EXPECT_EQ(testing::parse_csv(read_text(root_ / "stand_table.csv")).size(), 1u + 6 * 3);
  EXPECT_FALSE(has_temporaries(root_));
}

TEST_F(StandOutputRun, TablesOnlyWhenVtkIsOff) {
  {
    StandOutput out({root_, false, 100.0, false});
    run_two_output_years(out);
    out.finish(example_manifest());
  }
  EXPECT_FALSE(fs::exists(root_ / "stand.pvd"));
  EXPECT_FALSE(fs::exists(root_ / "stand"));
  EXPECT_TRUE(fs::exists(root_ / "trees.csv"));
}

TEST_F(StandOutputRun, ABadPlotAreaIsRefusedBeforeTheFolderIsTouched) {
  EXPECT_THROW(StandOutput({root_, false, 0.0}), std::invalid_argument);
  EXPECT_FALSE(fs::exists(root_));
}

TEST_F(StandOutputRun, ANonEmptyFolderIsRefusedAndLeftAlone) {
  fs::create_directories(root_);
  std::ofstream(root_ / "field_notes.txt") << "plot 3";
  EXPECT_THROW(StandOutput({root_, false, 100.0}), OutputFolderError);
  EXPECT_EQ(read_text(root_ / "field_notes.txt"), "plot 3");
  EXPECT_EQ(std::distance(fs::directory_iterator(root_), fs::directory_iterator()), 1);
}

TEST_F(StandOutputRun, ATableThatCannotBeWrittenStopsTheRunThatYearNamingItAndTheReason) {
  std::string message;
  int failed_in_year = -1;
  {
    StandOutput out({root_, false, 100.0, false});
    out.write_stand_rows(inventory_of(stand_in_year(0).snapshot));
    out.write_year(stand_in_year(0).snapshot);
    out.write_stand_rows(inventory_of(stand_in_year(1).snapshot));
    testing::FileSizeLimit full_disk;
    for (int year = 2; year <= 5 && failed_in_year < 0; ++year) {
      try {
        out.write_stand_rows(inventory_of(stand_in_year(year).snapshot));
      } catch (const OutputFolderError& e) {
        message = e.what();
        failed_in_year = year;
      }
    }
  }  // the run unwinds: the tables that closed whole are kept, the failed one is not
  EXPECT_EQ(failed_in_year, 2) << "the first year whose rows could not be written must stop the run";
  EXPECT_EQ(message, "cannot write " + (root_ / "stand_table.csv").string() + ": " + std::strerror(EFBIG));
  EXPECT_FALSE(fs::exists(root_ / "stand_table.csv")) << "a table missing rows must not appear under its name";
  EXPECT_TRUE(fs::exists(root_ / "trees.csv")) << "the tables that were written whole are kept";
  EXPECT_TRUE(fs::exists(root_ / "events.csv"));
  EXPECT_FALSE(fs::exists(root_ / "run.json"));
  EXPECT_FALSE(has_temporaries(root_));
}

// Writes the tiny two-year stand the ParaView render checks (tests/scripts/paraview.cmake) open; its third tree
// is thinned in the second year (written once more, removed, with the crown it had).
// Disabled in the ordinary run; CTest calls it explicitly as the fixture of those checks.
TEST(ParaViewFixture, DISABLED_WriteTinyStand) {
  const fs::path root = fs::path(HELIOSTAND_BINARY_DIR) / "tests" / "paraview" / "tiny_stand";
  fs::create_directories(root.parent_path());
  StandOutput out({root, true, 100.0});
  const auto young = testing::make_synthetic_stand(10, 0);
  out.write_year(young.snapshot);
  auto older = testing::make_synthetic_stand(16, 6);
  TreeSnapshot& thinned = older.snapshot.trees[2];
  thinned.status = TreeStatus::removed;
  thinned.gone_at_age = 16;
  thinned.status_reason = "first thinning";
  thinned.crown_when_gone = std::move(thinned.leaf_balls);
  thinned.leaf_balls.clear();
  thinned.leaf_ball_light.clear();
  out.write_year(older.snapshot);
  out.finish(example_manifest());
  EXPECT_TRUE(fs::exists(root / "stand.pvd"));
}

}  // namespace
}  // namespace heliostand
