#include "architecture/conifer_tree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "architecture/branch_angle.hpp"
#include "architecture/branch_diameter.hpp"
#include "architecture/elongation.hpp"
#include "architecture/height_curve.hpp"
#include "architecture/lower_order_branching.hpp"
#include "architecture/stem_taper.hpp"
#include "geometry/angles.hpp"

namespace heliostand {
namespace {

ConiferTree grown(int age, TreeCalibration calibration = {}, std::uint64_t seed = 42, int tree_id = 1,
                  SpeciesParameters species = {}) {
  ConiferTree tree(species, calibration, {10.0, -5.0, 1.0}, seed, tree_id);
  tree.grow_to_age(age);
  return tree;
}

double angle_from_vertical_deg(glm::dvec3 v) { return degrees(std::acos(v.z / glm::length(v))); }

TEST(ConiferTree, StemFollowsTheHeightCurveOneShootPerYear) {
  const ConiferTree tree = grown(20);
  EXPECT_NEAR(tree.height_m(), tree_height_m(SpeciesParameters{}, 28.0, 20.0), 1e-12);
  const auto& stem = tree.axes()[0].shoots;
  ASSERT_EQ(stem.size(), 20u);
  for (std::size_t i = 0; i < stem.size(); ++i) {
    const Shoot& s = tree.shoots()[stem[i]];
    EXPECT_EQ(s.year_formed, static_cast<int>(i) + 1);
    EXPECT_NEAR(s.tip.z - tree.stem_base().z, tree_height_m(SpeciesParameters{}, 28.0, i + 1.0), 1e-9);
    EXPECT_NEAR(s.tip.x, tree.stem_base().x, 1e-12);  // vertical
  }
}

TEST(ConiferTree, WhorlsAverageEq3BranchesAndSitOnLastYearsLeaderTip) {
  // Long-lived first-order branches so every whorl is still there to count; 200 trees × 19 whorls.
  TreeCalibration calibration;
  calibration.growth_stop_years_first_order = 100.0;
  calibration.elongation_scale = 0.05;  // tiny shoots: no laterals, fast
  std::map<int, int> per_whorl;
  int whorls = 0, branches = 0;
  for (int id = 0; id < 200; ++id) {
    const ConiferTree tree = grown(20, calibration, 9, id);
    per_whorl.clear();
    for (const BranchAxis& axis : tree.axes()) {
      if (axis.order != 1) continue;
      ++per_whorl[axis.year_formed];
      const Shoot& first = tree.shoots()[axis.shoots.front()];
      EXPECT_NEAR(first.base.z - tree.stem_base().z, tree_height_m(SpeciesParameters{}, 28.0, axis.year_formed - 1),
                  1e-9);
    }
    EXPECT_EQ(per_whorl.size(), 19u);  // one whorl a year from age 2
    for (const auto& [year, n] : per_whorl) ++whorls, branches += n;
  }
  // 3800 whorls: standard error sqrt(0.564 × 0.436 / 3800) = 0.0080; 0.035 is 4.4 standard errors
  // (and rejects a plain 4-or-5 coin, mean 4.5).
  EXPECT_NEAR(static_cast<double>(branches) / whorls, 4.564, 0.035);
}

TEST(ConiferTree, NewWhorlTipsLieOnTheCrownCone) {
  const ConiferTree tree = grown(12);  // elongation scale 1: eq. 9 unscaled
  const glm::dvec3 top = tree.stem_base() + glm::dvec3{0, 0, tree.height_m()};
  int checked = 0;
  for (const BranchAxis& axis : tree.axes()) {
    if (axis.order != 1 || axis.year_formed != 12) continue;
    const Shoot& s = tree.shoots()[axis.shoots.front()];
    const glm::dvec3 from_top = s.tip - top;
    EXPECT_NEAR(degrees(std::atan2(std::hypot(from_top.x, from_top.y), -from_top.z)),
                crown_angle_deg(SpeciesParameters{}, 12.0), 1e-6);
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

TEST(ConiferTree, UndisturbedFirstOrderChordFollowsEq4AndTheTipTurnsUp) {
  const ConiferTree tree = grown(25);
  int checked = 0;
  for (const BranchAxis& axis : tree.axes()) {
    if (axis.order != 1 || !axis.alive) continue;
    const glm::dvec3 chord = tree.shoots()[axis.shoots.back()].tip - tree.shoots()[axis.shoots.front()].base;
    // eq. 4: 60 + (0.3 + 0.5) × years since emergence
    EXPECT_NEAR(angle_from_vertical_deg(chord), 60.0 + 0.8 * (25 - axis.year_formed), 1e-6);
    if (axis.shoots.size() >= 3) {
      const Shoot& newest = tree.shoots()[axis.shoots.back()];
      EXPECT_LT(angle_from_vertical_deg(newest.tip - newest.base), angle_from_vertical_deg(chord));  // anti-gravity
    }
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST(ConiferTree, FirstOrderElongationFollowsEq8) {
  const ConiferTree tree = grown(15);
  for (const BranchAxis& axis : tree.axes()) {
    if (axis.order != 1 || axis.shoots.size() < 5) continue;
    double total = 0.0;
    for (int s : axis.shoots) total += glm::length(tree.shoots()[s].tip - tree.shoots()[s].base);
    EXPECT_NEAR(total, total_elongation_m(axis.initial_elongation_m, axis.shoots.size(), 0.9), 1e-9);
  }
}

TEST(ConiferTree, SecondOrderPairsFlushAtLastYearsTipWithLinearElongation) {
  const ConiferTree tree = grown(10);
  int pairs = 0;
  for (const BranchAxis& axis : tree.axes()) {
    if (axis.order != 2) continue;
    const Shoot& first = tree.shoots()[axis.shoots.front()];
    const Shoot& bearing = tree.shoots()[first.parent];
    EXPECT_EQ(bearing.axis, axis.parent_axis);
    EXPECT_EQ(bearing.year_formed, axis.year_formed - 1);
    EXPECT_NEAR(glm::length(first.base - bearing.tip), 0.0, 1e-12);
    EXPECT_NEAR(axis.initial_elongation_m, 0.45 * glm::length(bearing.tip - bearing.base), 1e-12);
    ++pairs;
  }
  EXPECT_GT(pairs, 20);
}

TEST(ConiferTree, SecondOrderPairsSpreadFiftyDegreesWithUpDownJitter) {
  const ConiferTree tree = grown(10);
  double smallest = 180.0, largest = 0.0;
  int left = 0, right = 0;
  for (const BranchAxis& axis : tree.axes()) {
    if (axis.order != 2) continue;
    const Shoot& first = tree.shoots()[axis.shoots.front()];
    const Shoot& bearing = tree.shoots()[first.parent];
    const glm::dvec3 along = glm::normalize(bearing.tip - bearing.base);
    const glm::dvec3 out = glm::normalize(first.tip - first.base);
    const double spread = degrees(std::acos(std::clamp(glm::dot(along, out), -1.0, 1.0)));
    smallest = std::min(smallest, spread), largest = std::max(largest, spread);
    // 50° from the parent, tilted up or down by at most 10°: within 50 ± 10°.
    EXPECT_GE(spread, 40.0 - 1e-9);
    EXPECT_LE(spread, 60.0 + 1e-9);
    (glm::dot(glm::cross(along, glm::dvec3{0, 0, 1}), out) > 0.0 ? left : right)++;
  }
  EXPECT_GT(largest - smallest, 5.0);  // the jitter is there
  EXPECT_EQ(left, right);              // opposite pairs
}

TEST(ConiferTree, ThirdOrderBudsFlushAtTheTableRateOfTheirParentShoot) {
  SpeciesParameters species;
  species.activity = -5.0;           // S2 = 13, S3 = 8: third order grows
  species.min_parent_length_m = 0.0;  // the table alone decides
  TreeCalibration calibration;
  calibration.elongation_scale = 0.6;  // second-order shoots of 2-7 cm: the table's uncertain rows
  double expected = 0.0, variance = 0.0;
  int flushed = 0, uncertain_events = 0;
  for (int id = 0; id < 6; ++id) {
    ConiferTree tree(species, calibration, {}, 77, id);
    tree.grow_to_age(12);
    std::map<int, int> thirds_on;  // bearing shoot → third-order laterals on it
    for (const BranchAxis& axis : tree.axes())
      if (axis.order == 3) ++thirds_on[tree.shoots()[axis.shoots.front()].parent];
    for (const BranchAxis& axis : tree.axes()) {
      if (axis.order != 2) continue;
      // Every shoot but the newest bore a pair attempt the year after it flushed (the axis grew on).
      for (std::size_t k = 0; k + 1 < axis.shoots.size(); ++k) {
        const Shoot& bearing = tree.shoots()[axis.shoots[k]];
        const double p = lateral_occurrence_probability(species, 3, glm::length(bearing.tip - bearing.base));
        expected += 2.0 * p;
        variance += 2.0 * p * (1.0 - p);
        if (p > 0.0 && p < 1.0) ++uncertain_events;
        flushed += thirds_on[axis.shoots[k]];
      }
    }
  }
  ASSERT_GT(uncertain_events, 200);
  EXPECT_NEAR(flushed, expected, 4.0 * std::sqrt(variance)) << "expected " << expected << " ± " << std::sqrt(variance);
}

TEST(ConiferTree, LowerBranchesStopDieAndFallSoTheCrownBaseRises) {
  TreeCalibration calibration;
  calibration.growth_stop_years_first_order = 10.0;
  const SpeciesParameters species;  // dead branches stay attached 10 years
  ConiferTree tree(species, calibration, {}, 3, 7);
  double previous_base = -1.0;
  for (int age = 1; age <= 30; ++age) {
    tree.grow_year();
    if (age < 12) continue;
    // Living whorls are those formed in the last 10 years: the lowest from age - 9, at height H(age - 10).
    EXPECT_NEAR(tree.crown_base_m(), tree_height_m(species, 28.0, age - 10), 1e-9) << "age " << age;
    EXPECT_GT(tree.crown_base_m(), previous_base);
    previous_base = tree.crown_base_m();
  }
  int dead_first_order = 0;
  for (const BranchAxis& axis : tree.axes()) {
    if (axis.order != 1) continue;
    const int years_since_emergence = 30 - axis.year_formed;
    EXPECT_EQ(axis.alive, years_since_emergence < 10);
    if (axis.alive) continue;
    ++dead_first_order;
    const int years_dead = 30 - axis.year_stopped;
    EXPECT_LT(years_dead, 10) << "a branch dead for 10 years has fallen";
    double length = 0.0;
    for (int s : axis.shoots) {
      EXPECT_FALSE(tree.shoots()[s].alive);
      length += glm::length(tree.shoots()[s].tip - tree.shoots()[s].base);
    }
    // eq. 13: (years dead / 10) of the length at death has gone from the tip; a shoot falls once it lies
    // wholly in that lost part, so the remaining tip shoot straddles the boundary.
    const double kept = (1.0 - years_dead / 10.0) * axis.length_at_death_m;
    const Shoot& tip = tree.shoots()[axis.shoots.back()];
    EXPECT_GE(length, kept - 1e-9);
    EXPECT_LT(length - glm::length(tip.tip - tip.base), kept);
    if (years_dead >= 2) EXPECT_LT(length, axis.length_at_death_m - 1e-9);  // something has already fallen
  }
  EXPECT_GT(dead_first_order, 20);  // dead branches persist below the crown
}

TEST(ConiferTree, SameSeedSameTreeDifferentSeedDifferentTree) {
  const ConiferTree a = grown(15, {}, 42, 1), b = grown(15, {}, 42, 1);
  ASSERT_EQ(a.shoots().size(), b.shoots().size());
  for (std::size_t i = 0; i < a.shoots().size(); ++i) {
    EXPECT_EQ(a.shoots()[i].tip, b.shoots()[i].tip);
    EXPECT_EQ(a.shoots()[i].parent, b.shoots()[i].parent);
  }
  const ConiferTree c = grown(15, {}, 43, 1), d = grown(15, {}, 42, 2);
  auto first_whorl_tip = [](const ConiferTree& t) { return t.shoots()[t.axes()[1].shoots.front()].tip; };
  EXPECT_NE(first_whorl_tip(a), first_whorl_tip(c));
  EXPECT_NE(first_whorl_tip(a), first_whorl_tip(d));
}

TEST(ConiferTree, GrowingOtherTreesInBetweenChangesNothing) {
  ConiferTree alone({}, {}, {}, 5, 3);
  alone.grow_to_age(12);
  ConiferTree interleaved({}, {}, {}, 5, 3), neighbour({}, {}, {}, 5, 4);
  for (int year = 0; year < 12; ++year) neighbour.grow_year(), interleaved.grow_year();
  ASSERT_EQ(alone.shoots().size(), interleaved.shoots().size());
  for (std::size_t i = 0; i < alone.shoots().size(); ++i) EXPECT_EQ(alone.shoots()[i].tip, interleaved.shoots()[i].tip);
}

// Memory (issue 16): a year's new shoots and fallen branches leave the crown's lists no bigger than they hold,
// through the years when branches fall (remove_flagged) as well as those when none do.
TEST(ConiferTree, ShootAndAxisListsHoldNoSpareCapacityAfterAYear) {
  ConiferTree tree({}, {}, {}, 5, 3);
  for (int year = 0; year < 30; ++year) {
    tree.grow_year();
    EXPECT_EQ(tree.shoots().capacity(), tree.shoots().size()) << "age " << tree.age();
    EXPECT_EQ(tree.axes().capacity(), tree.axes().size()) << "age " << tree.age();
  }
}

TEST(ConiferTree, LeafBallsOnRecentLivingShootsWithClampedRadius) {
  const ConiferTree tree = grown(20);
  const SpeciesParameters species;
  // A leaf ball on every living shoot of the last foliage_years years whose order is at most
  // foliage_max_order (default 1: stem and first-order shoots; their laterals' foliage is lumped in).
  auto carries = [&](const Shoot& s) {
    return s.alive && s.order <= species.foliage_max_order && s.year_formed > 20 - species.foliage_years;
  };
  std::size_t expected = 0, second_order = 0;
  for (const Shoot& s : tree.shoots()) {
    if (carries(s)) ++expected;
    if (s.alive && s.order == 2) ++second_order;
  }
  ASSERT_GT(second_order, 0u) << "the tree must have laterals for this test to mean anything";
  const auto balls = tree.leaf_balls();
  EXPECT_EQ(balls.size(), expected);
  const auto owners = tree.foliage_shoot_indices();
  ASSERT_EQ(owners.size(), balls.size());
  for (std::size_t b = 0; b < balls.size(); ++b) {
    EXPECT_EQ(tree.shoots()[owners[b]].tip, balls[b].centre);
    EXPECT_LE(tree.shoots()[owners[b]].order, species.foliage_max_order);
  }
  std::size_t ball = 0;
  for (const Shoot& s : tree.shoots()) {
    if (!carries(s)) continue;
    const double length = glm::length(s.tip - s.base);
    EXPECT_EQ(balls[ball].centre, s.tip);
    EXPECT_NEAR(balls[ball].radius, std::clamp(2.0 * length, 0.05, 0.6), 1e-12);
    ++ball;
  }
}

TEST(ConiferTree, FoliageMaxOrderGivesLateralsTheirOwnLeafBalls) {
  SpeciesParameters every_order;
  every_order.foliage_max_order = 3;
  ConiferTree lumped(SpeciesParameters{}, TreeCalibration{}, {0, 0, 0}, 1, 0);
  ConiferTree own(every_order, TreeCalibration{}, {0, 0, 0}, 1, 0);
  lumped.grow_to_age(20);
  own.grow_to_age(20);
  std::size_t recent_living = 0;
  for (const Shoot& s : own.shoots())
    if (s.alive && s.year_formed > 20 - every_order.foliage_years) ++recent_living;
  EXPECT_EQ(own.leaf_balls().size(), recent_living);
  EXPECT_GT(own.leaf_balls().size(), 2 * lumped.leaf_balls().size());
}

TEST(ConiferTree, CrownRadiusOfATwoYearOldIsTheMeanSectorReach) {
  const SpeciesParameters species;
  const ConiferTree tree = grown(2);
  // Two stem shoots (balls on the axis: reach = ball radius, sector 0) and one whorl of branches at d0 = 60°,
  // each one shoot of the eq.-9 length e.
  const double h1 = tree_height_m(species, 28.0, 1.0), h2 = tree_height_m(species, 28.0, 2.0);
  const double e = first_order_initial_elongation_m(species, h2 - h1, 2.0);
  std::array<double, 8> reach{};
  reach[0] = std::max(std::clamp(2.0 * h1, 0.05, 0.6), std::clamp(2.0 * (h2 - h1), 0.05, 0.6));
  for (const BranchAxis& axis : tree.axes()) {
    if (axis.order != 1) continue;
    const int sector = static_cast<int>(axis.azimuth_rad / (pi / 4.0));
    reach[sector] = std::max(reach[sector], e * std::sin(radians(60.0)) + std::clamp(2.0 * e, 0.05, 0.6));
  }
  double mean = 0.0;
  for (double r : reach) mean += r / 8.0;
  EXPECT_NEAR(tree.crown_radius_m(), mean, 1e-9);
}

// Grown alone (no light field: relative light 1), the DBH follows eq. 2's taper within a few per cent (it carries
// its DBH along the taper year by year; the taper changes form where the crown base passes 1.3 m), and the
// volume is the taper's scaled to the tree's own DBH. Set to a surveyed DBH, the volume scales with DBH².
TEST(ConiferTree, DbhAndVolumeFollowEq2AtTheTreesCrownBase) {
  ConiferTree tree = grown(35);
  const StemTaper taper{tree.height_m(), tree.crown_base_m()};
  const double taper_dbh = taper.dbh_cm(SpeciesParameters{});
  EXPECT_NEAR(tree.dbh_cm(), taper_dbh, 0.05 * taper_dbh);
  const double scale = tree.dbh_cm() / taper_dbh;
  EXPECT_NEAR(tree.stem_volume_m3(), scale * scale * taper.volume_m3(SpeciesParameters{}), 1e-12);
  tree.set_survey_state(0.8 * taper_dbh, tree.crown_base_m());
  EXPECT_NEAR(tree.dbh_cm(), 0.8 * taper_dbh, 1e-12);
  EXPECT_NEAR(tree.stem_volume_m3(), 0.64 * taper.volume_m3(SpeciesParameters{}), 1e-9);
  EXPECT_GT(tree.dbh_cm(), 15.0);
  EXPECT_LT(tree.dbh_cm(), 40.0);
}

TEST(ConiferTree, RadiiFollowEq2OnTheStemAndEq11OnBranches) {
  const ConiferTree tree = grown(15);
  const SpeciesParameters species;
  const StemTaper taper{tree.height_m(), tree.crown_base_m()};
  for (int s : tree.axes()[0].shoots) {
    const Shoot& shoot = tree.shoots()[s];
    EXPECT_NEAR(shoot.base_radius_m, taper.diameter_cm(species, shoot.base.z - tree.stem_base().z) / 200.0, 1e-12);
  }
  int branch_shoots = 0;
  for (const BranchAxis& axis : tree.axes()) {
    if (axis.order == 0 || !axis.alive) continue;
    double length = 0.0;
    for (int s : axis.shoots) length += glm::length(tree.shoots()[s].tip - tree.shoots()[s].base);
    EXPECT_NEAR(tree.shoots()[axis.shoots.front()].base_radius_m, branch_diameter_cm(species, length) / 200.0, 1e-12);
    EXPECT_EQ(tree.shoots()[axis.shoots.back()].tip_radius_m, 0.0);
    // Every shoot between, at both ends, by its own length from the branch tip (update_radii carries each base's
    // value to the next shoot's tip, so a slip there would show on the inner shoots only).
    double from_tip = 0.0;
    for (auto s = axis.shoots.rbegin(); s != axis.shoots.rend(); ++s, ++branch_shoots) {
      const Shoot& shoot = tree.shoots()[*s];
      EXPECT_NEAR(shoot.tip_radius_m, branch_diameter_cm(species, from_tip) / 200.0, 1e-12);
      from_tip += glm::length(shoot.tip - shoot.base);
      EXPECT_NEAR(shoot.base_radius_m, branch_diameter_cm(species, from_tip) / 200.0, 1e-12);
    }
  }
  EXPECT_GT(branch_shoots, 100);  // a 15-year tree's branches, many of several shoots
}

TEST(ConiferTree, RemovingAShootTakesEverythingItCarries) {
  ConiferTree tree = grown(12);
  int target_axis = -1;
  for (std::size_t i = 0; i < tree.axes().size(); ++i)
    if (tree.axes()[i].order == 1 && tree.axes()[i].shoots.size() >= 6) target_axis = static_cast<int>(i);
  ASSERT_GE(target_axis, 0);
  const int cut = tree.axes()[target_axis].shoots[2];
  const glm::dvec3 kept_tip = tree.shoots()[tree.axes()[target_axis].shoots[1]].tip;
  const std::size_t before = tree.shoots().size();
  tree.remove_shoot(cut);
  EXPECT_LT(tree.shoots().size(), before - 3);
  // The branch now ends where its second shoot ended; the list stays consistent.
  bool found = false;
  for (const BranchAxis& axis : tree.axes())
    if (axis.order == 1 && axis.shoots.size() == 2 && tree.shoots()[axis.shoots.back()].tip == kept_tip) found = true;
  EXPECT_TRUE(found);
  for (std::size_t i = 0; i < tree.shoots().size(); ++i) {
    const Shoot& s = tree.shoots()[i];
    ASSERT_LT(s.parent, static_cast<int>(i));
    ASSERT_LT(s.axis, static_cast<int>(tree.axes().size()));
    if (s.parent >= 0) EXPECT_NEAR(glm::length(tree.shoots()[s.parent].tip - s.base), 0.0, 1e-9);
  }
  tree.grow_year();  // and growth goes on from the cut
  EXPECT_EQ(tree.age(), 13);
}

TEST(ConiferTree, BendingANewShootKeepsItsBaseAndLength) {
  ConiferTree tree = grown(8);
  const int i = tree.new_shoot_indices().back();
  const Shoot before = tree.shoots()[i];
  tree.bend_shoot(i, {0.0, 0.0, 1.0});
  const Shoot& after = tree.shoots()[i];
  EXPECT_EQ(after.base, before.base);
  EXPECT_NEAR(glm::length(after.tip - after.base), glm::length(before.tip - before.base), 1e-12);
  EXPECT_NEAR(angle_from_vertical_deg(after.tip - after.base), 0.0, 1e-6);
  for (int n : tree.new_shoot_indices()) EXPECT_EQ(tree.shoots()[n].year_formed, 8);
}

// Bending a shoot that already bears laterals carries them along rigidly (every shoot stays attached to its
// bearer's tip) and moves nothing else, before it in the list or after it.
TEST(ConiferTree, BendingABearingShootCarriesItsLateralsAndNothingElse) {
  ConiferTree tree = grown(8);
  const std::vector<Shoot> before = tree.shoots();
  std::vector<char> descends(before.size(), 0);
  int bent = -1;
  for (std::size_t i = 0; i < before.size() && bent < 0; ++i)
    if (before[i].order == 1)
      for (std::size_t j = i + 1; j < before.size(); ++j)
        if (before[j].parent == static_cast<int>(i)) bent = static_cast<int>(i);
  ASSERT_GE(bent, 0) << "no first-order shoot bears another";
  descends[bent] = 1;
  for (std::size_t j = bent + 1; j < before.size(); ++j)
    if (before[j].parent >= 0 && descends[before[j].parent]) descends[j] = 1;
  ASSERT_GT(std::count(descends.begin(), descends.end(), 1), 2);
  ASSERT_LT(bent + 1, static_cast<int>(before.size()) - 1);

  tree.bend_shoot(bent, {0.0, 0.0, 1.0});
  const auto& after = tree.shoots();
  const glm::dvec3 pivot = before[bent].base;
  int moved = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (!descends[i]) {
      EXPECT_EQ(after[i].base, before[i].base) << "shoot " << i;
      EXPECT_EQ(after[i].tip, before[i].tip) << "shoot " << i;
      continue;
    }
    moved += after[i].tip != before[i].tip;
    EXPECT_NEAR(glm::length(after[i].tip - pivot), glm::length(before[i].tip - pivot), 1e-9) << "shoot " << i;
    if (static_cast<int>(i) != bent)
      EXPECT_NEAR(glm::length(after[after[i].parent].tip - after[i].base), 0.0, 1e-9) << "shoot " << i;
  }
  EXPECT_EQ(moved, std::count(descends.begin(), descends.end(), 1));
  EXPECT_NEAR(angle_from_vertical_deg(after[bent].tip - after[bent].base), 0.0, 1e-6);
}

TEST(ConiferTree, AThirtyFiveYearTreeStaysWithinAFewThousandLivingShoots) {
  const ConiferTree tree = grown(35);  // species defaults
  EXPECT_GT(tree.living_shoot_count(), 1000u);
  EXPECT_LT(tree.living_shoot_count(), 8000u);  // 5.5 thousand with the defaults (docs/model.md)
}

}  // namespace
}  // namespace heliostand
