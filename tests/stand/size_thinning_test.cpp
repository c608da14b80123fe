// From below, from above and neutral thinning to stem, basal-area and relative targets: which trees leave.
#include "stand/size_thinning.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

namespace heliostand {
namespace {

using ::testing::ElementsAre;

// Ten trees of DBH 10, 12, ..., 28 cm on a 0.1 ha plot (100 stems/ha, basal area 3.0945 m²/ha), listed in a shuffled
// order so that ranking by DBH, not by position in the list, is what the tests see. dbh_of(k) is the k-th smallest.
const std::vector<int> listed_rank{4, 9, 0, 7, 2, 5, 8, 1, 6, 3};
double dbh_of(int rank) { return 10.0 + 2.0 * rank; }

std::vector<ThinningCandidate> ten_ranked_trees() {
  std::vector<ThinningCandidate> trees;
  for (int rank : listed_rank) trees.push_back({"r" + std::to_string(rank), dbh_of(rank), false});
  return trees;
}

// The DBH ranks of the chosen trees, in removal order.
std::vector<int> ranks_of(const std::vector<std::size_t>& chosen) {
  std::vector<int> ranks;
  for (std::size_t i : chosen) ranks.push_back(listed_rank[i]);
  return ranks;
}

ThinningRule rule(ThinningMethod method) {
  ThinningRule r;
  r.method = method;
  return r;
}

TEST(NeutralThinning, TakesOneTreeFromTheMiddleOfEachEqualSliceOfTheDbhRanking) {
  EXPECT_THAT(neutral_ranks(5, 10), ElementsAre(1, 3, 5, 7, 9));
  EXPECT_THAT(neutral_ranks(2, 10), ElementsAre(2, 7));
  EXPECT_THAT(neutral_ranks(3, 7), ElementsAre(1, 3, 5));
  EXPECT_THAT(neutral_ranks(4, 4), ElementsAre(0, 1, 2, 3));
  EXPECT_THAT(neutral_ranks(9, 3), ElementsAre(0, 1, 2));  // never more than there are
}

TEST(NeutralThinning, ToAStemTargetKeepsTheDbhDistributionsShape) {
  auto neutral = rule(ThinningMethod::neutral);
  neutral.target_stems_per_ha = 50;  // 10 → 5 trees
  const auto chosen = select_by_size(neutral, ten_ranked_trees(), 0.1);
  EXPECT_THAT(ranks_of(chosen), ElementsAre(1, 3, 5, 7, 9));
  // From below and from above take the ends of the distribution instead.
  auto low = rule(ThinningMethod::from_below);
  low.target_stems_per_ha = 50;
  EXPECT_THAT(ranks_of(select_by_size(low, ten_ranked_trees(), 0.1)), ElementsAre(0, 1, 2, 3, 4));
  auto high = rule(ThinningMethod::from_above);
  high.target_stems_per_ha = 50;
  EXPECT_THAT(ranks_of(select_by_size(high, ten_ranked_trees(), 0.1)), ElementsAre(9, 8, 7, 6, 5));
}

TEST(NeutralThinning, ToABasalAreaTargetTakesTheFewestEvenlySpreadTrees) {
  // 3.0945 → at most 2.5 m²/ha: at least 0.05945 m² must go. One tree (rank 5, 20 cm: 0.0314 m²) is not enough;
  // two (ranks 2 and 7, 14 and 24 cm: 0.0154 + 0.0452 = 0.0606 m²) are.
  auto neutral = rule(ThinningMethod::neutral);
  neutral.target_basal_area_m2_per_ha = 2.5;
  EXPECT_THAT(ranks_of(select_by_size(neutral, ten_ranked_trees(), 0.1)), ElementsAre(2, 7));
  neutral.target_basal_area_m2_per_ha = 3.2;  // already below
  EXPECT_TRUE(select_by_size(neutral, ten_ranked_trees(), 0.1).empty());
}

TEST(NeutralThinning, ProtectedTreesAreLeftOutOfTheRanking) {
  auto trees = ten_ranked_trees();
  for (auto& tree : trees)
    if (tree.label == "r3") tree.is_protected = true;
  auto neutral = rule(ThinningMethod::neutral);
  neutral.target_stems_per_ha = 80;  // 2 of the 9 unprotected: ranks 2 and 6 of 0..8, i.e. DBH ranks 2 and 7
  EXPECT_THAT(ranks_of(select_by_size(neutral, trees, 0.1)), ElementsAre(2, 7));
}

TEST(RelativeTargets, RemoveFractionTakesRoundedShareOfTheLivingStems) {
  auto low = rule(ThinningMethod::from_below);
  low.remove_fraction = 0.3;
  EXPECT_THAT(ranks_of(select_by_size(low, ten_ranked_trees(), 0.1)), ElementsAre(0, 1, 2));
  low.remove_fraction = 0.25;  // 2.5 rounds to 3
  EXPECT_EQ(select_by_size(low, ten_ranked_trees(), 0.1).size(), 3u);
  // Protected trees count toward the living stems but are never taken.
  auto trees = ten_ranked_trees();
  for (auto& tree : trees) tree.is_protected = tree.label == "r0";
  low.remove_fraction = 0.3;
  EXPECT_THAT(ranks_of(select_by_size(low, trees, 0.1)), ElementsAre(1, 2, 3));
}

TEST(RelativeTargets, RemoveBasalAreaFractionLeavesAtMostTheRest) {
  // Half of 3.0945 m²/ha leaves at most 1.5473. From above: 28, 26 and 24 cm take 0.6158 + 0.5309 + 0.4524 = 1.5991,
  // leaving 1.4954; two would leave 1.9478.
  auto high = rule(ThinningMethod::from_above);
  high.remove_basal_area_fraction = 0.5;
  EXPECT_THAT(ranks_of(select_by_size(high, ten_ranked_trees(), 0.1)), ElementsAre(9, 8, 7));
  // Neutral to the same fraction: 0.1547 m² must go. 1 to 4 evenly spread trees take at most 0.1225 m²
  // (ranks 1, 3, 6, 8: 12, 16, 22, 26 cm); five (12, 16, 20, 24, 28 cm) take 0.1696 m².
  auto neutral = rule(ThinningMethod::neutral);
  neutral.remove_basal_area_fraction = 0.5;
  EXPECT_THAT(ranks_of(select_by_size(neutral, ten_ranked_trees(), 0.1)), ElementsAre(1, 3, 5, 7, 9));
}

}  // namespace
}  // namespace heliostand
