// The stand's root zone: spin-up from planting, the soil under the plot, pruning events, dropped roots of
// removed trees, and both bonuses handed to crown and roots by couple().
#include "stand/root_zone.hpp"

#include <gtest/gtest.h>

namespace heliostand {
namespace {

StandTree planted_tree(int id, glm::dvec3 base, int age) {
  ConiferTree tree(SpeciesParameters{}, TreeCalibration{}, base, 3, id);
  tree.grow_to_age(age);
  return StandTree{id, std::to_string(id + 1), "todomatsu", std::move(tree)};
}

Stand two_tree_stand() {
  std::vector<StandTree> trees;
  trees.push_back(planted_tree(0, {3.0, 4.0, 0.0}, 6));
  trees.push_back(planted_tree(1, {7.0, 4.0, 0.0}, 3));  // planted three years later
  return Stand(0.008, 6, std::move(trees), {});
}

const PlotBounds plot{0.0, 0.0, 10.0, 8.0};

TEST(RootZone, SoilCoversThePlotToItsDepth) {
  SoilSettings soil;
  soil.spacing_m = 0.5;
  soil.depth_m = 3.0;
  soil.nutrient.value = 0.5;
  const roots::SoilGrid grid = make_soil(soil, plot);
  EXPECT_EQ(grid.geometry().cells, glm::ivec3(20, 16, 6));
  EXPECT_DOUBLE_EQ(grid.surface_z(), 0.0);
  EXPECT_DOUBLE_EQ(grid.min_corner().z, -3.0);
  EXPECT_DOUBLE_EQ(grid.nutrient({5.0, 4.0, -1.0}), 0.5);
  EXPECT_DOUBLE_EQ(grid.moisture({5.0, 4.0, -1.0}), 1.0);
}

TEST(RootZone, SpinUpGrowsEachTreeFromItsPlanting) {
  Stand stand = two_tree_stand();
  RootZone zone(RootsSettings{}, plot, 9, 1.0, compute::ComputeBackend::reference());
  zone.establish(stand);
  for (int id : {0, 1}) {
    const roots::RootSystem* roots = zone.roots_of(id);
    ASSERT_NE(roots, nullptr);
    EXPECT_EQ(roots->year(), 6);
    const glm::dvec3 collar = stand.trees()[id].conifer.stem_base();
    EXPECT_DOUBLE_EQ(roots->segments()[0].start.x, collar.x);
    EXPECT_DOUBLE_EQ(roots->segments()[0].start.y, collar.y);
  }
  // Each tree's first (main-root) segment formed in its planting year.
  auto first_birth = [&](int id) {
    int year = 1000;
    for (const auto& s : zone.roots_of(id)->segments()) year = std::min(year, s.birth_year);
    return year;
  };
  EXPECT_EQ(first_birth(0), 0);  // the seedling's main root is planted in year 0 ...
  EXPECT_EQ(first_birth(1), 3);  // ... the younger tree's three years later
  EXPECT_GT(zone.roots_of(0)->total_length_m(), zone.roots_of(1)->total_length_m());
}

TEST(RootZone, CoupleHandsBranchToTheCrownAndRootToTheRoots) {
  Stand stand = two_tree_stand();
  RootZone zone(RootsSettings{}, plot, 9, 1.0, compute::ComputeBackend::reference());
  zone.establish(stand);
  for (std::size_t i = 0; i < 2; ++i) {
    // Full light on every leaf ball.
    ConiferTree& tree = stand.tree_at(i).conifer;
    tree.set_foliage_light(std::vector<ConiferTree::FoliageLight>(tree.leaf_balls().size()));
  }
  zone.couple(stand);
  for (int id : {0, 1}) {
    const PathBalance* balance = zone.balance_of(id);
    ASSERT_NE(balance, nullptr);
    EXPECT_EQ(stand.trees()[id].conifer.branching_bonus(), balance->branch);
    EXPECT_EQ(zone.roots_of(id)->branching_bonus(), balance->root);
    double light = 0.0;
    for (double lp : balance->lp) light += lp;
    // ρ Σ L_i with L_i = 1: LP summed over the paths is ρ × the number of leaf balls.
    EXPECT_NEAR(light, RootsSettings{}.coupling.rho * stand.trees()[id].conifer.leaf_balls().size(), 1e-9);
  }
}

TEST(RootZone, PruningEveryYearClearsItsPathOfTheNamedTreeOnly) {
  Stand stand = two_tree_stand();
  RootsSettings settings;
  settings.pruning.push_back({0, std::nullopt, true, {0, 1}, 0.0, 0.0, {"1"}});
  RootZone zone(settings, plot, 9, 1.0, compute::ComputeBackend::reference());
  zone.establish(stand);
  auto old_segments_in = [&](int id, int year) {
    int n = 0;
    for (const auto& s : zone.roots_of(id)->segments())
      n += (s.sector == 0 || s.sector == 1) && s.birth_year < year;
    return n;
  };
  ASSERT_GT(old_segments_in(0, 7), 0);
  stand.grow_year();
  zone.grow_year(stand);
  EXPECT_EQ(old_segments_in(0, 7), 0);  // only this year's regrowth is left in paths 0 and 1
  EXPECT_GT(old_segments_in(1, 7), 0);  // tree "2" is not pruned
}

TEST(RootZone, RemovedTreesLoseTheirRoots) {
  Stand stand = two_tree_stand();
  RootZone zone(RootsSettings{}, plot, 9, 1.0, compute::ComputeBackend::reference());
  zone.establish(stand);
  stand.tree_at(1).status = TreeStatus::removed;
  stand.grow_year();
  zone.grow_year(stand);
  EXPECT_EQ(zone.roots_of(1), nullptr);
  ASSERT_NE(zone.roots_of(0), nullptr);
  EXPECT_EQ(zone.roots_of(0)->year(), 7);
  EXPECT_EQ(zone.living_roots().size(), 1u);
  StandSnapshot snapshot;
  snapshot.trees.resize(2);
  snapshot.trees[0].id = 0;
  snapshot.trees[1].id = 1;
  zone.annotate(snapshot);
  EXPECT_NEAR(snapshot.trees[0].root_length_m, zone.roots_of(0)->total_length_m(), 1e-12);
  EXPECT_GT(snapshot.trees[0].root_max_depth_m, 0.3);
  EXPECT_GT(snapshot.trees[0].root_uptake, 0.0);
  EXPECT_TRUE(std::isnan(snapshot.trees[1].root_length_m));
}

}  // namespace
}  // namespace heliostand
