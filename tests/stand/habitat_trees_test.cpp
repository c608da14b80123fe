// Habitat trees in the stand: a tree carrying a hollow is kept by a thinning unless that thinning turns the
// protection off, and its trunk mesh (the `trunk` output block) carries the hollow's callus and bark.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "io/vtk_stand_blocks.hpp"
#include "stand/snapshot.hpp"
#include "stand/stand.hpp"
#include "stand/trunk_mesh.hpp"

#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace heliostand {
namespace {

StandTree planted(int id, double x, int age) {
  ConiferTree tree(SpeciesParameters{}, TreeCalibration{}, {x, 0.0, 0.0}, 3, id);
  tree.grow_to_age(age);
  return StandTree{id, std::to_string(id), "todomatsu", std::move(tree)};
}

hollow::HollowSpec small_hollow() {
  hollow::HollowSpec spec;
  spec.height_m = 1.0;
  spec.azimuth_deg = 90;
  spec.width_m = 0.06;
  spec.wound_height_m = 0.12;
  spec.callus_radius_m = 0.01;
  spec.bulge_m = 0.005;
  spec.outline_step_m = 0.002;
  return spec;
}

// Four trees; the thinnest one (planted last, youngest) carries a hollow.
Stand four_trees_with_a_habitat_tree(bool protect) {
  std::vector<StandTree> trees;
  for (int i = 0; i < 4; ++i) trees.push_back(planted(i, 3.0 * i, 30 - 2 * i));
  trees[3].hollows.push_back(small_hollow());
  ThinningEvent low{{30}, ThinningRule{ThinningMethod::from_below, {}, 300.0, std::nullopt}, "low thinning", protect};
  return Stand(0.01, 30, std::move(trees), {low});  // 400 stems/ha down to 300: one tree goes
}

std::vector<std::string> removed_labels(const std::vector<TreeEvent>& events) {
  std::vector<std::string> labels;
  for (const auto& e : events) labels.push_back(e.label);
  return labels;
}

TEST(HabitatTrees, ThinningFromBelowKeepsTheHabitatTreeUnlessProtectionIsOff) {
  Stand protected_stand = four_trees_with_a_habitat_tree(true);
  ASSERT_LT(protected_stand.trees()[3].conifer.dbh_cm(), protected_stand.trees()[2].conifer.dbh_cm());
  EXPECT_EQ(removed_labels(protected_stand.thin()), std::vector<std::string>{"2"});  // the next-smallest
  EXPECT_TRUE(protected_stand.trees()[3].alive());

  Stand unprotected = four_trees_with_a_habitat_tree(false);
  EXPECT_EQ(removed_labels(unprotected.thin()), std::vector<std::string>{"3"});  // the smallest, hollow or not
}

TEST(HabitatTrees, TrunkMeshCarriesTheHollowAndThePlainStemDoesNot) {
  Stand stand = four_trees_with_a_habitat_tree(true);
  const auto plain = trunk_mesh_of(stand.trees()[0]);
  const auto habitat = trunk_mesh_of(stand.trees()[3]);
  ASSERT_TRUE(plain && habitat);
  auto count_part = [](const hollow::HollowMesh& mesh, hollow::MeshPart part) {
    return std::count(mesh.part.begin(), mesh.part.end(), static_cast<int>(part));
  };
  EXPECT_EQ(count_part(*plain, hollow::MeshPart::callus), 0);
  EXPECT_GT(count_part(*habitat, hollow::MeshPart::callus), 100);
  EXPECT_GT(count_part(*habitat, hollow::MeshPart::bark), 100);
  // The plain stem reaches the tree top and is as thick at breast height as the tree's DBH says.
  const ConiferTree& tree = stand.trees()[0].conifer;
  double top = 0, widest_at_breast_height = 0;
  for (const auto& v : plain->vertices) {
    top = std::max(top, v.z);
    if (std::abs(v.z - 1.3) < 0.13) widest_at_breast_height = std::max(widest_at_breast_height, std::hypot(v.x, v.y));
  }
  EXPECT_NEAR(top, tree.height_m(), 1e-6);
  EXPECT_NEAR(2 * widest_at_breast_height * 100, tree.dbh_cm(), 0.05 * tree.dbh_cm());
}

TEST(HabitatTrees, SnapshotFlagsTheHabitatTreeAndTheTrunkBlockPlacesEveryStem) {
  std::vector<StandTree> trees;
  for (int i = 0; i < 4; ++i) trees.push_back(planted(i, 3.0 * i, 30 - 2 * i));
  trees[3].hollows.push_back(small_hollow());
  hollow::HollowSpec higher = small_hollow();
  higher.height_m = 2.0;
  higher.azimuth_deg = 270;
  trees[2].hollows = {small_hollow(), higher};  // two hollows, stacked on one stem
  Stand stand(0.01, 30, std::move(trees), {});
  SnapshotTracker tracker;
  const StandSnapshot snapshot = tracker.take(stand, 0);
  ASSERT_EQ(snapshot.trees.size(), 4u);
  EXPECT_EQ(snapshot.trees[3].hollow_count, 1);
  EXPECT_EQ(snapshot.trees[2].hollow_count, 2);
  EXPECT_EQ(snapshot.trees[0].hollow_count, 0);
  const auto block = build_trunk_block(snapshot);
  vtkDataArray* tree_id = block->GetPointData()->GetArray("tree_id");
  vtkDataArray* part = block->GetPointData()->GetArray("part");
  ASSERT_TRUE(tree_id && part);
  int callus_of_tree_3 = 0, callus_elsewhere = 0;
  double callus_low_of_tree_2 = 0, callus_high_of_tree_2 = 0;  // callus points near each of its two hollows
  std::vector<double> min_x(4, 1e9);
  for (vtkIdType p = 0; p < block->GetNumberOfPoints(); ++p) {
    const int id = static_cast<int>(tree_id->GetTuple1(p));
    min_x[id] = std::min(min_x[id], block->GetPoint(p)[0]);
    if (part->GetTuple1(p) != 2) continue;
    const double z = block->GetPoint(p)[2];
    if (id == 3) ++callus_of_tree_3;
    else if (id == 2) (z < 1.5 ? callus_low_of_tree_2 : callus_high_of_tree_2) += 1;
    else ++callus_elsewhere;
  }
  EXPECT_GT(callus_of_tree_3, 0);
  EXPECT_GT(callus_low_of_tree_2, 0);
  EXPECT_GT(callus_high_of_tree_2, 0);
  EXPECT_EQ(callus_elsewhere, 0);
  for (int id = 0; id < 4; ++id) EXPECT_NEAR(min_x[id], 3.0 * id, 0.3) << "tree " << id;  // at its own position
  EXPECT_GT(block->GetNumberOfCells(), 0);

  SnapshotTracker without_trunks(false);
  EXPECT_FALSE(without_trunks.take(stand, 0).trees[0].trunk);
}

}  // namespace
}  // namespace heliostand
