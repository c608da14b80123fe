#include "stand/thinning.hpp"
#include "stand/thinning_candidates.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace heliostand {
namespace {

// Ten trees of DBH 10, 12, ..., 28 cm; on a 0.1 ha plot, 100 stems/ha.
using testing::ten_trees;

}  // namespace

TEST(Thinning, BasalAreaOfOneStem) {
  // 20 cm DBH: π · 0.1² = 0.0314159 m²
  EXPECT_NEAR(basal_area_m2(20.0), 0.0314159, 1e-6);
}

TEST(Thinning, FromBelowToStemTargetRemovesTheSmallest) {
  ThinningRule rule{ThinningMethod::from_below, {}, 70.0, std::nullopt};
  const auto chosen = select_for_thinning(rule, ten_trees(), 0.1);
  // 100 → 70 stems/ha on 0.1 ha: 3 trees, the three thinnest (indices 0, 1, 2).
  ASSERT_EQ(chosen.size(), 3u);
  EXPECT_EQ(chosen[0], 0u);
  EXPECT_EQ(chosen[1], 1u);
  EXPECT_EQ(chosen[2], 2u);
}

TEST(Thinning, FromAboveToStemTargetRemovesTheLargest) {
  ThinningRule rule{ThinningMethod::from_above, {}, 80.0, std::nullopt};
  const auto chosen = select_for_thinning(rule, ten_trees(), 0.1);
  ASSERT_EQ(chosen.size(), 2u);
  EXPECT_EQ(chosen[0], 9u);
  EXPECT_EQ(chosen[1], 8u);
}

TEST(Thinning, FromBelowToBasalAreaTarget) {
  // Basal area of the ten trees: Σ π (d/200)² for d = 10..28 step 2 = 0.309447 m² → 3.0945 m²/ha.
  // Removing d = 10, 12, 14, 16 (0.007854 + 0.011310 + 0.015394 + 0.020106 m²) leaves 2.5478 m²/ha (> 2.5);
  // also removing 18 (0.025447) leaves 2.2934 ≤ 2.5: five trees.
  ThinningRule rule{ThinningMethod::from_below, {}, std::nullopt, 2.5};
  const auto chosen = select_for_thinning(rule, ten_trees(), 0.1);
  EXPECT_EQ(chosen.size(), 5u);
}

TEST(Thinning, TargetAlreadyMetRemovesNothing) {
  ThinningRule rule{ThinningMethod::from_below, {}, 150.0, std::nullopt};
  EXPECT_TRUE(select_for_thinning(rule, ten_trees(), 0.1).empty());
}

TEST(Thinning, ProtectedTreesAreSkipped) {
  auto trees = ten_trees();
  trees[0].is_protected = true;
  ThinningRule rule{ThinningMethod::from_below, {}, 80.0, std::nullopt};
  const auto chosen = select_for_thinning(rule, trees, 0.1);
  ASSERT_EQ(chosen.size(), 2u);
  EXPECT_EQ(chosen[0], 1u);
  EXPECT_EQ(chosen[1], 2u);
}

TEST(Thinning, MarkingListRemovesExactlyTheListedTrees) {
  ThinningRule rule{ThinningMethod::ids, {"t3", "t7"}, std::nullopt, std::nullopt};
  const auto chosen = select_for_thinning(rule, ten_trees(), 0.1);
  ASSERT_EQ(chosen.size(), 2u);
  EXPECT_EQ(chosen[0], 3u);
  EXPECT_EQ(chosen[1], 7u);
}

}  // namespace heliostand
