#pragma once
// The batch's output root: one folder holding every run's folder, log and composed scenario, and the summary.
//   ROOT/.heliostand-batch                 marker: this folder holds a heliostand batch
//   ROOT/inputs/STAND/SCENARIO.toml        the scenario each run grows (composed from the manifest)
//   ROOT/runs/STAND/SCENARIO/seed-N/       each run's output folder (as `heliostand grow --out`)
//   ROOT/logs/STAND/SCENARIO/seed-N.log    each run's warnings and errors
//   ROOT/summary.csv, ROOT/stand_tables.csv
// A root that holds a batch is taken again: finished runs (run.json present) are kept, unfinished ones are
// grown again, so a batch killed half-way (or whose node died) is completed by starting it again.
#include <filesystem>
#include <string_view>
#include <vector>

#include "batch/batch_run.hpp"

namespace heliostand {

constexpr std::string_view batch_marker_name = ".heliostand-batch";

// Creates or takes `root` and writes every run's composed scenario. Refuses (OutputFolderError) a non-empty
// folder that is not a batch, a batch whose inputs differ from `runs`' (another manifest: --force starts over),
// and any symbolic link on the way to a file it writes. With `force`, an earlier batch's contents are deleted.
void prepare_batch_root(const std::filesystem::path& root, const std::vector<BatchRun>& runs, bool force);

// Throws OutputFolderError unless `relative` is a plain relative path (no "..", not absolute) and no part of
// root/relative that exists is a symbolic link: a written path cannot leave the root.
void check_inside_root(const std::filesystem::path& root, const std::filesystem::path& relative);

// True when the run's folder holds run.json, which `grow` writes last (a finished run).
bool run_finished(const std::filesystem::path& root, const BatchRun& run);

}  // namespace heliostand
