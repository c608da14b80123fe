// Every thinning regime applied to a stand of grown trees (Stand::thin): the right trees leave, and the stand table
// (records/stand_metrics.hpp, what stand_table.csv writes) drops by exactly what they carried. Triggered thinnings fire
// in the year their condition first holds, and re-arm only when told.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <glm/geometric.hpp>

#include "light/reference_light_solver.hpp"
#include "records/stand_metrics.hpp"
#include "records/stand_table_ledger.hpp"
#include "stand/crop_tree_thinning.hpp"
#include "stand/production_sky.hpp"
#include "stand/size_thinning.hpp"
#include "stand/snapshot.hpp"
#include "stand/stand.hpp"

namespace heliostand {
namespace {

constexpr std::uint64_t regime_seed = 3;

StandTree planted_light_driven(int id, glm::dvec3 position, double site_asymptote_m, int age) {
  TreeCalibration calibration;
  calibration.site_asymptote_m = site_asymptote_m;
  ConiferTree tree(SpeciesParameters{}, calibration, position, regime_seed, id);
  tree.grow_to_age(age);
  tree.set_light_driven_crown(true);
  return StandTree{id, "t" + std::to_string(id), "todomatsu", std::move(tree)};
}

// Six planted rows running east, 3 m apart, of four trees 1.5 m apart (a 6 m x 18 m plot, 0.0108 ha), 12 years
// old, each on its own site (height-curve asymptote 18 to 29.5 m, shuffled over the plot) so that no two have the same
// DBH. Tree 4r + k stands in row r (0-based, from the south).
constexpr int rows = 6, per_row = 4;
std::vector<StandTree> six_rows() {
  std::vector<StandTree> trees;
  for (int r = 0; r < rows; ++r)
    for (int k = 0; k < per_row; ++k) {
      const int id = per_row * r + k;
      trees.push_back(
          planted_light_driven(id, {0.75 + 1.5 * k, 1.5 + 3.0 * r, 0.0}, 18.0 + 0.5 * ((id * 7) % 24), 12));
    }
  return trees;
}
constexpr double plot_area_ha = 6.0 * 18.0 / 1e4;

ThinningEvent at_age(int age, ThinningRule rule) { return {{age}, std::move(rule), "test thinning", true}; }

ThinningRule rule_of(ThinningMethod method) {
  ThinningRule rule;
  rule.method = method;
  return rule;
}

// The stand table row of the stand as it is, with `events` as the flows since the last row.
StandTableRow table_row(const Stand& stand, const std::vector<TreeEvent>& events) {
  SnapshotTracker snapshots(false);
  const StandInventory inventory = inventory_of(snapshots.take(stand, 0));
  return measure_row(inventory, whole_stand_species, inventory.living, events, stand.plot_area_ha());
}

std::set<std::string> labels(const std::vector<TreeEvent>& events) {
  std::set<std::string> out;
  for (const auto& e : events) out.insert(e.label);
  return out;
}

// Thins `stand` once and checks the table: living stems and basal area fall by what the removals carried.
std::vector<TreeEvent> thin_and_check_table(Stand& stand) {
  const StandTableRow before = table_row(stand, {});
  const std::vector<TreeEvent> removed = stand.thin();
  const StandTableRow after = table_row(stand, removed);
  double basal_area = 0, volume = 0;
  for (const auto& tree : removed) {
    basal_area += basal_area_m2(tree.dbh_cm) / stand.plot_area_ha();
    volume += tree.volume_m3 / stand.plot_area_ha();
  }
  EXPECT_NEAR(after.removed.stems, removed.size() / stand.plot_area_ha(), 1e-9);
  EXPECT_NEAR(after.removed.basal_area_m2, basal_area, 1e-9);
  EXPECT_NEAR(after.living.stems_per_ha, before.living.stems_per_ha - after.removed.stems, 1e-9);
  EXPECT_NEAR(after.living.basal_area_m2_per_ha, before.living.basal_area_m2_per_ha - basal_area, 1e-9);
  EXPECT_NEAR(after.living.volume_m3_per_ha, before.living.volume_m3_per_ha - volume, 1e-9);
  return removed;
}

// Labels of the living trees by DBH, smallest first (ties in tree order).
std::vector<std::string> by_dbh(const std::vector<StandTree>& trees) {
  std::vector<const StandTree*> order;
  for (const auto& tree : trees) order.push_back(&tree);
  std::stable_sort(order.begin(), order.end(),
                   [](auto* a, auto* b) { return a->conifer.dbh_cm() < b->conifer.dbh_cm(); });
  std::vector<std::string> out;
  for (auto* tree : order) out.push_back(tree->label);
  return out;
}

TEST(ThinningRegimesInAStand, EveryTreeHasItsOwnDbh) {
  const auto trees = six_rows();
  std::set<double> dbh;
  for (const auto& tree : trees) dbh.insert(tree.conifer.dbh_cm());
  EXPECT_EQ(dbh.size(), trees.size());  // the rankings below have no ties to break
}

TEST(ThinningRegimesInAStand, FromBelowAndFromAboveTakeTheEndsOfTheDbhRanking) {
  const auto ranking = by_dbh(six_rows());
  auto low = rule_of(ThinningMethod::from_below);
  low.remove_fraction = 0.25;  // 6 of 24
  Stand below(plot_area_ha, 20, six_rows(), {at_age(20, low)});
  EXPECT_EQ(labels(thin_and_check_table(below)), std::set<std::string>(ranking.begin(), ranking.begin() + 6));

  auto high = rule_of(ThinningMethod::from_above);
  high.target_stems_per_ha = 18 / plot_area_ha;  // keep 18
  Stand above(plot_area_ha, 20, six_rows(), {at_age(20, high)});
  EXPECT_EQ(labels(thin_and_check_table(above)), std::set<std::string>(ranking.end() - 6, ranking.end()));
}

TEST(ThinningRegimesInAStand, NeutralTakesEvenlyAcrossTheDbhRanking) {
  const auto ranking = by_dbh(six_rows());
  auto neutral = rule_of(ThinningMethod::neutral);
  neutral.remove_fraction = 0.25;
  Stand stand(plot_area_ha, 20, six_rows(), {at_age(20, neutral)});
  std::set<std::string> expected;
  for (std::size_t rank : neutral_ranks(6, 24)) expected.insert(ranking[rank]);  // ranks 2, 6, 10, 14, 18, 22
  EXPECT_EQ(labels(thin_and_check_table(stand)), expected);
}

TEST(ThinningRegimesInAStand, DbhClassTakesTheClass) {
  auto trees = six_rows();
  const auto ranking = by_dbh(trees);
  // The class from the 5th to the 12th smallest DBH (half-open at the 13th).
  auto dbh_of = [&](const std::string& label) {
    return std::find_if(trees.begin(), trees.end(), [&](auto& t) { return t.label == label; })->conifer.dbh_cm();
  };
  auto in_class = rule_of(ThinningMethod::dbh_class);
  in_class.dbh_class = {dbh_of(ranking[4]), dbh_of(ranking[12])};
  ASSERT_LT(dbh_of(ranking[3]), dbh_of(ranking[4]));
  ASSERT_LT(dbh_of(ranking[11]), dbh_of(ranking[12]));
  Stand stand(plot_area_ha, 20, std::move(trees), {at_age(20, in_class)});
  EXPECT_EQ(labels(thin_and_check_table(stand)), std::set<std::string>(ranking.begin() + 4, ranking.begin() + 12));
}

TEST(ThinningRegimesInAStand, RowThinningTakesEveryThirdPlantedRow) {
  auto every_third = rule_of(ThinningMethod::rows);
  every_third.rows.interval = 3;
  every_third.rows.first_row = 2;  // rows 2 and 5 (0-based 1 and 4), found from the positions
  Stand stand(plot_area_ha, 20, six_rows(), {at_age(20, every_third)});
  std::set<std::string> expected;
  for (int r : {1, 4})
    for (int k = 0; k < per_row; ++k) expected.insert("t" + std::to_string(per_row * r + k));
  EXPECT_EQ(labels(thin_and_check_table(stand)), expected);
}

TEST(ThinningRegimesInAStand, CropTreeThinningReleasesTheCropTrees) {
  // Two crop trees at least 9 m apart, each losing every tree within 2 m (its in-row neighbours, 1.5 m away).
  auto release = rule_of(ThinningMethod::crop_tree);
  release.crop_trees = {2 / plot_area_ha, 9.0, 2.0, std::nullopt};
  Stand stand(plot_area_ha, 20, six_rows(), {at_age(20, release)});
  std::vector<ThinningCandidate> candidates;
  for (const auto& tree : stand.trees())
    candidates.push_back({tree.label, tree.conifer.dbh_cm(), false, tree.conifer.height_m(), tree.conifer.stem_base().x,
                          tree.conifer.stem_base().y});
  const auto crop_trees = select_crop_trees(release.crop_trees, candidates, ThinningPlot{plot_area_ha, {}});
  ASSERT_EQ(crop_trees.size(), 2u);
  std::set<std::string> expected;
  for (std::size_t crop_tree : crop_trees)
    for (const auto& tree : stand.trees())
      if (tree.id != static_cast<int>(crop_tree) &&
          glm::length(tree.conifer.stem_base() - stand.trees()[crop_tree].conifer.stem_base()) < 2.0)
        expected.insert(tree.label);
  ASSERT_FALSE(expected.empty());

  const auto before = stand.hegyi_indices();
  EXPECT_EQ(labels(thin_and_check_table(stand)), expected);
  // Released: each crop tree's competition index falls; a removed tree has none.
  const auto after = stand.hegyi_indices();
  for (std::size_t crop_tree : crop_trees) {
    EXPECT_TRUE(stand.trees()[crop_tree].alive());
    EXPECT_LT(after[crop_tree], before[crop_tree]);
  }
  for (const auto& tree : stand.trees())
    if (!tree.alive()) EXPECT_TRUE(std::isnan(after[static_cast<std::size_t>(tree.id)])) << tree.label;
}

TEST(ThinningRegimesInAStand, HabitatTreesStayInEveryRegime) {
  auto every_second = rule_of(ThinningMethod::rows);
  every_second.rows.interval = 2;  // rows 1, 3, 5: trees 0..3, 8..11, 16..19
  auto trees = six_rows();
  trees[1].hollows.push_back(hollow::HollowSpec{});
  Stand stand(plot_area_ha, 20, std::move(trees), {at_age(20, every_second)});
  const auto removed = labels(thin_and_check_table(stand));
  EXPECT_EQ(removed.size(), 11u);
  EXPECT_FALSE(removed.count("t1"));
}

TEST(ThinningRegimesInAStand, SnapshotsCarryTheHegyiIndexOfTheLivingTrees) {
  auto every_second = rule_of(ThinningMethod::rows);
  every_second.rows.interval = 2;
  Stand stand(plot_area_ha, 20, six_rows(), {at_age(20, every_second)});
  stand.thin();
  const auto index = stand.hegyi_indices();
  SnapshotTracker snapshots(false);
  const StandSnapshot snapshot = snapshots.take(stand, 0);
  ASSERT_EQ(snapshot.trees.size(), stand.trees().size());  // the removed ones are shown once
  for (const auto& tree : snapshot.trees) {
    if (tree.status == TreeStatus::alive) {
      EXPECT_GT(tree.hegyi_index, 0.0) << tree.label;  // rows 3 m apart, trees 1.5 m apart: neighbours within 6 m
      EXPECT_EQ(tree.hegyi_index, index[static_cast<std::size_t>(tree.id)]) << tree.label;
    } else {
      EXPECT_TRUE(std::isnan(tree.hegyi_index)) << tree.label;
    }
  }
}

using testing::coarse_sky;

// Steps 1 to 5 of the simulated year (stand/stand_year.hpp, no roots): the stand as the thinning step finds it.
void grow_until_thinning(Stand& stand, LightSolver& solver, int year) {
  if (year > 0) stand.grow_year();
  stand.illuminate(solver, solver);
  if (year == 0) return;
  stand.respond_to_light(regime_seed);
  stand.apply_mortality(regime_seed);
}

// A stand grown in its own light: a thinning from below fires in the first year the basal area exceeds its
// threshold — not at the start, where it is below — and only then.
TEST(TriggeredThinning, FiresTheYearBasalAreaExceedsItsThresholdAndOnlyThen) {
  Stand probe(plot_area_ha, 20, six_rows(), {});
  const double start = table_row(probe, {}).living.basal_area_m2_per_ha;
  auto low = rule_of(ThinningMethod::from_below);
  low.remove_fraction = 0.25;
  const ThinningTrigger dense{0, StandCondition{StandCondition::Measure::basal_area_m2_per_ha, start * 1.002}};
  ThinningEvent when_dense{dense, low, "low thinning", true};
  Stand stand(plot_area_ha, 20, six_rows(), {when_dense});

  ReferenceLightSolver solver(coarse_sky());
  std::vector<int> fired_at;
  for (int year = 0; year <= 4; ++year) {
    grow_until_thinning(stand, solver, year);
    const double basal_area = table_row(stand, {}).living.basal_area_m2_per_ha;
    std::vector<std::string> ranking;
    for (const auto& label : by_dbh(stand.trees()))
      if (std::any_of(stand.trees().begin(), stand.trees().end(),
                      [&](auto& t) { return t.label == label && t.alive(); }))
        ranking.push_back(label);
    const auto removed = thin_and_check_table(stand);
    EXPECT_EQ(!removed.empty(), basal_area > start * 1.002 && fired_at.empty()) << "year " << year;
    if (removed.empty()) continue;
    fired_at.push_back(stand.stand_age());
    const auto count = static_cast<std::size_t>(std::lround(0.25 * static_cast<double>(ranking.size())));
    EXPECT_EQ(labels(removed), std::set<std::string>(ranking.begin(), ranking.begin() + count));
  }
  ASSERT_EQ(fired_at.size(), 1u);
  EXPECT_GT(fired_at[0], 20);
}

TEST(TriggeredThinning, ARepeatingTriggerFiresAgainAfterItsInterval) {
  Stand probe(plot_area_ha, 20, six_rows(), {});
  const double top_height = table_row(probe, {}).living.top_height_m;
  auto low = rule_of(ThinningMethod::from_below);
  low.remove_fraction = 0.1;  // the tallest tree stays: the top height holds
  const ThinningTrigger tall{0, StandCondition{StandCondition::Measure::top_height_m, top_height}, 2};
  ThinningEvent when_tall{tall, low, "low thinning", true};
  Stand stand(plot_area_ha, 20, six_rows(), {when_tall});
  ReferenceLightSolver solver(coarse_sky());
  std::vector<int> fired_at;
  for (int year = 0; year <= 5; ++year) {
    grow_until_thinning(stand, solver, year);
    if (!stand.thin().empty()) fired_at.push_back(stand.stand_age());
  }
  EXPECT_EQ(fired_at, (std::vector<int>{20, 22, 24}));
}

}  // namespace
}  // namespace heliostand
