// The `foliage` block (detail `full`, docs/formats.md): one needle spray per living foliage-year shoot with a leaf
// ball, none on dead shoots or dead trees, each as wide as its ball and coloured by the ball's light.
#include "io/vtk_foliage_block.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>

#include "io/synthetic_stand.hpp"
#include "io/tree_cell_data.hpp"
#include "io/vtk_stand_blocks.hpp"

namespace heliostand {
namespace {

class FoliageBlock : public ::testing::Test {
 protected:
  testing::SyntheticStand stand_ = testing::make_synthetic_stand(16, 0);  // trees of 9, 8 and 7 m

  int ball_count() const {
    int count = 0;
    for (const TreeSnapshot& tree : stand_.snapshot.trees) count += static_cast<int>(tree.leaf_balls.size());
    return count;
  }
};

// Distance from `p` to the segment base–tip.
double distance_to_shoot(const glm::dvec3& p, const Shoot& shoot) {
  const glm::dvec3 along = shoot.tip - shoot.base;
  const double t = std::clamp(glm::dot(p - shoot.base, along) / glm::dot(along, along), 0.0, 1.0);
  return glm::length(p - (shoot.base + t * along));
}

glm::dvec3 point_of(vtkPolyData& block, vtkIdType id) {
  double p[3];
  block.GetPoint(id, p);
  return {p[0], p[1], p[2]};
}

int cells_of_tree(vtkPolyData& block, int id) {
  vtkDataArray* ids = block.GetCellData()->GetArray("tree_id");
  int count = 0;
  for (vtkIdType c = 0; c < block.GetNumberOfCells(); ++c) count += static_cast<int>(ids->GetTuple1(c)) == id;
  return count;
}

TEST_F(FoliageBlock, OnePiecePerLivingFoliageShootWithALeafBall) {
  vtkSmartPointer<vtkPolyData> block = build_foliage_block(stand_.snapshot);
  ASSERT_GT(ball_count(), 0);
  EXPECT_EQ(block->GetNumberOfStrips(), ball_count());
  EXPECT_EQ(block->GetNumberOfCells(), ball_count()) << "one cell (a triangle strip) per piece, nothing else";
  for (const TreeSnapshot& tree : stand_.snapshot.trees)
    EXPECT_EQ(cells_of_tree(*block, tree.id), static_cast<int>(tree.leaf_balls.size())) << "tree " << tree.id;
  // The builder names each piece's tree; the multiblock (build_stand_multiblock) then adds the tree attributes from it.
  ASSERT_TRUE(add_tree_cell_data(*block, stand_.snapshot));
  // The tree attributes and the needles' age are on every piece.
  for (const char* name : {"tree_id", "status", "habitat_tree", "light", "foliage_age"}) {
    ASSERT_NE(block->GetCellData()->GetArray(name), nullptr) << name;
    EXPECT_EQ(block->GetCellData()->GetArray(name)->GetNumberOfTuples(), ball_count()) << name;
  }
  // The synthetic tree of height h is 2 h years old; its branch of stem node z flushed at age z.
  const TreeSnapshot& first = stand_.snapshot.trees[0];
  const Shoot& shoot = first.shoots[first.leaf_ball_shoot[0]];
  EXPECT_EQ(block->GetCellData()->GetArray("foliage_age")->GetTuple1(0), first.age_years - shoot.year_formed);
}

TEST_F(FoliageBlock, ADeadShootHasNoFoliageEvenWithABall) {
  const int before = build_foliage_block(stand_.snapshot)->GetNumberOfCells();
  TreeSnapshot& tree = stand_.snapshot.trees[1];
  stand_.trees[1].shoots[tree.leaf_ball_shoot[2]].alive = false;  // the snapshot views these shoots
  EXPECT_EQ(build_foliage_block(stand_.snapshot)->GetNumberOfCells(), before - 1);
}

TEST_F(FoliageBlock, DeadAndRemovedTreesHaveNoFoliage) {
  stand_.snapshot.trees[0].status = TreeStatus::dead;  // the leaf balls left in place on purpose
  stand_.snapshot.trees[2].status = TreeStatus::removed;
  vtkSmartPointer<vtkPolyData> block = build_foliage_block(stand_.snapshot);
  EXPECT_EQ(cells_of_tree(*block, stand_.snapshot.trees[0].id), 0);
  EXPECT_EQ(cells_of_tree(*block, stand_.snapshot.trees[2].id), 0);
  EXPECT_EQ(cells_of_tree(*block, stand_.snapshot.trees[1].id),
            static_cast<int>(stand_.snapshot.trees[1].leaf_balls.size()));
}

TEST_F(FoliageBlock, EveryPointCarriesItsBallsLightInZeroToOne) {
  // One ball without a light value: its piece takes its shoot's own light instead of NaN.
  TreeSnapshot& tree = stand_.snapshot.trees[2];
  tree.leaf_ball_light[0] = std::numeric_limits<double>::quiet_NaN();
  stand_.trees[2].shoots[tree.leaf_ball_shoot[0]].light = 0.125;
  vtkSmartPointer<vtkPolyData> block = build_foliage_block(stand_.snapshot);
  vtkDataArray* light = block->GetPointData()->GetArray("light");
  ASSERT_NE(light, nullptr);
  ASSERT_EQ(light->GetNumberOfTuples(), block->GetNumberOfPoints());
  vtkIdType cell = 0;
  for (const TreeSnapshot& t : stand_.snapshot.trees)
    for (std::size_t i = 0; i < t.leaf_balls.size(); ++i, ++cell) {
      const double expected = (&t == &tree && i == 0) ? 0.125 : t.leaf_ball_light[i];
      vtkIdList* corners = block->GetCell(cell)->GetPointIds();
      for (vtkIdType k = 0; k < corners->GetNumberOfIds(); ++k) {
        const double value = light->GetTuple1(corners->GetId(k));
        EXPECT_NEAR(value, expected, 1e-6) << "tree " << t.id << " ball " << i;
        EXPECT_TRUE(value >= 0.0 && value <= 1.0) << value;
      }
    }
}

TEST_F(FoliageBlock, EachPieceIsAsWideAsItsBallAndStaysWithinItOfTheShoot) {
  vtkSmartPointer<vtkPolyData> block = build_foliage_block(stand_.snapshot);
  vtkIdType cell = 0;
  for (const TreeSnapshot& tree : stand_.snapshot.trees)
    for (std::size_t i = 0; i < tree.leaf_balls.size(); ++i, ++cell) {
      const Shoot& shoot = tree.shoots[tree.leaf_ball_shoot[i]];
      const double radius = tree.leaf_balls[i].radius;
      vtkIdList* corners = block->GetCell(cell)->GetPointIds();
      double widest = 0.0;
      for (vtkIdType k = 0; k < corners->GetNumberOfIds(); ++k) {
        const double d = distance_to_shoot(point_of(*block, corners->GetId(k)), shoot);
        EXPECT_LE(d, radius + 1e-5) << "tree " << tree.id << " ball " << i;
        widest = std::max(widest, d);
      }
      EXPECT_NEAR(widest, radius, 1e-5) << "tree " << tree.id << " ball " << i << ": the spray is the ball's width";
    }
}

TEST_F(FoliageBlock, IsWrittenAtFullDetailOnly) {
  auto names_at = [](OutputDetail detail) {
    std::vector<std::string> names;
    for (const StandBlock& block : stand_blocks(detail)) names.push_back(block.name);
    return names;
  };
  const auto full = names_at(OutputDetail::full);
  EXPECT_NE(std::find(full.begin(), full.end(), "foliage"), full.end());
  for (OutputDetail lighter : {OutputDetail::envelope, OutputDetail::cone}) {
    const auto names = names_at(lighter);
    EXPECT_EQ(std::find(names.begin(), names.end(), "foliage"), names.end()) << name_of(lighter);
  }
  for (const StandBlock& block : stand_blocks(OutputDetail::full))
    if (block.name == "foliage")
      EXPECT_EQ(block.build(stand_.snapshot)->GetNumberOfElements(vtkDataObject::CELL), ball_count());
}

}  // namespace
}  // namespace heliostand
