#include "io/stand_tables.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace heliostand {
namespace {

// Decimals per kind of quantity: enough to resolve one year's change on a small plot, no more.
constexpr int kMetres = 3;        // mm
constexpr int kCentimetres = 2;   // 0.1 mm of diameter
constexpr int kVolume = 4;        // 0.1 dm³
constexpr int kPerHectare = 3;
constexpr int kLight = 4;

}  // namespace

void write_stand_table_header(CsvWriter& csv) {
  std::vector<std::string> columns{"stand_age", "year_index", "stems_per_ha", "basal_area_m2_per_ha", "qmd_cm",
                                   "mean_height_m", "top_height_m", "volume_m3_per_ha", "removed_stems_per_ha",
                                   "removed_basal_area_m2_per_ha", "removed_volume_m3_per_ha", "dead_stems_per_ha",
                                   "dead_basal_area_m2_per_ha", "dead_volume_m3_per_ha"};
  for (DeathCause cause : all_death_causes) {
    const std::string name(cause_code(cause));
    for (const char* quantity : {"_stems_per_ha", "_basal_area_m2_per_ha", "_volume_m3_per_ha"})
      columns.push_back("dead_" + name + quantity);
  }
  csv.header(columns);
}

void write_stand_table_row(CsvWriter& csv, const StandTableRow& row) {
  csv.integer(row.stand_age)
      .integer(row.year_index)
      .number(row.living.stems_per_ha, kPerHectare)
      .number(row.living.basal_area_m2_per_ha, kPerHectare)
      .number(row.living.qmd_cm, kCentimetres)
      .number(row.living.mean_height_m, kMetres)
      .number(row.living.top_height_m, kMetres)
      .number(row.living.volume_m3_per_ha, kPerHectare)
      .number(row.removed_stems_per_ha, kPerHectare)
      .number(row.removed_basal_area_m2_per_ha, kPerHectare)
      .number(row.removed_volume_m3_per_ha, kPerHectare)
      .number(row.dead_stems_per_ha, kPerHectare)
      .number(row.dead_basal_area_m2_per_ha, kPerHectare)
      .number(row.dead_volume_m3_per_ha, kPerHectare);
  for (const auto& losses : row.dead_by_cause)
    csv.number(losses.stems_per_ha, kPerHectare)
        .number(losses.basal_area_m2_per_ha, kPerHectare)
        .number(losses.volume_m3_per_ha, kPerHectare);
  csv.end_row();
}

void write_trees_header(CsvWriter& csv) {
  csv.header({"stand_age", "tree_id", "label", "x_m", "y_m", "status", "habitat_tree", "hollows", "age", "height_m", "dbh_cm", "crown_base_m",
              "crown_radius_m", "volume_m3", "leaf_balls", "mean_light", "light_budget", "relative_light",
              "dbh_increment_cm", "root_length_m", "root_max_depth_m", "root_uptake", "hegyi_index"});
}

void write_tree_rows(CsvWriter& csv, const StandSnapshot& snapshot) {
  constexpr int kCompetitionIndex = 4;  // 1/m: a 20 cm neighbour 2 m from a 20 cm tree adds 0.5
  for (const TreeSnapshot& tree : snapshot.trees) {
    csv.integer(snapshot.stand_age)
        .integer(tree.id)
        .text(tree.label)
        .number(tree.position.x, kMetres)
        .number(tree.position.y, kMetres)
        .text(to_string(tree.status))
        .integer(tree.hollow_count > 0 ? 1 : 0)
        .integer(tree.hollow_count)
        .integer(std::lround(tree.age_years))  // trees age in whole years
        .number(tree.height_m, kMetres)
        .number(tree.dbh_cm, kCentimetres)
        .number(tree.crown_base_m, kMetres)
        .number(tree.crown_radius_m, kMetres)
        .number(tree.volume_m3, kVolume)
        .integer(static_cast<long long>(tree.leaf_balls.size()))
        .number(tree.mean_light, kLight)
        .number(tree.light_budget, kLight)
        .number(tree.relative_light, kLight)
        .number(tree.dbh_increment_cm, kCentimetres + 1)
        .number(tree.root_length_m, kMetres)
        .number(tree.root_max_depth_m, kMetres)
        .number(tree.root_uptake, kLight)
        .number(tree.hegyi_index, kCompetitionIndex)
        .end_row();
  }
}

void write_events_header(CsvWriter& csv) {
  csv.header({"stand_age", "tree_id", "label", "event", "reason", "dbh_cm", "height_m", "volume_m3"});
}

void write_event_row(CsvWriter& csv, const TreeEvent& event) {
  csv.integer(event.stand_age)
      .integer(event.tree_id)
      .text(event.label)
      .text(to_string(event.kind))
      .text(event.reason)
      .number(event.dbh_cm, kCentimetres)
      .number(event.height_m, kMetres)
      .number(event.volume_m3, kVolume)
      .end_row();
}

}  // namespace heliostand
