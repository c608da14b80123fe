// Seed 000's last two figures on the conifer (seed 001's branching pattern), as measured quantities averaged over
// seeds (docs/model.md, table of findings):
//  - Fig. 16: heliotropism works with a conifer branching pattern: beside a neighbour, the shoots that flush in the
//    stand turn toward the open side with heliotropism (I = 0.4) more than without (I = 0), everything else equal,
//    in every seed. The crown as a whole does not lean further away with it (a deviation, recorded: docs/model.md);
//  - Fig. 17: with an active period, lower boughs past it die and fall, so the crown base rises with age and the
//    lower stem is bare without any special long root branch; a tree whose boughs never end their active period
//    keeps its crown to the ground.
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

#include "architecture/conifer_tree.hpp"
#include "light/reference_light_solver.hpp"
#include "stand/production_sky.hpp"
#include "stand/stand.hpp"
#include "stand/stand_year.hpp"

namespace heliostand {
namespace {

constexpr int seeds = 3;

ConiferTree lone_tree(std::uint64_t seed, double growth_stop_years, int age) {
  TreeCalibration calibration;
  calibration.growth_stop_years_first_order = growth_stop_years;
  ConiferTree tree(SpeciesParameters{}, calibration, {0.0, 0.0, 0.0}, seed, 0);
  tree.grow_to_age(age);
  return tree;
}

TEST(ConiferFindings, Fig17ActivePeriodRaisesTheCrownBaseWithAgeAndBaresTheLowerStem) {
  // Crown base (lowest living first-order branch) at ages 10, 20, 30, means over seeds; seed 001's calibrated
  // active period (growth stop after 18 years for first order, eq. 12) vs one no bough outlives (1000 years).
  const std::vector<int> ages{10, 20, 30};
  std::vector<double> with_period(ages.size(), 0.0), endless(ages.size(), 0.0);
  for (int s = 1; s <= seeds; ++s)
    for (std::size_t a = 0; a < ages.size(); ++a) {
      with_period[a] += lone_tree(s, 18.0, ages[a]).crown_base_m() / seeds;
      endless[a] += lone_tree(s, 1000.0, ages[a]).crown_base_m() / seeds;
    }
  std::cerr << "crown base (m) at 10/20/30 years: active period " << with_period[0] << " / " << with_period[1]
            << " / " << with_period[2] << "; endless " << endless[0] << " / " << endless[1] << " / " << endless[2]
            << "\n";
  EXPECT_LT(with_period[0], with_period[1]);
  EXPECT_LT(with_period[1], with_period[2]);
  EXPECT_GT(with_period[2], endless[2] + 1.0);  // the bare lower stem comes from the active period alone
}

// The tree beside its neighbour after the stand's light response.
struct BesideANeighbour {
  double new_shoots_toward_east = 0;  // mean x of the unit directions of the shoots flushed in the stand (< 0: west)
  double crown_lean_m = 0;            // mean x of the leaf balls from the stem (< 0: leaning west)
};

// A tree with one neighbour 1.5 m to the east, both 8 years old, grown 4 years with the stand's light response.
BesideANeighbour beside_a_neighbour(std::uint64_t seed, double heliotropism) {
  SpeciesParameters species;
  species.heliotropism_strength = heliotropism;
  std::vector<StandTree> trees;
  for (int id = 0; id < 2; ++id) {
    TreeCalibration calibration;
    calibration.site_asymptote_m = 24.0;
    ConiferTree tree(species, calibration, {1.5 * id, 0.0, 0.0}, seed + 10 * id, id);
    tree.grow_to_age(8);
    trees.push_back(StandTree{id, std::to_string(id), "todomatsu", std::move(tree)});
  }
  Stand stand(0.01, 8, std::move(trees), {});
  ReferenceLightSolver solver(testing::production_sky(4, 8));
  StageClock clock;
  StandYear simulated_year(stand, solver, solver, nullptr, nullptr, {seed, 1.0, 4, 1}, clock);
  for (int year = 0; year <= 4; ++year) simulated_year.run(year);
  const ConiferTree& tree = stand.trees()[0].conifer;
  BesideANeighbour found;
  int flushed = 0;
  for (const Shoot& shoot : tree.shoots()) {
    if (shoot.parent < 0 || shoot.year_formed <= 8) continue;  // only what flushed in the stand (ages 9-12)
    const glm::dvec3 along = shoot.tip - shoot.base;
    if (glm::length(along) <= 0) continue;
    found.new_shoots_toward_east += glm::normalize(along).x;
    ++flushed;
  }
  if (flushed > 0) found.new_shoots_toward_east /= flushed;
  const auto balls = tree.leaf_balls();
  for (const LeafBall& ball : balls) found.crown_lean_m += (ball.centre.x - tree.stem_base().x) / balls.size();
  return found;
}

// Until 2026-11-24 this test asserted the crown's lean (the mean leaf-ball x) over 3 seeds; it passed by the luck of
// seeds 2 and 3. Over 16 seeds the crown leans *less* away from its neighbour with heliotropism (+0.011 m; 11 of 16
// seeds), while its new shoots turn west in all 16 (docs/model.md, Fig. 16's deviation). The turn is asserted seed by
// seed; the lean is printed, the deviation recorded.
constexpr int fig16_seeds = 16;

TEST(ConiferFindings, Fig16HeliotropismTurnsAConifersNewShootsTowardTheOpenSide) {
  double lean_with = 0.0, lean_without = 0.0;
  for (int s = 1; s <= fig16_seeds; ++s) {
    const BesideANeighbour with = beside_a_neighbour(s, 0.4), without = beside_a_neighbour(s, 0.0);
    EXPECT_LT(with.new_shoots_toward_east, without.new_shoots_toward_east) << "seed " << s;
    std::cerr << "seed " << s << ": new shoots' mean direction x " << with.new_shoots_toward_east << " with I = 0.4, "
              << without.new_shoots_toward_east << " with I = 0; crown lean " << with.crown_lean_m << " vs "
              << without.crown_lean_m << " m\n";
    lean_with += with.crown_lean_m / fig16_seeds;
    lean_without += without.crown_lean_m / fig16_seeds;
  }
  std::cerr << "recorded (deviation): mean leaf-ball x from the stem (neighbour at +1.5 m) over " << fig16_seeds
            << " seeds: I = 0.4 " << lean_with << " m, I = 0 " << lean_without << " m\n";
}

}  // namespace
}  // namespace heliostand
