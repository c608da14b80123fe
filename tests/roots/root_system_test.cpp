#include "roots/root_system.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <algorithm>
#include <numeric>

#include <glm/geometric.hpp>

#include "roots/reference_root_field_solver.hpp"
#include "roots/root_growth.hpp"

namespace heliostand::roots {
namespace {

SoilGrid big_soil() { return SoilGrid({{-6.0, -6.0, -4.0}, 0.5, {24, 24, 8}}, 1.0, 0.5); }

// Grows `trees` together for `years` years from year 1.
void grow(std::vector<RootSystem>& trees, SoilGrid& soil, int years, std::uint64_t seed = 42) {
  ReferenceRootFieldSolver solver;
  std::vector<RootSystem*> pointers;
  for (RootSystem& tree : trees) pointers.push_back(&tree);
  for (int year = 1; year <= years; ++year) {
    grow_roots(pointers, soil, solver, year, seed);
    soil.recharge({});
  }
}

RootSystem grown_tree(int years, RootParameters parameters = tap_rooted_conifer(), std::uint64_t seed = 42) {
  SoilGrid soil = big_soil();
  std::vector<RootSystem> trees;
  trees.emplace_back(0, glm::dvec3(0.0), parameters, 0);
  grow(trees, soil, years, seed);
  return trees[0];
}

// Every segment hangs on its parent: valid index, parent first, end to start.
void expect_connected(const RootSystem& tree) {
  const auto segments = tree.segments();
  for (std::size_t s = 1; s < segments.size(); ++s) {
    ASSERT_GE(segments[s].parent, 0);
    ASSERT_LT(segments[s].parent, static_cast<int>(s));
    EXPECT_LT(glm::length(segments[segments[s].parent].end - segments[s].start), 1e-12);
  }
}

TEST(RootSystem, SeedlingIsOneMainRootSegmentStraightDown) {
  const RootSystem tree(3, {1.0, 2.0, 0.0}, tap_rooted_conifer(), 0);
  ASSERT_EQ(tree.segments().size(), 1u);
  const RootSegment& tap = tree.segments()[0];
  EXPECT_EQ(tap.type, RootType::main);
  EXPECT_EQ(tap.end, glm::dvec3(1.0, 2.0, -tap_rooted_conifer().of(RootType::main).elongation_m_per_year));
  EXPECT_TRUE(tap.growing);
  EXPECT_EQ(tap.sector, no_sector);
}

TEST(RootSystem, InvalidParametersAreRejected) {
  RootParameters parameters = tap_rooted_conifer();
  parameters.of(RootType::lateral).tropisms.alpha += 0.1;  // Σ = 1.1
  EXPECT_THROW(RootSystem(0, glm::dvec3(0.0), parameters, 0), std::invalid_argument);
  parameters = tap_rooted_conifer();
  parameters.moisture_probes = 3;
  EXPECT_THROW(RootSystem(0, glm::dvec3(0.0), parameters, 0), std::invalid_argument);
}

TEST(RootSystem, OnlyTheSeedsBranchingRulesAreUsed) {
  RootParameters parameters = tap_rooted_conifer();
  // Ask for every combination, allowed or not: the rules must filter them.
  for (RootType type : all_root_types) {
    parameters.of(type).branching_frequency = {0.4, 0.4, 0.4, 0.4};
    parameters.of(type).lifespan_years = 100.0;
    parameters.of(type).growth_years = 100.0;
  }
  const RootSystem tree = grown_tree(8, parameters);
  std::set<std::pair<RootType, RootType>> seen;
  for (const RootSegment& segment : tree.segments()) {
    if (segment.parent < 0) continue;
    const RootType parent = tree.segments()[segment.parent].type;
    EXPECT_TRUE(parent == segment.type || may_branch_into(parent, segment.type))
        << name_of(parent) << " -> " << name_of(segment.type);
    seen.emplace(parent, segment.type);
  }
  // Every allowed rule of P occurs: main → lateral, lateral → sinker / fine, sinker → fine, ...
  for (auto [parent, child] : {std::pair{RootType::main, RootType::lateral}, std::pair{RootType::lateral, RootType::sinker},
                               std::pair{RootType::lateral, RootType::fine}, std::pair{RootType::sinker, RootType::fine},
                               std::pair{RootType::fine, RootType::fine}})
    EXPECT_TRUE(seen.contains({parent, child})) << name_of(parent) << " -> " << name_of(child);
  EXPECT_FALSE(seen.contains({RootType::fine, RootType::lateral}));
  EXPECT_FALSE(seen.contains({RootType::sinker, RootType::lateral}));
  EXPECT_FALSE(seen.contains({RootType::lateral, RootType::main}));
}

TEST(RootSystem, SegmentsHaveTheirTypesElongationAndRadius) {
  const RootSystem tree = grown_tree(6);
  const RootParameters parameters = tap_rooted_conifer();
  for (const RootSegment& segment : tree.segments()) {
    EXPECT_NEAR(segment.length(), parameters.of(segment.type).elongation_m_per_year, 1e-9);
    EXPECT_EQ(segment.radius_m, parameters.of(segment.type).radius_m);
  }
  expect_connected(tree);
}

TEST(RootSystem, AxesStopAfterTheirGrowthYearsAndFineRootsDieAfterTheirLifespan) {
  const RootParameters parameters = tap_rooted_conifer();
  const RootSystem tree = grown_tree(12);
  int main_segments = 0;
  for (const RootSegment& segment : tree.segments()) {
    if (segment.type == RootType::main) ++main_segments;
    EXPECT_LE(tree.age_of(segment), parameters.of(segment.type).lifespan_years);
    if (segment.growing) EXPECT_LT(tree.year() - segment.axis_birth_year + 1, parameters.of(segment.type).growth_years);
  }
  EXPECT_EQ(main_segments, static_cast<int>(parameters.of(RootType::main).growth_years));
}

TEST(RootSystem, RootsStayInsideTheSoil) {
  // A small box: roots hit the walls, the bottom and the surface.
  SoilGrid soil({{-0.5, -0.5, -0.6}, 0.1, {10, 10, 6}}, 1.0, 0.5);
  RootParameters parameters = tap_rooted_conifer();
  parameters.of(RootType::lateral).tropisms = {.alpha = 0.2, .beta = 0.0, .gamma = 0.0, .delta = 0.0, .epsilon = 0.8};
  std::vector<RootSystem> trees;
  trees.emplace_back(0, glm::dvec3(0.0), parameters, 0);
  grow(trees, soil, 10);
  const double ceiling = soil.surface_z() - parameters.min_depth_m;
  for (const RootSegment& segment : trees[0].segments()) {
    EXPECT_TRUE(soil.contains(segment.end));
    EXPECT_LE(segment.end.z, ceiling + 1e-12);
  }
  // The reflection rule by hand: heading up-east from 0.05 m under the surface, 0.1 m long.
  const glm::dvec3 end = keep_in_soil({0.0, 0.0, -0.05}, glm::normalize(glm::dvec3(1.0, 0.0, 1.0)), 0.1, soil, 0.02);
  EXPECT_NEAR(end.x, 0.1 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(end.z, -0.05 - 0.1 / std::sqrt(2.0), 1e-12);  // reflected downward
}

TEST(RootSystem, SameSeedSameRootsWhateverTheOrderOfTrees) {
  const glm::dvec3 a(-0.5, 0.0, 0.0), b(0.5, 0.0, 0.0);
  SoilGrid soil_ab = big_soil(), soil_ba = big_soil();
  std::vector<RootSystem> ab, ba;
  ab.emplace_back(1, a, tap_rooted_conifer(), 0);
  ab.emplace_back(2, b, tap_rooted_conifer(), 0);
  ba.emplace_back(2, b, tap_rooted_conifer(), 0);
  ba.emplace_back(1, a, tap_rooted_conifer(), 0);
  grow(ab, soil_ab, 6);
  grow(ba, soil_ba, 6);
  for (auto [first, second] : {std::pair{&ab[0], &ba[1]}, std::pair{&ab[1], &ba[0]}}) {
    ASSERT_EQ(first->segments().size(), second->segments().size());
    for (std::size_t s = 0; s < first->segments().size(); ++s)
      EXPECT_LT(glm::length(first->segments()[s].end - second->segments()[s].end), 1e-12);
  }
  // A different seed gives a different tree.
  const RootSystem other = grown_tree(6, tap_rooted_conifer(), 43);
  const RootSystem same = grown_tree(6, tap_rooted_conifer(), 42);
  EXPECT_TRUE(other.segments().size() != same.segments().size() ||
              glm::length(other.segments().back().end - same.segments().back().end) > 1e-6);
}

TEST(RootSystem, EveryRootInheritsThePathWhereItsRouteJoinsTheMainRoot) {
  const RootSystem tree = grown_tree(8);
  const auto segments = tree.segments();
  for (const RootSegment& segment : segments) {
    if (segment.type == RootType::main) {
      EXPECT_EQ(segment.sector, no_sector);
      continue;
    }
    const RootSegment* joining = &segment;  // walk back to the first segment off the main root
    while (segments[joining->parent].type != RootType::main) joining = &segments[joining->parent];
    EXPECT_EQ(segment.sector, compass_sector_of(joining->end - joining->start));
  }
}

TEST(RootSystem, PruningAPathRemovesItsRootsAndWhatTheyCarry) {
  RootSystem tree = grown_tree(8);
  std::array<int, path_count> before{};
  for (const RootSegment& segment : tree.segments())
    if (segment.sector != no_sector) ++before[segment.sector];
  ASSERT_GT(before[1], 0);
  const int main_segments = static_cast<int>(std::ranges::count_if(
      tree.segments(), [](const RootSegment& s) { return s.type == RootType::main; }));
  EXPECT_EQ(tree.prune({.sector = 1}), before[1]);
  for (const RootSegment& segment : tree.segments()) EXPECT_NE(segment.sector, 1);
  EXPECT_EQ(std::ranges::count_if(tree.segments(), [](const RootSegment& s) { return s.type == RootType::main; }),
            main_segments);
  expect_connected(tree);
}

TEST(RootSystem, PruningByDepthRemovesEverythingBelowAndItsDescendants) {
  RootSystem tree = grown_tree(8);
  const double depth = 0.4;
  EXPECT_GT(tree.prune({.sector = no_sector, .min_depth_m = depth}), 0);
  for (const RootSegment& segment : tree.segments()) {
    if (segment.type == RootType::main) continue;
    EXPECT_LT(tree.collar().z - segment.end.z, depth);
    // Nothing left hangs below a cut: every ancestor off the main root is shallower too.
    for (int p = segment.parent; p >= 0 && tree.segments()[p].type != RootType::main; p = tree.segments()[p].parent)
      EXPECT_LT(tree.collar().z - tree.segments()[p].end.z, depth);
  }
  expect_connected(tree);
}

TEST(RootSystem, UptakeCapacitySitsAtTheYoungTips) {
  const RootSystem tree = grown_tree(6);
  const RootParameters parameters = tap_rooted_conifer();
  double total = 0.0, young = 0.0;
  for (const RootSegment& segment : tree.segments()) {
    const double expected = parameters.of(segment.type).absorptive_weight * segment.length() *
                            std::exp(-tree.age_of(segment) / parameters.uptake_decay_years);
    EXPECT_NEAR(tree.uptake_capacity(segment), expected, 1e-15);
    total += expected;
    if (tree.age_of(segment) == 0) young += expected;
  }
  EXPECT_GT(young / total, 0.8);  // with τ_u = 0.5 y, this year's segments hold most of it
  const auto by_path = tree.uptake_capacity_by_path();
  EXPECT_NEAR(std::accumulate(by_path.begin(), by_path.end(), 0.0), total, 1e-12);
}

TEST(RootSystem, TheMainRootsCapacityIsSharedByAllPaths) {
  const RootSystem seedling(0, glm::dvec3(0.0), tap_rooted_conifer(), 0);
  const double capacity = seedling.uptake_capacity(seedling.segments()[0]);
  EXPECT_NEAR(capacity, 0.5 * 0.15, 1e-15);  // absorptive weight 0.5 × 0.15 m, age 0
  for (double path : seedling.uptake_capacity_by_path()) EXPECT_NEAR(path, capacity / 8, 1e-15);
}

TEST(RootSystem, BranchingBonusOfAPathAddsBranchesThere) {
  auto new_roots_in_path = [](const std::array<double, path_count>& bonus, int path) {
    SoilGrid soil = big_soil();
    std::vector<RootSystem> trees;
    trees.emplace_back(0, glm::dvec3(0.0), tap_rooted_conifer(), 0);
    grow(trees, soil, 4);
    trees[0].set_branching_bonus(bonus);
    std::vector<RootSystem*> pointers{&trees[0]};
    ReferenceRootFieldSolver solver;
    grow_roots(pointers, soil, solver, 5, 42);
    // New roots of the path grown from its own roots (the main root's apex feels the mean bonus of all
    // paths, so new laterals off the main root are left out).
    const auto segments = trees[0].segments();
    return std::ranges::count_if(segments, [path, segments](const RootSegment& s) {
      return s.birth_year == 5 && s.sector == path && segments[s.parent].type != RootType::main;
    });
  };
  // The two paths with the most new roots without a bonus: boost the first, watch the second.
  std::array<double, path_count> none{}, boosted{}, suppressed{};
  std::array<long, path_count> base{};
  for (int path = 0; path < path_count; ++path) base[path] = new_roots_in_path(none, path);
  std::array<int, path_count> order{0, 1, 2, 3, 4, 5, 6, 7};
  std::ranges::sort(order, [&](int a, int b) { return base[a] > base[b]; });
  const int path = order[0], other = order[1];
  ASSERT_GT(base[other], 0);
  boosted[path] = 3.0;
  EXPECT_GT(new_roots_in_path(boosted, path), base[path]);
  EXPECT_EQ(new_roots_in_path(boosted, other), base[other]);  // other paths untouched
  suppressed.fill(-10.0);
  // Strongly negative: no new roots anywhere, only the apices' own continuations.
  SoilGrid soil = big_soil();
  std::vector<RootSystem> trees;
  trees.emplace_back(0, glm::dvec3(0.0), tap_rooted_conifer(), 0);
  grow(trees, soil, 4);
  trees[0].set_branching_bonus(suppressed);
  const int apices = static_cast<int>(std::ranges::count_if(trees[0].segments(), [](const RootSegment& s) { return s.growing; }));
  const auto buds = trees[0].buds(5, 42);
  EXPECT_EQ(static_cast<int>(buds.size()), apices);
  for (const RootBud& bud : buds) EXPECT_TRUE(bud.continuation);
}

TEST(RootSystem, UptakeDepletesTheSoilAtYoungTips) {
  SoilGrid soil = big_soil();
  const RootSystem seedling(0, glm::dvec3(0.0), tap_rooted_conifer(), 0);
  const glm::dvec3 tip = seedling.segments()[0].end;
  const double taken = seedling.take_up(soil);
  EXPECT_GT(taken, 0.0);
  // W = 0.075, rate 0.05 /m: the fraction 0.00375 is shared by the tip's 8 vertices (moisture 1).
  EXPECT_NEAR(taken, 0.05 * 0.075, 1e-12);
  EXPECT_LT(soil.moisture(tip), 1.0);
  EXPECT_DOUBLE_EQ(soil.moisture({3.0, 3.0, -2.0}), 1.0);
}

}  // namespace
}  // namespace heliostand::roots

namespace heliostand::roots {
namespace {

TEST(RootSystem, WoodyRootsStopBranchingAtTheMaximumOrder) {
  RootParameters parameters = tap_rooted_conifer();
  parameters.max_woody_order = 2;
  parameters.of(RootType::lateral).branching_frequency[index_of(RootType::lateral)] = 1.0;
  const RootSystem tree = grown_tree(8, parameters);
  int second_order = 0;
  for (const RootSegment& segment : tree.segments()) {
    if (segment.type == RootType::fine) continue;
    EXPECT_LE(segment.order, 2);
    if (segment.order == 2) ++second_order;
    if (segment.parent >= 0) {
      const RootSegment& parent = tree.segments()[segment.parent];
      const bool continuation = parent.type == segment.type && parent.order == segment.order;
      EXPECT_EQ(segment.order, continuation ? parent.order : parent.order + 1);
    }
  }
  EXPECT_GT(second_order, 0);
}

TEST(RootSystem, TheFrameworkKeepsRenewingFineRootsAfterItsAxesStop) {
  RootParameters parameters = tap_rooted_conifer();
  for (RootType type : {RootType::main, RootType::lateral, RootType::sinker}) parameters.of(type).growth_years = 3.0;
  auto fine_roots_in_year = [](const RootSystem& tree) {
    return std::ranges::count_if(tree.segments(),
                                 [&](const RootSegment& s) { return s.type == RootType::fine && s.birth_year == tree.year(); });
  };
  const RootSystem sprouting = grown_tree(12, parameters);
  EXPECT_EQ(std::ranges::count_if(sprouting.segments(), [](const RootSegment& s) { return s.growing && s.type != RootType::fine; }), 0);
  EXPECT_GT(fine_roots_in_year(sprouting), 0);
  for (const RootSegment& segment : sprouting.segments())
    if (segment.type == RootType::fine) EXPECT_LE(sprouting.age_of(segment), parameters.of(RootType::fine).lifespan_years);
  for (RootType type : all_root_types) parameters.of(type).fine_root_sprouting_per_year = 0.0;
  const RootSystem apices_only = grown_tree(12, parameters);
  EXPECT_EQ(fine_roots_in_year(apices_only), 0);  // the seed's rule alone: no apices, no new fine roots
}

}  // namespace
}  // namespace heliostand::roots

namespace heliostand::roots {
namespace {

TEST(RootSystem, AvailableUptakeScalesWithTheSoilsWaterAndNutrients) {
  const RootSystem tree = grown_tree(5);
  SoilGrid poor = big_soil(), rich = big_soil();  // moisture 1.0, nutrient 0.5
  rich.fill_uniform(SoilField::nutrient, 1.0);
  const auto capacity = tree.uptake_capacity_by_path();
  const auto from_poor = tree.available_uptake_by_path(poor);
  const auto from_rich = tree.available_uptake_by_path(rich);
  for (int path = 0; path < path_count; ++path) {
    EXPECT_NEAR(from_poor[path], 0.5 * capacity[path], 1e-12);
    EXPECT_NEAR(from_rich[path], capacity[path], 1e-12);
  }
}

}  // namespace
}  // namespace heliostand::roots
