#pragma once
// Where the simulated year hands what it recorded: the stand manager (stand/stand_year.hpp) drives this interface
// and knows nothing of files; io/stand_output.hpp writes the records as the run's tables and VTK series. A stand
// run without outputs (tests, calibration) passes no recorder at all.
#include <span>

#include "records/stand_snapshot.hpp"
#include "records/stand_table_ledger.hpp"  // StandInventory
#include "records/tree_event.hpp"

namespace heliostand {

class YearRecorder {
 public:
  virtual ~YearRecorder() = default;
  // The year's removals and deaths, in the order they happened (events.csv, and the flows of the next stand rows).
  virtual void record_events(std::span<const TreeEvent> events) = 0;
  // The living stand's inventory of the year (stand_table.csv), every year.
  virtual void write_stand_rows(const StandInventory& inventory) = 0;
  // An output year's snapshot (trees.csv rows, the VTK year).
  virtual void write_year(const StandSnapshot& snapshot) = 0;
  // Whether write_year draws the trees (the VTK series): only then does a snapshot mesh each trunk.
  virtual bool draws_trunks() const = 0;
};

}  // namespace heliostand
