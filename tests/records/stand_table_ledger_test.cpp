// The rows of stand_table.csv, year by year: the whole stand and each species, their flows, and production
// (total production, CAI, MAI), every expectation worked out by hand.
#include "records/stand_table_ledger.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace heliostand {
namespace {

TreeSnapshot tree_with(double dbh_cm, double height_m, double volume_m3, TreeStatus status = TreeStatus::alive) {
  TreeSnapshot t;
  t.species = "todomatsu";
  t.dbh_cm = dbh_cm;
  t.height_m = height_m;
  t.volume_m3 = volume_m3;
  t.status = status;
  return t;
}

TreeEvent removal(int age, const char* species, double dbh_cm, double volume_m3) {
  return {age, 0, "r", species, TreeEventKind::removed, "thinning", "first thinning", dbh_cm, 10.0, volume_m3};
}

TreeEvent death(int age, const char* species, const char* cause, const char* reason, double dbh_cm,
                double volume_m3) {
  return {age, 0, "d", species, TreeEventKind::died, cause, reason, dbh_cm, 10.0, volume_m3};
}

TEST(StandTableRows, CountOnlyLivingTreesAndTurnTheYearsEventsIntoPerHectareFlows) {
  StandSnapshot snapshot;
  snapshot.stand_age = 35;
  snapshot.year_index = 10;
  snapshot.trees = {tree_with(20, 15, 0.25), tree_with(30, 20, 0.75), tree_with(12, 9, 0.05, TreeStatus::dead),
                    tree_with(40, 22, 1.5, TreeStatus::removed)};
  const std::vector<TreeEvent> events = {removal(35, "todomatsu", 40, 1.5), removal(35, "todomatsu", 20, 0.5),
                                         death(35, "todomatsu", "suppression", "suppression", 12, 0.05)};
  StandTableLedger ledger(0.05);
  const auto rows = ledger.rows_of_year(inventory_of(snapshot), events);
  ASSERT_EQ(rows.size(), 2u) << "the whole stand, then its one species";
  const StandTableRow& row = rows[0];
  EXPECT_EQ(row.species, "all");
  EXPECT_EQ(row.stand_age, 35);
  EXPECT_EQ(row.year_index, 10);
  EXPECT_DOUBLE_EQ(row.living.stems_per_ha, 40.0);                                        // 2 / 0.05
  EXPECT_NEAR(row.living.basal_area_m2_per_ha, std::numbers::pi * 0.0325 / 0.05, 1e-12);  // π(0.01+0.0225)
  EXPECT_NEAR(row.living.volume_m3_per_ha, 20.0, 1e-12);                                  // 1.0 / 0.05
  EXPECT_DOUBLE_EQ(row.living.mean_height_m, 17.5);
  EXPECT_DOUBLE_EQ(row.living.top_height_m, 17.5);  // 5 trees wanted on 0.05 ha, only 2 alive: mean of both
  EXPECT_DOUBLE_EQ(row.removed.stems, 40.0);
  EXPECT_NEAR(row.removed.basal_area_m2, std::numbers::pi, 1e-12);  // π(0.04 + 0.01) / 0.05
  EXPECT_NEAR(row.removed.volume_m3, 40.0, 1e-12);                  // 2.0 / 0.05
  EXPECT_DOUBLE_EQ(row.dead.stems, 20.0);
  EXPECT_EQ(rows[1].species, "todomatsu");
  EXPECT_DOUBLE_EQ(rows[1].living.volume_m3_per_ha, row.living.volume_m3_per_ha);
  EXPECT_DOUBLE_EQ(rows[1].removed.volume_m3, row.removed.volume_m3);
}

TEST(StandTableRows, DeathsAreCountedByTheirCauseCodeNotTheirLabel) {
  const std::vector<TreeEvent> events{death(50, "todomatsu", "suppression", "suppression", 20.0, 0.3),
                                      death(50, "todomatsu", "light", "light", 10.0, 0.05),
                                      death(50, "todomatsu", "background", "windthrow", 16.0, 0.2),
                                      removal(50, "todomatsu", 30.0, 0.6)};
  const StandTableRow row = measure_row({50, 20, {}}, "all", {}, events, 1.0);
  EXPECT_DOUBLE_EQ(row.dead.stems, 3.0);
  EXPECT_NEAR(row.dead.basal_area_m2, std::numbers::pi * (0.1 * 0.1 + 0.05 * 0.05 + 0.08 * 0.08), 1e-12);
  EXPECT_DOUBLE_EQ(row.dead_by_cause[0].stems, 1.0);  // light
  EXPECT_DOUBLE_EQ(row.dead_by_cause[1].stems, 1.0);  // suppression
  EXPECT_NEAR(row.dead_by_cause[1].volume_m3, 0.3, 1e-12);
  EXPECT_DOUBLE_EQ(row.dead_by_cause[2].stems, 1.0);  // background, labelled "windthrow"
  EXPECT_DOUBLE_EQ(row.removed.stems, 1.0);
  EXPECT_THROW(measure_row({50, 20, {}}, "all", {}, std::vector{death(50, "todomatsu", "windthrow", "", 9, 0.1)}, 1.0),
               std::logic_error)
      << "a death whose code is no cause of death would be in dead_* but in no dead_<cause>_*";
}

// One tree = 100 stems/ha on 0.01 ha, and 1 m³ = 100 m³/ha.
TEST(StandTableRows, TotalProductionCountsWhatWasRemovedOrDiedAndItsIncrementsFollow) {
  StandTableLedger ledger(0.01);
  // The survey year, age 30: 0.5 + 0.3 + 0.2 m³ standing. Nothing has left yet.
  const auto survey = ledger.rows_of_year({30, 0, {{30, 20, 0.5}, {25, 18, 0.3}, {20, 16, 0.2}}}, {});
  EXPECT_NEAR(survey[0].total_production_m3_per_ha, 100.0, 1e-9);
  EXPECT_TRUE(std::isnan(survey[0].cai_m3_per_ha)) << "the survey year has no year before it";
  EXPECT_NEAR(survey[0].mai_m3_per_ha, 100.0 / 30, 1e-9);
  // Age 31: the 0.3 m³ tree (now 0.32) is thinned, the 0.2 m³ one (now 0.21) dies; 0.56 m³ standing.
  const auto thinned = ledger.rows_of_year({31, 1, {{31, 21, 0.56}}},
                                           std::vector{removal(31, "", 25.5, 0.32),
                                                       death(31, "", "background", "windthrow", 20.2, 0.21)});
  EXPECT_NEAR(thinned[0].living.volume_m3_per_ha, 56.0, 1e-9);
  EXPECT_NEAR(thinned[0].total_production_m3_per_ha, 56.0 + 32.0 + 21.0, 1e-9);  // 109
  EXPECT_NEAR(thinned[0].cai_m3_per_ha, 9.0, 1e-9);                              // 109 − 100
  EXPECT_NEAR(thinned[0].mai_m3_per_ha, 109.0 / 31, 1e-9);
  // Age 32: 0.62 m³ standing, nothing leaves; what left last year still counts.
  const auto later = ledger.rows_of_year({32, 2, {{32, 22, 0.62}}}, {});
  EXPECT_NEAR(later[0].total_production_m3_per_ha, 62.0 + 53.0, 1e-9);  // 115
  EXPECT_NEAR(later[0].cai_m3_per_ha, 6.0, 1e-9);
  EXPECT_NEAR(later[0].mai_m3_per_ha, 115.0 / 32, 1e-9);  // 3.59375
  EXPECT_DOUBLE_EQ(later[0].removed.volume_m3, 0.0) << "flows are this year's only";
}

// 0.02 ha: top height is the mean of the 2 thickest trees — of the stand, or of one species.
TEST(StandTableRows, EachSpeciesHasItsOwnRowAndItsOwnTopHeight) {
  StandTableLedger ledger(0.02);
  const StandInventory inventory{40, 0,
                                 {{30, 20, 0.6, "todomatsu"},
                                  {25, 24, 0.5, "karamatsu"},
                                  {20, 16, 0.3, "todomatsu"},
                                  {15, 14, 0.15, "karamatsu"},
                                  {10, 9, 0.05, "todomatsu"}}};
  const auto rows = ledger.rows_of_year(inventory, std::vector{removal(40, "karamatsu", 18, 0.2)});
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].species, "all");
  EXPECT_EQ(rows[1].species, "karamatsu") << "species by name after the whole stand";
  EXPECT_EQ(rows[2].species, "todomatsu");
  EXPECT_DOUBLE_EQ(rows[0].living.top_height_m, 22.0);  // dbh 30 (20 m) and 25 (24 m)
  EXPECT_DOUBLE_EQ(rows[1].living.top_height_m, 19.0);  // larch: 25 (24 m) and 15 (14 m)
  EXPECT_DOUBLE_EQ(rows[2].living.top_height_m, 18.0);  // fir: 30 (20 m) and 20 (16 m)
  EXPECT_DOUBLE_EQ(rows[0].living.stems_per_ha, 250.0);
  EXPECT_DOUBLE_EQ(rows[1].living.stems_per_ha, 100.0);
  EXPECT_DOUBLE_EQ(rows[2].living.stems_per_ha, 150.0);
  EXPECT_NEAR(rows[1].living.volume_m3_per_ha, 32.5, 1e-9);  // 0.65 / 0.02
  EXPECT_NEAR(rows[2].living.volume_m3_per_ha, 47.5, 1e-9);  // 0.95 / 0.02
  EXPECT_DOUBLE_EQ(rows[0].removed.stems, 50.0);
  EXPECT_DOUBLE_EQ(rows[1].removed.stems, 50.0) << "the larch that was thinned";
  EXPECT_DOUBLE_EQ(rows[2].removed.stems, 0.0);
  EXPECT_NEAR(rows[1].total_production_m3_per_ha, 32.5 + 10.0, 1e-9);
  EXPECT_NEAR(rows[0].total_production_m3_per_ha,
              rows[1].total_production_m3_per_ha + rows[2].total_production_m3_per_ha, 1e-9);
}

TEST(StandTableRows, ASpeciesKeepsItsRowWhenItsLastTreeHasGone) {
  StandTableLedger ledger(0.01);
  ledger.rows_of_year({40, 0, {{30, 20, 0.6, "todomatsu"}, {25, 24, 0.5, "karamatsu"}}}, {});
  const auto rows = ledger.rows_of_year({41, 1, {{31, 21, 0.65, "todomatsu"}}},
                                        std::vector{removal(41, "karamatsu", 26, 0.55)});
  ASSERT_EQ(rows.size(), 3u);
  const StandTableRow& larch = rows[1];
  EXPECT_EQ(larch.species, "karamatsu");
  EXPECT_DOUBLE_EQ(larch.living.stems_per_ha, 0.0);
  EXPECT_TRUE(std::isnan(larch.living.qmd_cm));
  EXPECT_NEAR(larch.total_production_m3_per_ha, 55.0, 1e-9) << "its cut volume stays in its production";
  EXPECT_NEAR(larch.cai_m3_per_ha, 5.0, 1e-9);  // 55 − 50
}

TEST(StandTableRows, NoSpeciesMayBeCalledLikeTheWholeStand) {
  StandTableLedger ledger(0.01);
  EXPECT_THROW(ledger.rows_of_year({30, 0, {{20, 15, 0.2, "all"}}}, {}), std::invalid_argument);
  EXPECT_THROW(StandTableLedger(0.0), std::invalid_argument);
}

}  // namespace
}  // namespace heliostand
