#pragma once
// run.json: what was run, how, how long each stage took, and which files it produced. Written last
// into the output folder, so a folder without run.json is an unfinished (or crashed) run.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/page_settings.hpp"
#include "core/processor.hpp"

namespace heliostand {

struct RunManifest {
  static constexpr int format_version = 1;   // bump when a key changes meaning or disappears

  std::string heliostand_version = HELIOSTAND_VERSION;
  std::string command_line;                  // as typed, for reproducing the run
  std::string scenario_path;
  std::uint64_t seed = 0;
  std::string device;                        // "reference", "opencl:0 (pocl cpu)", ...
  std::string started_utc;                   // ISO 8601, e.g. "2026-11-21T08:00:00Z"
  std::string finished_utc;
  // The machine of the session that finished the run, so its seconds are read as that machine's. A resumed run's
  // earlier sessions may have run on another one: their seconds are in wall_seconds, their machines not recorded.
  unsigned finished_on_hardware_threads = 0;
  Processor finished_on_processor;
  PageSettings finished_on_pages;  // the allocator's settings, which move a long run's seconds by up to a tenth
  int first_stand_age = 0;
  int last_stand_age = 0;
  double wall_seconds = 0;
  std::vector<std::pair<std::string, double>> stage_seconds;  // ("light", 12.3), in stage order
  std::vector<std::string> output_files;     // relative to the output folder, '/'-separated
};

// The manifest as pretty-printed JSON (keys in a fixed order), ending with a newline.
std::string to_json(const RunManifest& manifest);

// Current UTC time as ISO 8601 with a trailing Z, to the second.
std::string utc_now_iso8601();

}  // namespace heliostand
