// The levels of detail of the yearly VTK multiblock (run.detail, docs/formats.md): which blocks each level
// writes, that a crown envelope is closed and encloses the tree's foliage, that a cone spans the crown, that the
// per-tree attributes are on every cell, that the sizes written are stated, and that roots can skip years.
#include "io/vtk_time_series_writer.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "core/parallel_for.hpp"
#include "io/captured_log.hpp"
#include "io/open_edges.hpp"
#include "io/read_multiblock.hpp"
#include "io/synthetic_stand.hpp"
#include "io/temp_folder.hpp"
#include "io/tree_cell_data.hpp"
#include "io/vtk_crown_blocks.hpp"
#include "io/vtk_numbers.hpp"

namespace heliostand {
namespace {
namespace fs = std::filesystem;

std::vector<std::string> block_names(const fs::path& vtm) {
  const vtkSmartPointer<vtkMultiBlockDataSet> multiblock = testing::read_multiblock(vtm);
  std::vector<std::string> names;
  for (unsigned i = 0; i < multiblock->GetNumberOfBlocks(); ++i)
    if (multiblock->GetBlock(i) != nullptr)  // an empty block is an unnamed placeholder in the file
      names.emplace_back(multiblock->GetMetaData(i)->Get(vtkCompositeDataSet::NAME()));
  return names;
}

// The cells of `block` that belong to tree `id`, as their own polydata with only the points they use.
vtkSmartPointer<vtkPolyData> tree_cells_of(vtkPolyData& block, int id) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto tree = vtkSmartPointer<vtkPolyData>::New();
  tree->AllocateEstimate(block.GetNumberOfCells(), 4);
  std::map<vtkIdType, vtkIdType> renumbered;
  vtkDataArray* ids = block.GetCellData()->GetArray("tree_id");
  for (vtkIdType c = 0; c < block.GetNumberOfCells(); ++c) {
    if (static_cast<int>(ids->GetTuple1(c)) != id) continue;
    vtkIdList* corners = block.GetCell(c)->GetPointIds();
    std::vector<vtkIdType> local;
    for (vtkIdType k = 0; k < corners->GetNumberOfIds(); ++k) {
      const vtkIdType p = corners->GetId(k);
      auto [it, added] = renumbered.emplace(p, points->GetNumberOfPoints());
      if (added) points->InsertNextPoint(block.GetPoint(p));
      local.push_back(it->second);
    }
    tree->InsertNextCell(block.GetCellType(c), static_cast<vtkIdType>(local.size()), local.data());
  }
  tree->SetPoints(points);
  return tree;
}

class LevelsOfDetail : public ::testing::Test {
 protected:
  LevelsOfDetail() : tmp_("vtk_levels_of_detail"), folder_(tmp_.path() / "run", false) {}
  testing::TempFolder tmp_;
  OutputFolder folder_;
  testing::SyntheticStand stand_ = testing::make_synthetic_stand(16, 0);  // trees of 9, 8 and 7 m

  // The envelope block of the first tree alone, its leaf balls replaced by `balls`, and what the log said meanwhile.
  struct LoneEnvelope {
    vtkSmartPointer<vtkPolyData> block;
    std::string log;
  };
  LoneEnvelope lone_envelope(std::vector<LeafBall> balls) {
    stand_.snapshot.trees.resize(1);
    TreeSnapshot& tree = stand_.snapshot.trees[0];
    tree.leaf_balls = std::move(balls);
    tree.leaf_ball_light.assign(tree.leaf_balls.size(), 0.5);
    const testing::CapturedLog log;
    vtkSmartPointer<vtkPolyData> block = build_crown_envelope_block(stand_.snapshot);
    return {block, log.text()};
  }
};

TEST_F(LevelsOfDetail, EachLevelWritesItsBlocks) {
  const std::map<OutputDetail, std::vector<std::string>> expected = {
      // full also has `trunk`, but the synthetic trees have no stem mesh and VTK leaves an empty block out.
      {OutputDetail::full, {"branches", "leaf_balls", "trees", "crown_envelope", "foliage"}},
      {OutputDetail::envelope, {"trees", "stem", "crown_envelope"}},
      {OutputDetail::cone, {"trees", "crown_cone"}}};
  for (const auto& [detail, names] : expected) {
    OutputFolder folder(tmp_.path() / std::string(name_of(detail)), false);
    VtkTimeSeriesWriter writer(folder, stand_blocks(detail));
    const fs::path vtm = folder.path_of(writer.write_year(stand_.snapshot));
    EXPECT_EQ(block_names(vtm), names) << name_of(detail);
  }
}

TEST_F(LevelsOfDetail, EveryTreeHasAClosedEnvelopeAroundAllItsLeafBalls) {
  vtkSmartPointer<vtkPolyData> block = build_crown_envelope_block(stand_.snapshot);
  for (std::size_t i = 0; i < stand_.snapshot.trees.size(); ++i) {
    const TreeSnapshot& tree = stand_.snapshot.trees[i];
    vtkSmartPointer<vtkPolyData> envelope = tree_cells_of(*block, tree.id);
    ASSERT_GT(envelope->GetNumberOfCells(), 20) << "tree " << tree.id;
    EXPECT_EQ(open_edges(*envelope), 0) << "tree " << tree.id << ": the envelope is not closed";
    double bounds[6];
    envelope->GetBounds(bounds);
    for (const LeafBall& ball : tree.leaf_balls)
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LE(bounds[2 * axis], ball.centre[axis] - ball.radius + 1e-6) << "tree " << tree.id;
        EXPECT_GE(bounds[2 * axis + 1], ball.centre[axis] + ball.radius - 1e-6) << "tree " << tree.id;
      }
  }
  // The builder names each cell's tree; the multiblock (build_stand_multiblock) adds the tree attributes from it.
  ASSERT_TRUE(add_tree_cell_data(*block, stand_.snapshot));
  vtkDataArray* light = block->GetCellData()->GetArray("light");
  ASSERT_NE(light, nullptr);
  EXPECT_DOUBLE_EQ(light->GetTuple1(0), 0.5);  // the tree's mean_light
}

// The envelope's corners carry the light of the leaf ball they bound: the top of a crown is its top whorl's light, the
// bottom its lowest living whorl's (the synthetic trees' light grows with height), not the tree's mean.
TEST_F(LevelsOfDetail, AnEnvelopeCornerHasTheLightOfTheBallItBounds) {
  vtkSmartPointer<vtkPolyData> block = build_crown_envelope_block(stand_.snapshot);
  vtkDataArray* light = block->GetPointData()->GetArray("light");
  ASSERT_NE(light, nullptr);
  ASSERT_EQ(light->GetNumberOfTuples(), block->GetNumberOfPoints());
  vtkDataArray* ids = block->GetCellData()->GetArray("tree_id");
  for (const TreeSnapshot& tree : stand_.snapshot.trees) {
    double lowest = 1e9, highest = -1e9, light_low = -1, light_high = -1;
    for (vtkIdType c = 0; c < block->GetNumberOfCells(); ++c) {
      if (static_cast<int>(ids->GetTuple1(c)) != tree.id) continue;
      vtkIdList* corners = block->GetCell(c)->GetPointIds();
      for (vtkIdType k = 0; k < corners->GetNumberOfIds(); ++k) {
        const vtkIdType p = corners->GetId(k);
        const double z = block->GetPoint(p)[2];
        if (z < lowest) lowest = z, light_low = light->GetTuple1(p);
        if (z > highest) highest = z, light_high = light->GetTuple1(p);
      }
    }
    const auto [low, high] = std::minmax_element(tree.leaf_ball_light.begin(), tree.leaf_ball_light.end());
    EXPECT_DOUBLE_EQ(light_high, *high) << "tree " << tree.id;
    EXPECT_DOUBLE_EQ(light_low, *low) << "tree " << tree.id;
    EXPECT_LT(*low, *high) << "tree " << tree.id << ": the synthetic light varies with height";
  }
}

TEST_F(LevelsOfDetail, ATreeWithoutLeafBallsHasNoEnvelope) {
  stand_.snapshot.trees[1].leaf_balls.clear();
  vtkSmartPointer<vtkPolyData> block = build_crown_envelope_block(stand_.snapshot);
  EXPECT_EQ(tree_cells_of(*block, stand_.snapshot.trees[1].id)->GetNumberOfCells(), 0);
  EXPECT_GT(tree_cells_of(*block, stand_.snapshot.trees[0].id)->GetNumberOfCells(), 0);
}

// Six leaf balls of tree P0508 of the hectare benchmark (validation/bench/stands/planted_2500.csv) at age 20, where
// they stand, to the last bit: the fewest of its 224 balls (removed one at a time while it lasted) whose hull corners
// vtkDelaunay3D, which built the envelopes before Qhull, turned into a surface with 4 open edges (8 for all 224). Two
// pairs of whorl balls at one height put corners nearly on one sphere. Moved elsewhere, the same crown came out
// closed: the failure depends on the coordinates' last bits, so the case is kept exactly as it was found.
TEST_F(LevelsOfDetail, TheEnvelopeOfACrownThatDelaunayLeftOpenIsClosed) {
  stand_.snapshot.trees[0].label = "P0508";
  const LoneEnvelope envelope =
      lone_envelope({{{14.107662224025152, 21.167059379668299, 3.6457628902678607}, 0.19048268241177505},
                     {{14.84, 20.870000000000001, 10.5}, 0.59999999999999998},
                     {{15.955488884599101, 20.707406094855013, 3.7995013081778053}, 0.18250361189179987},
                     {{13.795390940655754, 21.293726495265961, 3.7995013081778053}, 0.18250361189180017},
                     {{15.183505312692034, 21.646100243492384, 6.1220915204574631}, 0.2114354424369462},
                     {{15.124624057580993, 20.070427218045332, 6.1220915204574657}, 0.21143544243694856}});
  ASSERT_GT(envelope.block->GetNumberOfCells(), 20);
  EXPECT_EQ(open_edges(*envelope.block), 0);
  EXPECT_EQ(envelope.log, "");  // with vtkDelaunay3D: "warning: … tree 'P0508' is not a closed surface (4 open edges)"
}

// Seven leaf balls on a quarter-metre grid, found by trying when vtkDelaunay3D built the envelopes: their hull's
// corners lie four or more to a plane, and vtkDelaunay3D met a degenerate tetrahedron among them ("1 degenerate
// triangles encountered, mesh quality suspect"), as it did for a few crowns of the example stand. Qhull merges the
// coplanar corners into faces and splits those into triangles: the envelope is closed and the log is silent.
TEST_F(LevelsOfDetail, TheEnvelopeOfCoplanarCornersIsClosedAndQuiet) {
  std::vector<LeafBall> balls;
  for (const glm::dvec3 centre :
       {glm::dvec3(-0.75, -0.5, -1.25), glm::dvec3(-1, -0.25, 1.25), glm::dvec3(-0.5, 0.25, 0.5),
        glm::dvec3(-0.75, -0.5, -0.25), glm::dvec3(0.75, -0.75, 0), glm::dvec3(-0.75, 0, -1.5),
        glm::dvec3(-0.5, 0.75, 1.75)})
    balls.push_back({centre, 0.25});
  const LoneEnvelope envelope = lone_envelope(balls);
  ASSERT_GT(envelope.block->GetNumberOfCells(), 20);
  EXPECT_EQ(open_edges(*envelope.block), 0);
  EXPECT_EQ(envelope.log, "");
}

// Every triangle of an envelope faces out of its crown (geometry/convex_hull.hpp turns them so), so ParaView lights
// the outside of the surface and a Normals filter needs no flipping.
TEST_F(LevelsOfDetail, EveryEnvelopeTriangleFacesOutOfItsCrown) {
  vtkSmartPointer<vtkPolyData> block = build_crown_envelope_block(stand_.snapshot);
  vtkDataArray* ids = block->GetCellData()->GetArray("tree_id");
  ASSERT_NE(ids, nullptr);
  std::map<int, glm::dvec3> crown_centre;
  for (const TreeSnapshot& tree : stand_.snapshot.trees) {
    glm::dvec3 sum(0);
    for (const LeafBall& ball : tree.leaf_balls) sum += ball.centre;
    crown_centre[tree.id] = sum / static_cast<double>(tree.leaf_balls.size());
  }
  ASSERT_GT(block->GetNumberOfCells(), 0);
  for (vtkIdType c = 0; c < block->GetNumberOfCells(); ++c) {
    vtkIdList* corners = block->GetCell(c)->GetPointIds();
    ASSERT_EQ(corners->GetNumberOfIds(), 3);
    glm::dvec3 p[3];
    for (int k = 0; k < 3; ++k) block->GetPoint(corners->GetId(k), &p[k].x);
    const glm::dvec3 normal = glm::cross(p[1] - p[0], p[2] - p[0]);
    EXPECT_GT(glm::dot(normal, p[0] - crown_centre.at(static_cast<int>(ids->GetTuple1(c)))), 0.0) << "cell " << c;
  }
}

// The crowns' pieces are made on the worker threads (io/vtk_crown_blocks.cpp, append_per_tree) and appended in the
// trees' order: the envelope block and the cone block of 24 trees are the same, number for number, on one thread and
// on four, and each tree's cells follow the trees' order.
TEST_F(LevelsOfDetail, TheCrownBlocksAreTheSameOnAnyNumberOfThreads) {
  StandSnapshot many = stand_.snapshot;
  many.trees.clear();
  for (int copy = 0; copy < 8; ++copy)
    for (TreeSnapshot tree : stand_.snapshot.trees) {  // each a copy moved 12 m further east, with its own id
      const glm::dvec3 shift(12.0 * copy, 0.0, 0.0);
      tree.id = static_cast<int>(many.trees.size()) + 1;
      tree.position += shift;
      for (LeafBall& ball : tree.leaf_balls) ball.centre += shift;
      many.trees.push_back(tree);
    }
  for (const auto build : {&build_crown_envelope_block, &build_crown_cone_block}) {
    set_worker_threads(1);
    const std::vector<double> one = testing::numbers_of(*build(many));
    set_worker_threads(4);
    vtkSmartPointer<vtkPolyData> block = build(many);
    set_worker_threads(0);
    EXPECT_EQ(testing::first_difference(testing::numbers_of(*block), one), -1);
    vtkDataArray* ids = block->GetCellData()->GetArray("tree_id");
    ASSERT_NE(ids, nullptr);
    ASSERT_GT(ids->GetNumberOfTuples(), 24);
    for (vtkIdType c = 1; c < ids->GetNumberOfTuples(); ++c) ASSERT_LE(ids->GetTuple1(c - 1), ids->GetTuple1(c));
    EXPECT_EQ(ids->GetTuple1(ids->GetNumberOfTuples() - 1), 24.0);
  }
}

TEST_F(LevelsOfDetail, EachConeSpansItsTreesCrown) {
  vtkSmartPointer<vtkPolyData> block = build_crown_cone_block(stand_.snapshot);
  for (const TreeSnapshot& tree : stand_.snapshot.trees) {
    vtkSmartPointer<vtkPolyData> cone = tree_cells_of(*block, tree.id);
    EXPECT_EQ(cone->GetNumberOfCells(), 9) << "eight sides and a base";
    double bounds[6];
    cone->GetBounds(bounds);
    EXPECT_NEAR(bounds[4], tree.position.z + tree.crown_base_m, 1e-9) << "tree " << tree.id;
    EXPECT_NEAR(bounds[5], tree.position.z + tree.height_m, 1e-9) << "tree " << tree.id;
    EXPECT_NEAR(bounds[1] - tree.position.x, tree.crown_radius_m, 1e-6) << "tree " << tree.id;
    EXPECT_NEAR(tree.position.x - bounds[0], tree.crown_radius_m, 1e-6) << "tree " << tree.id;
  }
}

TEST_F(LevelsOfDetail, TheStemIsTheAxisZeroShootsWithTheirRadius) {
  vtkSmartPointer<vtkPolyData> block = build_stem_block(stand_.snapshot);
  int stem_shoots = 0;
  for (int height : stand_.heights) stem_shoots += height;  // one-metre stem shoots
  EXPECT_EQ(block->GetNumberOfLines(), stem_shoots);
  ASSERT_TRUE(add_tree_cell_data(*block, stand_.snapshot));  // as build_stand_multiblock does
  for (const char* name : {"tree_id", "status", "habitat_tree", "light"}) {
    ASSERT_NE(block->GetCellData()->GetArray(name), nullptr) << name;
    EXPECT_EQ(block->GetCellData()->GetArray(name)->GetNumberOfTuples(), stem_shoots) << name;
  }
}

TEST_F(LevelsOfDetail, TheSizesOfEveryBlockAndYearAreStated) {
  VtkTimeSeriesWriter writer(folder_, stand_blocks(OutputDetail::envelope));
  const fs::path first = folder_.path_of(writer.write_year(stand_.snapshot));
  const auto later = testing::make_synthetic_stand(18, 2);
  writer.write_year(later.snapshot);
  std::ifstream csv(folder_.path_of(VtkTimeSeriesWriter::sizes_file));
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(csv, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 7u) << "a header and three blocks in each of two years";
  EXPECT_EQ(rows[0], "stand_age,block,bytes");
  const fs::path pieces = fs::path(first).replace_extension();
  const auto sizes = block_file_sizes(first);
  ASSERT_EQ(sizes.size(), 3u);
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const auto& [block, bytes] = sizes[i];
    EXPECT_EQ(rows[1 + i], fmt::format("16,{},{}", block, bytes));
    EXPECT_EQ(bytes, fs::file_size(pieces / fmt::format("stand_age_0016_{}.vtp", i))) << block;
  }
  EXPECT_EQ(rows[4].substr(0, 9), "18,trees,");
}

TEST_F(LevelsOfDetail, ABlockWithAnAgeMultipleIsWrittenOnlyInThoseYears) {
  VtkTimeSeriesWriter writer(folder_, stand_blocks(OutputDetail::cone));
  writer.add_block({"roots", [](const StandSnapshot& s) -> vtkSmartPointer<vtkDataObject> { return build_trees_block(s); },
                    10});
  const auto at_16 = block_names(folder_.path_of(writer.write_year(stand_.snapshot)));
  const auto stand_20 = testing::make_synthetic_stand(20, 4);
  const auto at_20 = block_names(folder_.path_of(writer.write_year(stand_20.snapshot)));
  EXPECT_EQ(at_16, (std::vector<std::string>{"trees", "crown_cone"}));
  EXPECT_EQ(at_20, (std::vector<std::string>{"trees", "crown_cone", "roots"}));
}

}  // namespace
}  // namespace heliostand
