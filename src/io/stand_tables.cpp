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

// The per-cause death columns, in all_death_causes order: dead_<cause>_stems_per_ha, ..._basal_area_..., ..._volume_...
std::vector<OutputColumn> dead_by_cause_columns() {
  std::vector<OutputColumn> columns;
  for (DeathCause cause : all_death_causes) {
    const std::string code(cause_code(cause));
    columns.push_back({"dead_" + code + "_stems_per_ha", "1/ha", "stems that died of " + code + " this year"});
    columns.push_back({"dead_" + code + "_basal_area_m2_per_ha", "m²/ha", "their basal area at death"});
    columns.push_back({"dead_" + code + "_volume_m3_per_ha", "m³/ha", "their stem volume at death"});
  }
  return columns;
}

// In the order of a yield table: the living stand, what left it this year, the production.
std::vector<OutputColumn> declare_stand_table_columns() {
  std::vector<OutputColumn> columns{
      {"stand_age", "years", "stand age"},
      {"year_index", "–", "simulated year of the run, 0 = the survey year"},
      {"species", "–", "a species, or all for the whole stand"},
      {"stems_per_ha", "1/ha", "living stems per hectare"},
      {"basal_area_m2_per_ha", "m²/ha", "basal area of the living stems"},
      {"qmd_cm", "cm", "Dg, quadratic mean diameter of the living stems"},
      {"mean_height_m", "m", "arithmetic mean height of the living stems"},
      {"hg_m", "m", "Hg, Lorey's height: mean height of the living stems weighted by basal area"},
      {"top_height_m", "m", "mean height of the 100 largest-DBH living trees per hectare"},
      {"volume_m3_per_ha", "m³/ha", "stem volume of the living trees"},
      {"removed_stems_per_ha", "1/ha", "stems removed by thinning this year"},
      {"removed_basal_area_m2_per_ha", "m²/ha", "their basal area at removal"},
      {"removed_volume_m3_per_ha", "m³/ha", "their stem volume at removal"},
      {"dead_stems_per_ha", "1/ha", "stems that died this year, all causes"},
      {"dead_basal_area_m2_per_ha", "m²/ha", "their basal area at death"},
      {"dead_volume_m3_per_ha", "m³/ha", "their stem volume at death"},
  };
  for (OutputColumn& column : dead_by_cause_columns()) columns.push_back(std::move(column));
  columns.push_back({"total_production_m3_per_ha", "m³/ha",
                     "living volume + volume removed or dead since the survey (this year's included)"});
  columns.push_back({"cai_m3_per_ha", "m³/(ha·year)", "current annual increment: total production's change this year"});
  columns.push_back({"mai_m3_per_ha", "m³/(ha·year)", "mean annual increment: total production / stand age"});
  return columns;
}

void write_trees_leaving(CsvWriter& csv, const PerHectare& leaving) {
  csv.number(leaving.stems, kPerHectare)
      .number(leaving.basal_area_m2, kPerHectare)
      .number(leaving.volume_m3, kPerHectare);
}

}  // namespace

const std::vector<OutputColumn>& stand_table_columns() {
  static const std::vector<OutputColumn> columns = declare_stand_table_columns();
  return columns;
}

const std::vector<OutputColumn>& trees_columns() {
  static const std::vector<OutputColumn> columns{
      {"stand_age", "years", "stand age of the output year"},
      {"tree_id", "–", "tree identifier"},
      {"label", "–", "survey id"},
      {"x_m", "m", "stem base position, east"},
      {"y_m", "m", "stem base position, north"},
      {"status", "–", "alive, dead or removed"},
      {"habitat_tree", "–", "1 when the tree carries a hollow, else 0"},
      {"hollows", "–", "number of hollows it carries"},
      {"age", "years", "tree age"},
      {"height_m", "m", "tree height"},
      {"dbh_cm", "cm", "diameter at breast height"},
      {"crown_base_m", "m", "crown base height"},
      {"crown_radius_m", "m", "projected crown radius"},
      {"volume_m3", "m³", "stem volume"},
      {"leaf_balls", "–", "number of leaf balls"},
      {"mean_light", "–", "mean light of its leaf balls, 0..1 of the open sky"},
      {"light_budget", "m", "light absorbed this year: Σ foliage amount × light over its leaf balls"},
      {"relative_light", "–", "light budget / the same sum with the tree alone, 0..1"},
      {"dbh_increment_cm", "cm", "this year's DBH increment"},
      {"root_length_m", "m", "total length of its living root segments"},
      {"root_max_depth_m", "m", "depth of its deepest root segment end"},
      {"root_uptake", "m", "available uptake Σ W_j × moisture × nutrient at its root tips"},
      {"hegyi_index", "1/m", "Hegyi's competition index among the living trees within [competition] hegyi_radius_m"},
  };
  return columns;
}

const std::vector<OutputColumn>& events_columns() {
  static const std::vector<OutputColumn> columns{
      {"stand_age", "years", "stand age in the year of the event"},
      {"tree_id", "–", "tree identifier"},
      {"label", "–", "survey id"},
      {"species", "–", "the tree's species"},
      {"event", "–", "removed (thinning) or died (mortality)"},
      {"cause", "–", "code: thinning, or the cause of death (light, suppression, background)"},
      {"reason", "–", "label: the scenario's reason for a thinning, the cause code again for a death"},
      {"dbh_cm", "cm", "DBH at the event"},
      {"height_m", "m", "height at the event"},
      {"volume_m3", "m³", "stem volume at the event"},
  };
  return columns;
}

void write_stand_table_header(CsvWriter& csv) { csv.header(column_names(stand_table_columns())); }

void write_stand_table_row(CsvWriter& csv, const StandTableRow& row) {
  csv.integer(row.stand_age)
      .integer(row.year_index)
      .text(row.species)
      .number(row.living.stems_per_ha, kPerHectare)
      .number(row.living.basal_area_m2_per_ha, kPerHectare)
      .number(row.living.qmd_cm, kCentimetres)
      .number(row.living.mean_height_m, kMetres)
      .number(row.living.hg_m, kMetres)
      .number(row.living.top_height_m, kMetres)
      .number(row.living.volume_m3_per_ha, kPerHectare);
  write_trees_leaving(csv, row.removed);
  write_trees_leaving(csv, row.dead);
  for (const PerHectare& dead : row.dead_by_cause) write_trees_leaving(csv, dead);
  csv.number(row.total_production_m3_per_ha, kPerHectare)
      .number(row.cai_m3_per_ha, kPerHectare)
      .number(row.mai_m3_per_ha, kPerHectare)
      .end_row();
}

void write_trees_header(CsvWriter& csv) { csv.header(column_names(trees_columns())); }

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

void write_events_header(CsvWriter& csv) { csv.header(column_names(events_columns())); }

void write_event_row(CsvWriter& csv, const TreeEvent& event) {
  csv.integer(event.stand_age)
      .integer(event.tree_id)
      .text(event.label)
      .text(event.species)
      .text(to_string(event.kind))
      .text(event.cause)
      .text(event.reason)
      .number(event.dbh_cm, kCentimetres)
      .number(event.height_m, kMetres)
      .number(event.volume_m3, kVolume)
      .end_row();
}

}  // namespace heliostand
