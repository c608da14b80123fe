#pragma once
// The rows of stand_table.csv (docs/formats.md): every simulated year, the whole stand (species "all") and then
// each species by name, as a yield table has them — the living stand, what was removed and what died this year,
// and the stand's production: total production (living volume + all volume removed or dead since the survey),
// its current annual increment (CAI) and its mean annual increment (MAI).
#include <array>
#include <iterator>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "architecture/species.hpp"  // whole_stand_species
#include "core/checkpoint_access.hpp"
#include "records/death_cause.hpp"
#include "records/stand_metrics.hpp"
#include "records/stand_snapshot.hpp"
#include "records/tree_event.hpp"

namespace heliostand {

// The living trees at the end of one simulated year: what that year's rows measure.
struct StandInventory {
  int stand_age = 0;
  int year_index = 0;  // 0 = the survey year
  std::vector<TreeMeasurement> living;
};

// The living (status alive) trees of an output year's snapshot, measured as the snapshot measured them.
StandInventory inventory_of(const StandSnapshot& snapshot);

// Trees leaving the stand, per hectare.
struct PerHectare {
  double stems = 0;
  double basal_area_m2 = 0;  // at the event
  double volume_m3 = 0;      // stem volume at the event
};

// One row of stand_table.csv.
struct StandTableRow {
  int stand_age = 0;
  int year_index = 0;
  std::string species{whole_stand_species};  // or one species' name
  StandMetrics living;  // trees alive at the end of the year
  PerHectare removed;   // thinned this year
  PerHectare dead;      // died this year, all causes
  std::array<PerHectare, std::size(all_death_causes)> dead_by_cause{};  // in all_death_causes order
  double total_production_m3_per_ha = 0;  // living volume + volume removed or dead since the survey, this year's too
  // Total production's change over this year; NaN in the survey year, which has no year before it.
  double cai_m3_per_ha = std::numeric_limits<double>::quiet_NaN();
  double mai_m3_per_ha = std::numeric_limits<double>::quiet_NaN();  // total production / stand age
};

// The living metrics and this year's removals and deaths of one row; `living` and `events` are the row's trees
// (one species' or all). Production is the ledger's: it needs the years before.
StandTableRow measure_row(const StandInventory& inventory, std::string_view species,
                          std::span<const TreeMeasurement> living, std::span<const TreeEvent> events,
                          double plot_area_ha);

// Keeps what a year's rows need from the years before it, for the whole stand and each species: the volume that
// left the stand since the survey (total production counts it) and last year's total production (for the CAI).
// A species keeps its row, with zero stems, once its last tree has gone, so that its flows always add up to the
// stand's and its total production stays on record.
class StandTableLedger {
 public:
  explicit StandTableLedger(double plot_area_ha);

  // The rows of one simulated year, the whole stand first and then each species by name. Years come in order,
  // one call each; `events_of_year` are the year's removals and deaths.
  std::vector<StandTableRow> rows_of_year(const StandInventory& inventory, std::span<const TreeEvent> events_of_year);

 private:
  friend struct checkpoint::Access;
  struct Production {
    double gone_volume_m3_per_ha = 0;  // removed or dead since the survey, up to the latest row's year
    double last_total_m3_per_ha = std::numeric_limits<double>::quiet_NaN();
  };
  StandTableRow row_of(const StandInventory& inventory, std::string_view species,
                       std::span<const TreeEvent> events_of_year, Production& production);
  static void book_production(StandTableRow& row, Production& production);

  double plot_area_ha_;
  Production stand_;
  std::map<std::string, Production, std::less<>> species_;  // sorted by name: the row order
};

}  // namespace heliostand
