// End-to-end runs of `heliostand grow` and `heliostand check` on the example stands, as a user runs them.
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkFieldData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <map>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.hpp"
#include "compute/device_choice.hpp"
#include "io/csv_test_reader.hpp"
#include "io/read_multiblock.hpp"
#include "tiny_stand_scenario.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

// The tiny stand: 8 trees on 0.01 ha, age 20 → 25, tree "4" removed at age 23 (stands/tiny/README.md).
const std::string tiny_scenario = source_path("stands/tiny/scenario.toml").string();

// Each CTest process is one TEST, so a run shared by several checks lives inside one TEST: the tiny
// stand is grown once with the reference solver and every output aspect is checked on that run.
CliResult grow_tiny(const fs::path& folder, const std::string& extra) {
  return run_cli("grow " + tiny_scenario + " --out " + folder.string() + " " + extra + " -q");
}

std::vector<std::map<std::string, std::string>> read_table(const fs::path& path) {
  const auto records = parse_csv(read_text(path));
  std::vector<std::map<std::string, std::string>> rows;
  for (std::size_t r = 1; r < records.size(); ++r) {
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < records[0].size() && c < records[r].size(); ++c) row[records[0][c]] = records[r][c];
    rows.push_back(row);
  }
  return rows;
}

vtkSmartPointer<vtkMultiBlockDataSet> read_year(const fs::path& folder, int stand_age) {
  char name[32];
  std::snprintf(name, sizeof name, "stand_age_%04d.vtm", stand_age);
  return testing::read_multiblock(folder / "stand" / name);
}

vtkPolyData* block(vtkMultiBlockDataSet* multiblock, const std::string& name) {
  for (unsigned i = 0; i < multiblock->GetNumberOfBlocks(); ++i) {
    const char* block_name = multiblock->GetMetaData(i)->Get(vtkCompositeDataSet::NAME());
    if (block_name != nullptr && name == block_name) return vtkPolyData::SafeDownCast(multiblock->GetBlock(i));
  }
  return nullptr;
}

}  // namespace

void check_every_output_written(const fs::path& folder) {
  for (const char* file : {"stand.pvd", "stand_table.csv", "trees.csv", "events.csv", "run.json"})
    EXPECT_TRUE(fs::exists(folder / file)) << file;
  // run.json is written last: no output file is newer.
  const auto manifest_time = fs::last_write_time(folder / "run.json");
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) EXPECT_LE(entry.last_write_time(), manifest_time) << entry.path();
  EXPECT_NE(read_text(folder / "run.json").find("\"light\""), std::string::npos) << "light time in run.json";
}

// run.json records the run a user would need to reproduce and judge it: the command, the scenario, the seed, the
// device, the ages grown, when and for how long, and where the time went.
void check_run_record(const fs::path& folder) {
  const auto record = nlohmann::json::parse(read_text(folder / "run.json"));
  EXPECT_NE(record.at("command_line").get<std::string>().find("grow"), std::string::npos);
  EXPECT_EQ(fs::path(record.at("scenario").get<std::string>()), fs::absolute(tiny_scenario).lexically_normal());
  EXPECT_EQ(record.at("seed").get<std::uint64_t>(), 7u) << "stands/tiny's [run] seed";
  EXPECT_EQ(record.at("device"), "reference");
  EXPECT_EQ(record.at("first_stand_age"), 20);
  EXPECT_EQ(record.at("last_stand_age"), 25);
  EXPECT_LE(record.at("started_utc").get<std::string>(), record.at("finished_utc").get<std::string>());
  const double wall = record.at("wall_seconds").get<double>();
  EXPECT_GT(wall, 0.0);
  double staged = 0;
  for (const char* stage : {"establishment", "roots", "light", "growth"}) {
    ASSERT_TRUE(record.at("stage_seconds").contains(stage)) << stage;
    staged += record.at("stage_seconds").at(stage).get<double>();
  }
  EXPECT_LE(staged, wall) << "the stages are parts of the run's wall time";
}

void check_thinning(const fs::path& folder) {
  const auto events = read_table(folder / "events.csv");
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].at("label"), "4");
  EXPECT_EQ(events[0].at("stand_age"), "23");
  EXPECT_EQ(events[0].at("event"), "removed");
  EXPECT_EQ(events[0].at("species"), "todomatsu");
  EXPECT_EQ(events[0].at("cause"), "thinning") << "the code, whatever the scenario calls the thinning";
  EXPECT_EQ(events[0].at("reason"), "test removal") << "the scenario's label beside the code";
  for (const auto& row : read_table(folder / "trees.csv"))
    EXPECT_EQ(row.at("habitat_tree"), row.at("label") == "5" ? "1" : "0") << "tree " << row.at("label");

  const auto table = read_table(folder / "stand_table.csv");
  ASSERT_EQ(table.size(), 12u) << "ages 20..25, each the whole stand and its one species";
  std::map<int, double> stems, removed;
  for (std::size_t r = 0; r < table.size(); r += 2) {
    const auto& stand = table[r];
    const auto& fir = table[r + 1];
    EXPECT_EQ(stand.at("species"), "all");
    EXPECT_EQ(fir.at("species"), "todomatsu");
    EXPECT_EQ(fir.at("total_production_m3_per_ha"), stand.at("total_production_m3_per_ha")) << "one species is all";
    stems[std::stoi(stand.at("stand_age"))] = std::stod(stand.at("stems_per_ha"));
    removed[std::stoi(stand.at("stand_age"))] = std::stod(stand.at("removed_stems_per_ha"));
  }
  EXPECT_DOUBLE_EQ(stems[22], 800.0);  // 8 trees on 0.01 ha
  EXPECT_DOUBLE_EQ(stems[23], 700.0);
  EXPECT_DOUBLE_EQ(removed[23], 100.0);
  EXPECT_DOUBLE_EQ(removed[24], 0.0);

  // The removed tree appears once, in the year of its removal, and never again.
  int rows_of_removed = 0;
  for (const auto& row : read_table(folder / "trees.csv"))
    if (row.at("label") == "4" && std::stoi(row.at("stand_age")) >= 23) {
      ++rows_of_removed;
      EXPECT_EQ(row.at("status"), "removed");
    }
  EXPECT_EQ(rows_of_removed, 1);
}

void check_vtk_years(const fs::path& folder) {
  const auto last = read_year(folder, 25);
  ASSERT_NE(last, nullptr);
  vtkPolyData* trees = block(last, "trees");
  vtkPolyData* branches = block(last, "branches");
  vtkPolyData* balls = block(last, "leaf_balls");
  ASSERT_NE(trees, nullptr);
  ASSERT_NE(branches, nullptr);
  ASSERT_NE(balls, nullptr);
  EXPECT_EQ(trees->GetNumberOfPoints(), 7) << "8 trees less the one thinned at 23";
  auto* time = last->GetFieldData()->GetArray("TimeValue");
  ASSERT_NE(time, nullptr);
  EXPECT_DOUBLE_EQ(time->GetTuple1(0), 25.0);
  auto* radius = branches->GetPointData()->GetArray("radius");
  ASSERT_NE(radius, nullptr) << "tube radius must be point data";
  EXPECT_EQ(radius->GetNumberOfTuples(), branches->GetNumberOfPoints());
  auto* light = balls->GetPointData()->GetArray("light");
  ASSERT_NE(light, nullptr);
  EXPECT_EQ(light->GetNumberOfTuples(), balls->GetNumberOfPoints());
  EXPECT_GT(balls->GetNumberOfPoints(), 7 * 10) << "every living tree carries foliage";
  double range[2];
  light->GetRange(range);
  EXPECT_GE(range[0], 0.0);
  EXPECT_LE(range[1], 1.0);
  EXPECT_GT(range[1], range[0]) << "leaf balls are not all equally lit";

  const auto first = read_year(folder, 20);
  EXPECT_EQ(block(first, "trees")->GetNumberOfPoints(), 8);

  // Tree "5" carries a hollow (survey column `hollow`): flagged in the trees block, and its callus roll is in
  // the trunk block, on its stem only.
  vtkPolyData* trunk = block(last, "trunk");
  ASSERT_NE(trunk, nullptr);
  auto* part = trunk->GetPointData()->GetArray("part");
  auto* trunk_tree = trunk->GetPointData()->GetArray("tree_id");
  ASSERT_TRUE(part && trunk_tree);
  std::set<int> stems, callus_on;
  for (vtkIdType p = 0; p < trunk->GetNumberOfPoints(); ++p) {
    stems.insert(static_cast<int>(trunk_tree->GetTuple1(p)));
    if (part->GetTuple1(p) == 2) callus_on.insert(static_cast<int>(trunk_tree->GetTuple1(p)));
  }
  EXPECT_EQ(stems.size(), 7u) << "a stem for every standing tree";
  EXPECT_EQ(callus_on, std::set<int>{4}) << "tree_id 4 is survey tree \"5\"";
  auto* habitat = trees->GetPointData()->GetArray("habitat_tree");
  auto* tree_id = trees->GetPointData()->GetArray("tree_id");
  ASSERT_TRUE(habitat && tree_id);
  for (vtkIdType p = 0; p < trees->GetNumberOfPoints(); ++p)
    EXPECT_EQ(habitat->GetTuple1(p), tree_id->GetTuple1(p) == 4 ? 1.0 : 0.0) << "tree_id " << tree_id->GetTuple1(p);
}

// Without an OpenCL device (or in a build without OpenCL) --device opencl must be refused before any output.
void check_opencl_refused() {
  const auto opencl = scratch_folder("tiny_opencl");
  const auto run = grow_tiny(opencl, "--device opencl");
  EXPECT_NE(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("device 'opencl'"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(opencl)) << "no output for a device that does not exist";
}

void check_opencl_agrees(const fs::path& folder) {
  const auto opencl = scratch_folder("tiny_opencl");
  const auto run = grow_tiny(opencl, "--device opencl");
  ASSERT_EQ(run.status, 0) << run.output;
  const auto reference_rows = read_table(folder / "trees.csv");
  const auto opencl_rows = read_table(opencl / "trees.csv");
  ASSERT_EQ(reference_rows.size(), opencl_rows.size());
  for (std::size_t i = 0; i < reference_rows.size(); ++i) {
    // Growth follows light, so these columns agree only as far as trees.csv prints them: in the tiny stand's five
    // years the float OpenCL light (within 2e-4 of the double reference, checked below) moves no printed digit.
    // A real disagreement of the two solvers would; should rounding alone ever flip a digit, compare with tolerances.
    for (const char* column : {"label", "status", "height_m", "dbh_cm", "crown_radius_m", "leaf_balls"})
      EXPECT_EQ(reference_rows[i].at(column), opencl_rows[i].at(column)) << "row " << i << " " << column;
    EXPECT_NEAR(std::stod(reference_rows[i].at("mean_light")), std::stod(opencl_rows[i].at("mean_light")), 2e-4)
        << "row " << i;
  }
}

TEST(GrowCli, TinyStandEndToEnd) {
  const auto folder = scratch_folder("tiny_reference");
  const auto run = grow_tiny(folder, "--device reference");
  ASSERT_EQ(run.status, 0) << run.output;
  {
    SCOPED_TRACE("every output written, run.json last");
    check_every_output_written(folder);
  }
  {
    SCOPED_TRACE("run.json records the run");
    check_run_record(folder);
  }
  {
    SCOPED_TRACE("thinning by id at age 23");
    check_thinning(folder);
  }
  {
    SCOPED_TRACE("VTK years read back");
    check_vtk_years(folder);
  }
  if (compute::opencl_device_exists()) {
    SCOPED_TRACE("OpenCL run agrees with the reference run");
    check_opencl_agrees(folder);
  } else {
    SCOPED_TRACE("no OpenCL device: --device opencl is refused");
    check_opencl_refused();
  }
}

TEST(GrowCli, SameSeedGivesIdenticalTablesAndAnotherSeedDoesNot) {
  const auto first = scratch_folder("tiny_seed_7_a"), again = scratch_folder("tiny_seed_7_b");
  const auto other = scratch_folder("tiny_seed_99");
  ASSERT_EQ(grow_tiny(first, "--device auto").status, 0);
  ASSERT_EQ(grow_tiny(again, "--device auto").status, 0);
  ASSERT_EQ(grow_tiny(other, "--device auto --seed 99").status, 0);
  EXPECT_EQ(read_text(first / "trees.csv"), read_text(again / "trees.csv"));
  EXPECT_EQ(read_text(first / "stand_table.csv"), read_text(again / "stand_table.csv"));
  EXPECT_NE(read_text(first / "trees.csv"), read_text(other / "trees.csv"));
}

TEST(GrowCli, NonEmptyOutputFolderIsRefusedWithoutForce) {
  const auto folder = scratch_folder("tiny_not_empty");
  fs::create_directories(folder);
  std::ofstream(folder / "notes.txt") << "mine\n";
  const auto run = run_cli("grow " + tiny_scenario + " --out " + folder.string() + " --device reference");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("--force"), std::string::npos) << run.output;
  EXPECT_EQ(read_text(folder / "notes.txt"), "mine\n");
  EXPECT_FALSE(fs::exists(folder / "stand.pvd"));
}

TEST(GrowCli, BadSurveyIsRejectedBeforeAnyOutput) {
  const auto folder = scratch_folder("bad_survey");
  const auto run = run_cli("grow " + source_path("stands/bad/scenario_bad_survey.toml").string() + " --out " +
                           folder.string());
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("survey_many_problems.csv:4: column 'height': expected a number > 0, got \"-3\""),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("survey_many_problems.csv:5: column 'id': duplicate id"), std::string::npos);
  EXPECT_FALSE(fs::exists(folder)) << "nothing may be written for bad input";
}

// The crash: a survey height of 1e308 m passed `check` and crashed `grow` with a segmentation fault.
TEST(GrowCli, AnImpossibleSurveyHeightIsBadInputNotACrash) {
  const auto stand = scratch_folder("huge_height_stand");
  fs::create_directories(stand);
  fs::copy_file(source_path("stands/tiny/scenario.toml"), stand / "scenario.toml");
  std::string survey = read_text(source_path("stands/tiny/survey.csv"));
  survey.replace(survey.find("9.2"), 3, "1e308");
  std::ofstream(stand / "survey.csv") << survey;
  const auto folder = scratch_folder("huge_height_out");
  for (const std::string command : {"check", "grow"}) {
    const auto run = run_cli(command + " " + (stand / "scenario.toml").string() +
                             (command == "grow" ? " --out " + folder.string() : ""));
    EXPECT_EQ(run.status, 2) << command << ": " << run.output;
    EXPECT_NE(run.output.find("survey.csv:2: column 'height': 1e+308 m is beyond the plausible limit of 130 m"),
              std::string::npos)
        << command << ": " << run.output;
  }
  EXPECT_FALSE(fs::exists(folder)) << "nothing may be written for bad input";
}

// A far-field table allowed a terabyte (the scenario's limit): with 2 cm cells the run wrote its tables' headers and
// then failed with "error: clCreateBuffer" (exit 1) on a 24 GiB machine, or would have filled a larger one. No
// machine the tests run on holds the 1.8 TiB estimate, so grow refuses the cap before any output, whatever the cells.
// (The default 1 m cells here: were the refusal lost, the tiny stand would grow, and this test fail, in seconds.)
// `check` reads the same scenario as good input and says that grow refuses it here.
TEST(GrowCli, AFarFieldTableCapBeyondTheMachineIsRefusedBeforeAnyOutput) {
  const auto scenario = write_tiny_stand_with_far_field_cap(scratch_folder("huge_table_stand"), 1000000);
  // check reads a scenario written for another machine as good input, and says what grow would do here
  const auto check = run_cli("check " + scenario.string());
  EXPECT_EQ(check.status, 0) << check.output;
  EXPECT_NE(check.output.find("memory     about 1862.7 GiB estimated, of the "), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("GiB this machine lets a run use: grow refuses it here"), std::string::npos)
      << check.output;
  const auto folder = scratch_folder("huge_table_out");
  const auto run = run_cli("grow " + scenario.string() + " --out " + folder.string());
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("scenario.toml: key 'light.far_field_table_mb': a far-field table of up to 1000000 MB"),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(folder)) << "nothing may be written for bad input";
}

TEST(GrowCli, UnknownDeviceIsBadInputAndMissingDeviceWritesNothing) {
  const auto folder = scratch_folder("tiny_bad_device");
  const auto malformed = run_cli("grow " + tiny_scenario + " --out " + folder.string() + " --device gpu");
  EXPECT_EQ(malformed.status, 2) << malformed.output;
  EXPECT_NE(malformed.output.find("device 'gpu'"), std::string::npos) << malformed.output;
  const auto missing = run_cli("grow " + tiny_scenario + " --out " + folder.string() + " --device opencl:99");
  EXPECT_NE(missing.status, 0) << missing.output;
  EXPECT_NE(missing.output.find("99"), std::string::npos) << missing.output;
  EXPECT_FALSE(fs::exists(folder)) << "no output for a device that does not exist";
}

// `grow` on the tiny stand with `flags` is bad input: exit 2, a message naming `named`, no output folder.
static void expect_refused_before_output(const std::string& folder_name, const std::string& flags,
                                         const std::string& named) {
  const auto folder = scratch_folder(folder_name);
  const auto run = run_cli("grow " + tiny_scenario + " --out " + folder.string() + " " + flags);
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find(named), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(folder));
}

// Files may not grow past 4 KiB (the shell's `ulimit -f 4`, its SIGXFSZ ignored), as on a full disk: the first
// table to reach it stops the run that year, with its name and the system's reason; that table is not left under
// its name, the others are, and there is no run.json. (Before, the run went on to its last year and failed at the
// rename with "cannot write OUT/.trees.csv.tmp" and no reason, losing the tables after the failed one.)
TEST(GrowCli, ATableThatCannotBeWrittenStopsTheRunNamingItAndTheReason) {
  const auto folder = scratch_folder("tiny_full_disk");
  const auto run = run_command("bash -c \"trap '' XFSZ; ulimit -f 4; exec " + heliostand_command() +
                               " -q grow " + tiny_scenario + " --device reference --no-vtk --out " + folder.string() + "\"");
  EXPECT_EQ(run.status, 2) << run.output;
  std::set<std::string> tables{"stand_table.csv", "trees.csv", "events.csv"};
  std::string failed;
  for (const std::string& table : tables) {
    if (run.output.find("error: cannot write " + (folder / table).string() + ": File too large") != std::string::npos)
      failed = table;
  }
  ASSERT_NE(failed, "") << run.output;
  tables.erase(failed);
  tables.insert(".heliostand-output");
  EXPECT_EQ(names_in(folder), tables) << "the tables but " << failed << ", and nothing else";
  if (failed != "stand_table.csv") {  // the run stopped in the year it failed, before the tiny stand's last (age 25)
    const auto rows = parse_csv(read_text(folder / "stand_table.csv"));
    ASSERT_GT(rows.size(), 1u);
    EXPECT_LT(std::stoi(rows.back()[0]), 25) << "the run went on after its table failed";
  }
}

TEST(GrowCli, YearsShorterThanAThinningIsBadInput) {
  expect_refused_before_output("tiny_too_short", "--years 2", "run.years");
}

// A negative --seed is refused like a negative run.seed in the scenario, not wrapped to 2^64 - 1.
TEST(GrowCli, NegativeSeedIsBadInput) {
  expect_refused_before_output("tiny_negative_seed", "--seed -1", "--seed");
}

// A thinning on a stand condition that repeats reaches the stand as the scenario gives it. The tiny stand's eight
// trees (7.4 to 10.1 m tall at the survey) are thinned whenever the top height is at least 1 m and three years have
// passed: at the survey's age 20 (a thinning step runs before the first year) and at 23, of ages 20 to 25. Had the
// condition been lost on the way, the rule would have fired on age alone (21 and 24, every three years from 0); had
// the repetition, at 20 only. A second thinning waits for a top height of 40 m and never fires.
TEST(GrowCli, ARepeatingThinningOnAStandConditionFiresEveryThirdYear) {
  const auto output = scratch_folder("tiny_triggered");
  const auto scenario =
      write_tiny_stand_scenario(scratch_folder("tiny_triggered_input"),
                                "[run]\nyears = 5\nseed = 7\noutput_interval = 5\n"
                                "[light]\nsky_bands = 4\nsky_sectors = 8\n"
                                "[roots]\nenabled = false\n"
                                "[[thinning]]\nwhen_top_height_reaches_m = 1.0\nrepeat_every_years = 3\n"
                                "method = \"from_below\"\nremove_fraction = 0.125\nreason = \"repeated low thinning\"\n"
                                "[[thinning]]\nwhen_top_height_reaches_m = 40.0\nmethod = \"from_above\"\n"
                                "remove_fraction = 0.5\nreason = \"never\"\n")
          .string();

  const auto check = run_cli("check " + scenario);
  ASSERT_EQ(check.status, 0) << check.output;
  EXPECT_NE(check.output.find("thinning   when top height >= 1 m, again after 3 years or more: repeated low thinning "
                              "(from_below)"),
            std::string::npos)
      << check.output;

  const auto run = run_cli("grow " + scenario + " --out " + output.string() + " --device reference -q");
  ASSERT_EQ(run.status, 0) << run.output;
  std::map<int, int> removed_at_age;
  for (const auto& event : read_table(output / "events.csv")) {
    if (event.at("event") != "removed") continue;
    ++removed_at_age[std::stoi(event.at("stand_age"))];
    EXPECT_EQ(event.at("reason"), "repeated low thinning");
  }
  // An eighth of the living stems, rounded: one tree of 8 and one of 7.
  EXPECT_EQ(removed_at_age, (std::map<int, int>{{20, 1}, {23, 1}}));
}

TEST(CheckCli, GoodScenarioPrintsASummary) {
  const auto run = run_cli("check " + source_path("stands/sobetsu/scenario.toml").string());
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("62 trees"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("habitat    3 trees with 3 hollows: S15, S20, S22"), std::string::npos) << run.output;
  // grow's estimate (1 GiB + 62 x 1.75 MiB), which every machine the tests run on holds
  EXPECT_NE(run.output.find("memory     about 1.1 GiB estimated, of the "), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("grow refuses it here"), std::string::npos) << run.output;
  // the device grow would open here, which holds the default far-field cap (512 MB)
  EXPECT_NE(run.output.find("\ndevice     "), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("grow refuses light.far_field_table_mb"), std::string::npos) << run.output;
}

TEST(CheckCli, BadKeysAreListedWithTheirPathAndExitTwo) {
  const auto run = run_cli("check " + source_path("stands/bad/scenario_bad_keys.toml").string());
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("key 'stand.colour': unknown key"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("key 'light.transmittance'"), std::string::npos) << run.output;
}

TEST(CheckCli, MissingScenarioFileIsBadInput) {
  const auto run = run_cli("check /nonexistent/scenario.toml");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("/nonexistent/scenario.toml"), std::string::npos) << run.output;
}

TEST(Cli, VersionAndUsageErrors) {
  const auto version = run_cli("--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_NE(version.output.find(HELIOSTAND_VERSION), std::string::npos);
  EXPECT_EQ(run_cli("grow").status, 2) << "missing arguments are a usage error";
  EXPECT_EQ(run_cli("no-such-command").status, 2);
}

}  // namespace heliostand::testing
