// `heliostand grow` with roots: a one-year run of four trees writes roots and soil blocks and the root
// columns of trees.csv; with [roots] enabled = false it writes neither.
#include <gtest/gtest.h>

#include <fstream>

#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "cli/cli_runner.hpp"
#include "io/csv_test_reader.hpp"
#include "io/read_multiblock.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

const std::string four_trees =
    "id,x,y,height,dbh,crown_radius,crown_base\n"
    "1,2,2,4,5,0.8,1.5\n2,7,2,4.5,5.5,0.9,1.6\n3,2,7,3.8,4.8,0.7,1.4\n4,7,7,4.2,5.2,0.8,1.5\n";

fs::path write_stand(const std::string& name, const std::string& extra) {
  const fs::path folder = scratch_folder(name);
  fs::create_directories(folder);
  std::ofstream(folder / "survey.csv") << four_trees;
  std::ofstream(folder / "scenario.toml")
      << "[stand]\nsurvey = \"survey.csv\"\nage_at_survey = 10\nx_min = 0\ny_min = 0\nx_max = 10\ny_max = 10\n"
         "[run]\nyears = 1\nseed = 3\n[light]\nsky_bands = 8\nsky_sectors = 16\n"
      << extra;
  return folder;
}

vtkDataObject* named_block(vtkMultiBlockDataSet* multiblock, const std::string& name) {
  for (unsigned i = 0; i < multiblock->GetNumberOfBlocks(); ++i) {
    const char* block_name = multiblock->GetMetaData(i)->Get(vtkCompositeDataSet::NAME());
    if (block_name != nullptr && name == block_name) return multiblock->GetBlock(i);
  }
  return nullptr;
}

vtkSmartPointer<vtkMultiBlockDataSet> read_year(const fs::path& out, const std::string& file) {
  return testing::read_multiblock(out / "stand" / file);
}

TEST(RootsCli, RootsAndSoilAreWrittenWithTheTrees) {
  const fs::path folder = write_stand("roots_cli_on", "[soil]\nnutrient = 0.5\n");
  const fs::path out = folder / "out";
  const auto run = run_cli("grow " + (folder / "scenario.toml").string() + " --out " + out.string() +
                           " --device reference -q");
  ASSERT_EQ(run.status, 0) << run.output;
  const auto rows = parse_csv(read_text(out / "trees.csv"));
  ASSERT_EQ(rows.size(), 9u);  // header + 4 trees × 2 output years
  const auto& header = rows[0];
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  for (std::size_t r = 1; r < rows.size(); ++r) {
    EXPECT_GT(std::stod(rows[r].at(column("root_length_m"))), 10.0);  // a 10-year tap-rooted tree: tens of metres
    EXPECT_GT(std::stod(rows[r].at(column("root_max_depth_m"))), 0.5);
    EXPECT_GT(std::stod(rows[r].at(column("root_uptake"))), 0.0);
  }
  const auto year = read_year(out, "stand_age_0011.vtm");
  ASSERT_NE(year, nullptr);
  auto* roots = vtkPolyData::SafeDownCast(named_block(year, "roots"));
  ASSERT_NE(roots, nullptr);
  EXPECT_GT(roots->GetNumberOfCells(), 400);
  for (const char* array : {"radius"}) EXPECT_NE(roots->GetPointData()->GetArray(array), nullptr) << array;
  auto* soil = vtkImageData::SafeDownCast(named_block(year, "soil"));
  ASSERT_NE(soil, nullptr);
  // 10 m × 10 m × 3 m at 0.5 m: 21 × 21 × 7 vertices; nutrient 0.5 except where roots took some up.
  EXPECT_EQ(soil->GetNumberOfPoints(), 21 * 21 * 7);
  double range[2];
  soil->GetPointData()->GetArray("nutrient")->GetRange(range);
  EXPECT_LE(range[1], 0.5 + 1e-9);
  EXPECT_LT(range[0], 0.5);
}

TEST(RootsCli, SwitchedOffWritesNoRoots) {
  const fs::path folder = write_stand("roots_cli_off", "[roots]\nenabled = false\n");
  const fs::path out = folder / "out";
  const auto run = run_cli("grow " + (folder / "scenario.toml").string() + " --out " + out.string() +
                           " --device reference -q");
  ASSERT_EQ(run.status, 0) << run.output;
  const auto rows = parse_csv(read_text(out / "trees.csv"));
  ASSERT_EQ(rows.size(), 9u);
  const std::size_t c = static_cast<std::size_t>(std::find(rows[0].begin(), rows[0].end(), "root_length_m") - rows[0].begin());
  for (std::size_t r = 1; r < rows.size(); ++r) EXPECT_EQ(rows[r].at(c), "");
  const auto year = read_year(out, "stand_age_0011.vtm");
  ASSERT_NE(year, nullptr);
  EXPECT_EQ(named_block(year, "roots"), nullptr);
  EXPECT_EQ(named_block(year, "soil"), nullptr);
}

}  // namespace
}  // namespace heliostand::testing
