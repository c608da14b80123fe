#pragma once
// The runs of a batch: every stand × scenario × seed, in manifest order (stands outermost, seeds innermost),
// each with the scenario it grows composed from the manifest's layers. The order is the same on every MPI rank
// and every machine, so a run's index names the same run everywhere.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "batch/batch_manifest.hpp"

namespace heliostand {

struct BatchRun {
  std::string stand;
  std::string scenario;
  std::uint64_t seed = 0;
  std::string composed_scenario;  // the scenario TOML this run grows (paths absolute), shared by its seeds

  // Paths relative to the batch's output root ('/'-separated): where the run writes, its log, its scenario.
  std::filesystem::path folder() const;         // runs/STAND/SCENARIO/seed-N
  std::filesystem::path log_file() const;       // logs/STAND/SCENARIO/seed-N.log
  std::filesystem::path scenario_file() const;  // inputs/STAND/SCENARIO.toml
  std::string id() const;                       // STAND/SCENARIO/seed-N
};

// The scenario of one stand under one scenario: the stand's scenario file, then its override, then the
// scenario's file and override, then the manifest's override. Tables merge key by key, anything else (a
// number, an array such as [[thinning]]) replaces what was there. Relative paths (stand.survey, soil.file)
// are made absolute from the folder of the layer that set them. Throws InputError for an unreadable stand file.
toml::table compose_scenario(const BatchManifest& manifest, const BatchStand& stand, const BatchScenario& scenario);

// Merges `layer` into `base` by the rule above.
void merge_scenario_layer(toml::table& base, const toml::table& layer);

std::vector<BatchRun> list_batch_runs(const BatchManifest& manifest);

}  // namespace heliostand
