// The year's uptake of a stand (take_up_in_order): the trees' shares are found in parallel, chunk by chunk, and the
// soil is depleted tree after tree. It must leave the soil and give each tree exactly what taking up one tree at a
// time in the stand's order does, since the split between trees sharing a vertex depends on that order.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "roots/reference_root_field_solver.hpp"
#include "roots/root_growth.hpp"

namespace heliostand::roots {
namespace {

// 150 trees (more than two of the uptake's chunks) 0.4 m apart on 0.5 m soil voxels, so that neighbours share the
// vertices around their tips, grown together for two years.
struct CrowdedSeedlings {
  SoilGrid soil{{{-1.0, -1.0, -3.0}, 0.5, {14, 10, 6}}, 1.0, 0.8};
  std::vector<RootSystem> trees;
  std::vector<RootSystem*> in_order;

  CrowdedSeedlings() {
    for (int t = 0; t < 150; ++t)
      trees.emplace_back(t, glm::dvec3(0.4 * (t % 15), 0.4 * (t / 15), 0.0), tap_rooted_conifer(), 0);
    for (RootSystem& tree : trees) in_order.push_back(&tree);
    ReferenceRootFieldSolver solver;
    for (int year = 1; year <= 2; ++year) grow_roots(in_order, soil, solver, year, 7);
  }
};

std::vector<double> one_tree_at_a_time(const std::vector<RootSystem*>& trees, SoilGrid& soil) {
  std::vector<double> taken;
  for (const RootSystem* tree : trees) taken.push_back(tree->take_up(soil));
  return taken;
}

TEST(RootUptake, AStandTakesUpExactlyAsItsTreesOneAtATimeInOrder) {
  const CrowdedSeedlings stand;
  SoilGrid by_tree = stand.soil, together = stand.soil;
  const std::vector<double> expected = one_tree_at_a_time(stand.in_order, by_tree);
  const std::vector<double> taken = take_up_in_order(stand.in_order, together);
  ASSERT_EQ(taken.size(), expected.size());
  for (std::size_t t = 0; t < taken.size(); ++t) EXPECT_EQ(taken[t], expected[t]) << "tree " << t;
  for (SoilField field : {SoilField::moisture, SoilField::nutrient})
    EXPECT_TRUE(together.values(field) == by_tree.values(field)) << "the soil left differs";
  EXPECT_GT(*std::ranges::min_element(taken), 0.0) << "every tree's young tips take up";
}

// The check above can see an order mixed up: in this stand the order changes what trees take.
TEST(RootUptake, TheSplitBetweenTreesSharingVerticesDependsOnTheirOrder) {
  const CrowdedSeedlings stand;
  SoilGrid forward = stand.soil, backward = stand.soil;
  std::vector<RootSystem*> reversed(stand.in_order.rbegin(), stand.in_order.rend());
  const std::vector<double> taken_forward = take_up_in_order(stand.in_order, forward);
  std::vector<double> taken_backward = take_up_in_order(reversed, backward);
  std::reverse(taken_backward.begin(), taken_backward.end());
  std::size_t differ = 0;
  for (std::size_t t = 0; t < taken_forward.size(); ++t) differ += taken_forward[t] != taken_backward[t] ? 1 : 0;
  EXPECT_GT(differ, taken_forward.size() / 2);
}

}  // namespace
}  // namespace heliostand::roots
