#pragma once
// The batch's summary tables, gathered from every run's stand_table.csv (docs/formats.md "Batch outputs"):
//   summary.csv       every run's final year (one row per species row of its last year), with its status
//   stand_tables.csv  every run's stand table, every year, each row led by the run's keys
// A failed run has one row in summary.csv, its error and empty stand columns, and no rows in stand_tables.csv.
#include <filesystem>
#include <string>
#include <vector>

#include "batch/batch_run.hpp"

namespace heliostand {

struct RunResult {
  const BatchRun* run = nullptr;
  int exit_status = 0;
  std::string error;
};

// Writes both tables into `root` (atomically: temporary name, then rename). Throws std::runtime_error when a
// finished run's stand_table.csv cannot be read.
void write_batch_summary(const std::filesystem::path& root, const std::vector<RunResult>& results);

}  // namespace heliostand
