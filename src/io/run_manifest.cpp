#include "io/run_manifest.hpp"

#include <chrono>
#include <ctime>

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/json_text.hpp"

namespace heliostand {

std::string to_json(const RunManifest& manifest) {
  nlohmann::ordered_json json;
  json["format_version"] = RunManifest::format_version;
  json["heliostand_version"] = manifest.heliostand_version;
  json["command_line"] = manifest.command_line;
  json["scenario"] = manifest.scenario_path;
  json["seed"] = manifest.seed;
  json["device"] = manifest.device;
  json["started_utc"] = manifest.started_utc;
  json["finished_utc"] = manifest.finished_utc;
  json["finished_on"] = {{"hardware_threads", manifest.finished_on_hardware_threads},
                         {"processor", processor_json(manifest.finished_on_processor)},
                         {"pages", page_settings_json(manifest.finished_on_pages)}};
  json["first_stand_age"] = manifest.first_stand_age;
  json["last_stand_age"] = manifest.last_stand_age;
  json["wall_seconds"] = manifest.wall_seconds;
  nlohmann::ordered_json stages = nlohmann::ordered_json::object();
  for (const auto& [stage, seconds] : manifest.stage_seconds) stages[stage] = seconds;
  json["stage_seconds"] = stages;
  json["output_files"] = manifest.output_files;
  return json_text(json);  // invalid UTF-8 (a path in a legacy encoding) replaced, not the run aborted at its end
}

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(now));
}

}  // namespace heliostand
