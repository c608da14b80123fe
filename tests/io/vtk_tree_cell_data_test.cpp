// The per-tree attributes on every block of the yearly multiblock (io/tree_cell_data.hpp, issue 15): every cell of
// every tree block carries them, one value per cell, whatever says which tree the cell is (a cell or a point
// `tree_id`); and a tree thinned in an output year is in that year's blocks, crown included, marked removed.
#include "io/tree_cell_data.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>

#include "io/read_multiblock.hpp"
#include "io/stand_output.hpp"
#include "io/synthetic_stand.hpp"
#include "io/temp_folder.hpp"
#include "io/vtk_stand_blocks.hpp"
#include "io/vtk_time_series_writer.hpp"
#include "light/reference_light_solver.hpp"
#include "stand/stand.hpp"
#include "stand/stand_year.hpp"

namespace heliostand {
namespace {
namespace fs = std::filesystem;

const char* const tree_arrays[] = {"tree_id", "status", "habitat_tree", "light", "species", "removal_age",
                                   "removal_reason"};

using testing::read_multiblock;

// name → block, for the non-empty blocks of a multiblock.
std::map<std::string, vtkPolyData*> blocks_of(vtkMultiBlockDataSet& multiblock) {
  std::map<std::string, vtkPolyData*> blocks;
  for (unsigned i = 0; i < multiblock.GetNumberOfBlocks(); ++i)
    if (auto* block = vtkPolyData::SafeDownCast(multiblock.GetBlock(i)))
      blocks[multiblock.GetMetaData(i)->Get(vtkCompositeDataSet::NAME())] = block;
  return blocks;
}

// The trees a block draws cells for, by status.
std::set<int> trees_with_status(vtkPolyData& block, int status) {
  std::set<int> trees;
  vtkDataArray* ids = block.GetCellData()->GetArray("tree_id");
  vtkDataArray* statuses = block.GetCellData()->GetArray("status");
  for (vtkIdType c = 0; c < block.GetNumberOfCells(); ++c)
    if (static_cast<int>(statuses->GetTuple1(c)) == status) trees.insert(static_cast<int>(ids->GetTuple1(c)));
  return trees;
}

// A stem mesh of one triangle per tree, enough for the `trunk` block to draw the tree (its tree_id is point data).
std::shared_ptr<const hollow::HollowMesh> one_triangle() {
  auto mesh = std::make_shared<hollow::HollowMesh>();
  mesh->vertices = {{0, 0, 0}, {0.1, 0, 0}, {0, 0, 1}};
  mesh->triangles = {{0, 1, 2}};
  mesh->part = {0, 0, 0};
  mesh->callus_thickness_m = mesh->bark_shift_m = mesh->bark_lift_m = {0, 0, 0};
  mesh->bark_line = {0, 0, 0};
  return mesh;
}

TEST(TreeCellData, EveryBlockOfEveryLevelCarriesTheTreeAttributesOnEveryCell) {
  testing::TempFolder tmp("vtk_tree_cell_data");
  testing::SyntheticStand stand = testing::make_synthetic_stand(16, 0);
  for (TreeSnapshot& tree : stand.snapshot.trees) tree.trunk = one_triangle();
  TreeSnapshot& thinned = stand.snapshot.trees[1];
  thinned.status = TreeStatus::removed;
  thinned.gone_at_age = stand.snapshot.stand_age;
  thinned.status_reason = "first thinning";
  thinned.crown_when_gone = thinned.leaf_balls;
  thinned.leaf_balls.clear();
  thinned.leaf_ball_light.clear();
  stand.snapshot.trees[2].species = "karamatsu";

  for (OutputDetail detail : {OutputDetail::full, OutputDetail::envelope, OutputDetail::cone}) {
    OutputFolder folder(tmp.path() / std::string(name_of(detail)), false);
    VtkTimeSeriesWriter writer(folder, stand_blocks(detail));
    const fs::path vtm = folder.path_of(writer.write_year(stand.snapshot));
    vtkSmartPointer<vtkMultiBlockDataSet> multiblock = read_multiblock(vtm);
    const auto blocks = blocks_of(*multiblock);
    ASSERT_GE(blocks.size(), 2u) << name_of(detail);
    for (const auto& [name, block] : blocks) {
      SCOPED_TRACE(std::string(name_of(detail)) + " / " + name);
      ASSERT_GT(block->GetNumberOfCells(), 0);
      for (const char* array : tree_arrays) {
        vtkDataArray* values = block->GetCellData()->GetArray(array);
        ASSERT_NE(values, nullptr) << array;
        EXPECT_EQ(values->GetNumberOfTuples(), block->GetNumberOfCells()) << array;
      }
      EXPECT_EQ(trees_with_status(*block, -1), std::set<int>{}) << "every cell is one of the snapshot's trees";
      // Each tree's cells carry its own attributes.
      vtkCellData& cells = *block->GetCellData();
      auto* species_names = vtkStringArray::SafeDownCast(block->GetFieldData()->GetAbstractArray("species_names"));
      auto* reasons = vtkStringArray::SafeDownCast(block->GetFieldData()->GetAbstractArray("removal_reasons"));
      ASSERT_NE(species_names, nullptr);
      ASSERT_NE(reasons, nullptr);
      for (vtkIdType c = 0; c < block->GetNumberOfCells(); ++c) {
        const int id = static_cast<int>(cells.GetArray("tree_id")->GetTuple1(c));
        const TreeSnapshot* tree = nullptr;
        for (const TreeSnapshot& t : stand.snapshot.trees)
          if (t.id == id) tree = &t;
        ASSERT_NE(tree, nullptr) << "cell " << c << " names tree " << id;
        EXPECT_EQ(cells.GetArray("status")->GetTuple1(c), status_code(tree->status));
        EXPECT_EQ(cells.GetArray("removal_age")->GetTuple1(c), tree->gone_at_age);
        EXPECT_EQ(species_names->GetValue(static_cast<vtkIdType>(cells.GetArray("species")->GetTuple1(c))),
                  tree->species);
        EXPECT_EQ(reasons->GetValue(static_cast<vtkIdType>(cells.GetArray("removal_reason")->GetTuple1(c))),
                  tree->status_reason);
      }
    }
    // The thinned tree's crown is drawn in the year it goes, marked removed.
    const char* crowns = detail == OutputDetail::cone ? "crown_cone" : "crown_envelope";
    ASSERT_TRUE(blocks.count(crowns)) << name_of(detail);
    EXPECT_EQ(trees_with_status(*blocks.at(crowns), status_code(TreeStatus::removed)), std::set<int>{thinned.id})
        << name_of(detail);
  }
}

TEST(TreeCellData, ABlockThatNamesItsTreesByPointGetsThemPerCell) {
  // Like `roots`: one line per segment, tree_id as point data.
  testing::SyntheticStand stand = testing::make_synthetic_stand(16, 0);
  auto block = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto tree_id = vtkSmartPointer<vtkIntArray>::New();
  tree_id->SetName("tree_id");
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (const TreeSnapshot& tree : stand.snapshot.trees) {
    const vtkIdType ends[2] = {points->InsertNextPoint(0, 0, 0), points->InsertNextPoint(0, 0, -1)};
    tree_id->InsertNextValue(tree.id);
    tree_id->InsertNextValue(tree.id);
    lines->InsertNextCell(2, ends);
  }
  block->SetPoints(points);
  block->SetLines(lines);
  block->GetPointData()->AddArray(tree_id);
  ASSERT_TRUE(add_tree_cell_data(*block, stand.snapshot));
  for (vtkIdType c = 0; c < block->GetNumberOfCells(); ++c)
    EXPECT_EQ(block->GetCellData()->GetArray("tree_id")->GetTuple1(c), stand.snapshot.trees[c].id);

  auto soil = vtkSmartPointer<vtkPolyData>::New();  // no tree_id: not a tree block
  EXPECT_FALSE(add_tree_cell_data(*soil, stand.snapshot));
}

// The whole path from the stand: a tree thinned at 22 is written at 22 with its crown, marked removed with the
// age and the reason, and is gone from every block at 23.
TEST(TreeCellData, AThinnedTreeIsDrawnAndMarkedInItsRemovalYearOnly) {
  testing::TempFolder tmp("vtk_tree_cell_data_thinned");
  auto planted = [](int id, const char* species, glm::dvec3 position) {
    ConiferTree tree(SpeciesParameters{}, TreeCalibration{}, position, 3, id);
    tree.grow_to_age(8);
    return StandTree{id, std::to_string(id + 1), species, std::move(tree)};
  };
  std::vector<StandTree> trees;
  trees.push_back(planted(0, "todomatsu", {2, 2, 0}));
  trees.push_back(planted(1, "karamatsu", {6, 3, 0}));
  trees.push_back(planted(2, "todomatsu", {4, 7, 0}));
  const ThinningEvent thin_larch{{22}, ThinningRule{ThinningMethod::ids, {"2"}, {}, {}}, "first thinning", true};
  Stand stand(0.01, 20, std::move(trees), {thin_larch});
  LightParameters sky;
  sky.sky_bands = 4;
  sky.sky_sectors = 8;
  ReferenceLightSolver solver(sky);
  StageClock clock;
  StandOutputOptions options{tmp.path() / "run", false, 100.0, true};
  options.detail = OutputDetail::envelope;
  StandOutput output(options);
  StandYear simulated_year(stand, solver, solver, nullptr, &output, {3, 1.0, 3, 1}, clock);  // written every year
  for (int year = 0; year <= 3; ++year) simulated_year.run(year);
  output.finish(RunManifest{});

  const int larch = 1;
  auto at_22 = read_multiblock(tmp.path() / "run" / "stand" / "stand_age_0022.vtm");
  for (const auto& [name, block] : blocks_of(*at_22)) {
    SCOPED_TRACE(name);
    EXPECT_EQ(trees_with_status(*block, status_code(TreeStatus::removed)), std::set<int>{larch});
    EXPECT_EQ(trees_with_status(*block, status_code(TreeStatus::alive)), (std::set<int>{0, 2}));
    vtkCellData& cells = *block->GetCellData();
    auto* reasons = vtkStringArray::SafeDownCast(block->GetFieldData()->GetAbstractArray("removal_reasons"));
    for (vtkIdType c = 0; c < block->GetNumberOfCells(); ++c) {
      if (cells.GetArray("tree_id")->GetTuple1(c) != larch) continue;
      EXPECT_EQ(cells.GetArray("removal_age")->GetTuple1(c), 22);
      EXPECT_EQ(reasons->GetValue(static_cast<vtkIdType>(cells.GetArray("removal_reason")->GetTuple1(c))),
                "first thinning");
    }
  }
  EXPECT_TRUE(blocks_of(*at_22).count("crown_envelope"));

  auto at_23 = read_multiblock(tmp.path() / "run" / "stand" / "stand_age_0023.vtm");
  for (const auto& [name, block] : blocks_of(*at_23)) {
    SCOPED_TRACE(name);
    EXPECT_EQ(trees_with_status(*block, status_code(TreeStatus::alive)), (std::set<int>{0, 2}));
    EXPECT_EQ(trees_with_status(*block, status_code(TreeStatus::removed)), std::set<int>{});
  }
}

}  // namespace
}  // namespace heliostand
