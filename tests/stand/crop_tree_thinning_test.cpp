// Crop-tree thinning: the crop trees are the biggest stems far enough apart, and each loses its strongest competitors
// by their Hegyi term; crop trees and protected trees are never removed.
#include "stand/crop_tree_thinning.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace heliostand {
namespace {

using ::testing::ElementsAre;

// A 20 m x 20 m plot (0.04 ha). A (40 cm) and C (35 cm) are the crop trees wanted; B is big but 2 m from A.
//   A 40 cm (5, 5)     B 38 cm (7, 5): 2 m from A, Hegyi term on A 38/40/2 = 0.475
//   E 25 cm (3, 5): 2 m, 0.3125      D 20 cm (5, 7): 2 m, 0.25     G 30 cm (5, 9.5): 4.5 m, 0.167
//   C 35 cm (15, 15)   F 15 cm (15, 13): 2 m from C, 15/35/2 = 0.214
enum Tree { A, B, C, D, E, F, G };
std::vector<ThinningCandidate> stand() {
  return {{"A", 40, false, 0, 5, 5},  {"B", 38, false, 0, 7, 5},   {"C", 35, false, 0, 15, 15},
          {"D", 20, false, 0, 5, 7},  {"E", 25, false, 0, 3, 5},   {"F", 15, false, 0, 15, 13},
          {"G", 30, false, 0, 5, 9.5}};
}
const ThinningPlot thinning_plot{0.04, StandEdges{}};

ThinningRule crop_tree_rule(double per_ha, double spacing, double radius, std::optional<int> per_crop_tree) {
  ThinningRule rule;
  rule.method = ThinningMethod::crop_tree;
  rule.crop_trees = {per_ha, spacing, radius, per_crop_tree};
  return rule;
}

TEST(CropTreeThinning, CropTreesAreTheBiggestStemsAtLeastTheSpacingApart) {
  // 50/ha on 0.04 ha: two crop trees. B (38 cm) is second by DBH but only 2 m from A.
  EXPECT_THAT(select_crop_trees(crop_tree_rule(50, 5, 4, {}).crop_trees, stand(), thinning_plot), ElementsAre(A, C));
  // Without a spacing, B is taken.
  EXPECT_THAT(select_crop_trees(crop_tree_rule(50, 0, 4, {}).crop_trees, stand(), thinning_plot), ElementsAre(A, B));
  // Wanting four with 12 m spacing finds only two: A and C are the only stems 12 m apart.
  EXPECT_THAT(select_crop_trees(crop_tree_rule(100, 12, 4, {}).crop_trees, stand(), thinning_plot), ElementsAre(A, C));
}

TEST(CropTreeThinning, TheStrongestCompetitorsOfEachCropTreeLeave) {
  // Two per crop tree within 4 m: B and E for A (G is 4.5 m away), F for C.
  EXPECT_THAT(select_crop_tree_competitors(crop_tree_rule(50, 5, 4, 2), stand(), thinning_plot), ElementsAre(B, E, F));
  // All within the radius, strongest first.
  EXPECT_THAT(select_crop_tree_competitors(crop_tree_rule(50, 5, 4, {}), stand(), thinning_plot), ElementsAre(B, E, D, F));
  // A wider radius reaches G, never the other crop tree (C is 14.1 m from A).
  EXPECT_THAT(select_crop_tree_competitors(crop_tree_rule(50, 5, 20, {}), stand(), thinning_plot),
              ElementsAre(B, E, D, G, F));
}

TEST(CropTreeThinning, ProtectedCompetitorsStayAndTheNextStrongestGoes) {
  auto trees = stand();
  trees[E].is_protected = true;
  EXPECT_THAT(select_crop_tree_competitors(crop_tree_rule(50, 5, 4, 2), trees, thinning_plot), ElementsAre(B, D, F));
}

TEST(CropTreeThinning, CompetitorsAcrossAPeriodicEdgeCount) {
  // A 10 m x 10 m plot: one crop tree (100/ha) at the west edge, a 30 cm competitor 1 m away across the edge.
  const std::vector<ThinningCandidate> trees{{"X", 40, false, 0, 0.5, 5}, {"Y", 30, false, 0, 9.5, 5},
                                             {"Z", 10, false, 0, 5.0, 5}};
  const ThinningPlot periodic{0.01, StandEdges{true, PlotBounds{0, 0, 10, 10}}};
  const ThinningPlot buffered{0.01, StandEdges{}};
  EXPECT_THAT(select_crop_tree_competitors(crop_tree_rule(100, 0, 3, {}), trees, periodic), ElementsAre(1));
  EXPECT_TRUE(select_crop_tree_competitors(crop_tree_rule(100, 0, 3, {}), trees, buffered).empty());
}

}  // namespace
}  // namespace heliostand
