#include "records/stand_table_ledger.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>


namespace heliostand {
namespace {

void add(PerHectare& flow, const TreeEvent& event, double plot_area_ha) {
  flow.stems += 1.0 / plot_area_ha;
  flow.basal_area_m2 += basal_area_m2(event.dbh_cm) / plot_area_ha;
  flow.volume_m3 += event.volume_m3 / plot_area_ha;
}

// Where a death's cause code sits in all_death_causes. A code that is not there is a producer's bug: its deaths
// would count in dead_* but in no dead_<cause>_* column.
std::size_t death_cause_slot(const TreeEvent& death) {
  for (std::size_t slot = 0; slot < std::size(all_death_causes); ++slot)
    if (death.cause == cause_code(all_death_causes[slot])) return slot;
  throw std::logic_error(fmt::format("tree {} died of '{}', which is no cause of death", death.label, death.cause));
}

template <typename Item>
std::vector<Item> of_species(std::span<const Item> items, std::string_view species) {
  std::vector<Item> chosen;
  for (const Item& item : items)
    if (item.species == species) chosen.push_back(item);
  return chosen;
}

void require_ordinary_species(const std::string& species) {
  if (species == whole_stand_species)
    throw std::invalid_argument(fmt::format("stand table: a species may not be called '{}', the whole stand's name",
                                            whole_stand_species));
}

}  // namespace

StandInventory inventory_of(const StandSnapshot& snapshot) {
  StandInventory inventory{snapshot.stand_age, snapshot.year_index, {}};
  for (const TreeSnapshot& tree : snapshot.trees)
    if (tree.status == TreeStatus::alive)
      inventory.living.push_back({tree.dbh_cm, tree.height_m, tree.volume_m3, tree.species});
  return inventory;
}

StandTableRow measure_row(const StandInventory& inventory, std::string_view species,
                          std::span<const TreeMeasurement> living, std::span<const TreeEvent> events,
                          double plot_area_ha) {
  StandTableRow row;
  row.stand_age = inventory.stand_age;
  row.year_index = inventory.year_index;
  row.species = species;
  row.living = measure_stand(living, plot_area_ha);
  for (const TreeEvent& event : events) {
    if (event.kind == TreeEventKind::removed) {
      add(row.removed, event, plot_area_ha);
      continue;
    }
    add(row.dead, event, plot_area_ha);
    add(row.dead_by_cause[death_cause_slot(event)], event, plot_area_ha);
  }
  return row;
}

StandTableLedger::StandTableLedger(double plot_area_ha) : plot_area_ha_(plot_area_ha) {
  if (!(plot_area_ha > 0)) throw std::invalid_argument("stand table: plot area must be > 0 ha");
}

std::vector<StandTableRow> StandTableLedger::rows_of_year(const StandInventory& inventory,
                                                          std::span<const TreeEvent> events_of_year) {
  for (const TreeMeasurement& tree : inventory.living) require_ordinary_species(tree.species);
  for (const TreeEvent& event : events_of_year) require_ordinary_species(event.species);
  for (const TreeMeasurement& tree : inventory.living) species_.try_emplace(tree.species);
  for (const TreeEvent& event : events_of_year) species_.try_emplace(event.species);

  std::vector<StandTableRow> rows{row_of(inventory, whole_stand_species, events_of_year, stand_)};
  for (auto& [species, production] : species_) rows.push_back(row_of(inventory, species, events_of_year, production));
  return rows;
}

StandTableRow StandTableLedger::row_of(const StandInventory& inventory, std::string_view species,
                                       std::span<const TreeEvent> events_of_year, Production& production) {
  StandTableRow row =
      species == whole_stand_species
          ? measure_row(inventory, species, inventory.living, events_of_year, plot_area_ha_)
          : measure_row(inventory, species, of_species<TreeMeasurement>(inventory.living, species),
                        of_species<TreeEvent>(events_of_year, species), plot_area_ha_);
  book_production(row, production);
  return row;
}

// Total production counts every cubic metre the stand grew since the survey, whether it still stands, was cut or
// died: the living volume plus all that left. Its change over the year is the current annual increment (CAI);
// spread over the stand's age, the mean annual increment (MAI).
void StandTableLedger::book_production(StandTableRow& row, Production& production) {
  production.gone_volume_m3_per_ha += row.removed.volume_m3 + row.dead.volume_m3;
  row.total_production_m3_per_ha = row.living.volume_m3_per_ha + production.gone_volume_m3_per_ha;
  row.cai_m3_per_ha = std::isnan(production.last_total_m3_per_ha)
                          ? undefined_mean
                          : row.total_production_m3_per_ha - production.last_total_m3_per_ha;
  production.last_total_m3_per_ha = row.total_production_m3_per_ha;
  row.mai_m3_per_ha = row.stand_age > 0 ? row.total_production_m3_per_ha / row.stand_age : undefined_mean;
}

}  // namespace heliostand
