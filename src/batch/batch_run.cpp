#include "batch/batch_run.hpp"

#include <fmt/format.h>

#include <sstream>
#include <utility>

#include "core/input_error.hpp"
#include "scenario/toml_file.hpp"

namespace heliostand {
namespace fs = std::filesystem;

fs::path BatchRun::folder() const { return fs::path("runs") / stand / scenario / fmt::format("seed-{}", seed); }
fs::path BatchRun::log_file() const { return fs::path("logs") / stand / scenario / fmt::format("seed-{}.log", seed); }
fs::path BatchRun::scenario_file() const { return fs::path("inputs") / stand / (scenario + ".toml"); }
std::string BatchRun::id() const { return fmt::format("{}/{}/seed-{}", stand, scenario, seed); }

void merge_scenario_layer(toml::table& base, const toml::table& layer) {
  for (auto&& [key, value] : layer) {
    toml::node* existing = base.get(key.str());
    if (existing && existing->is_table() && value.is_table()) {
      merge_scenario_layer(*existing->as_table(), *value.as_table());
    } else {
      base.insert_or_assign(key, value);
    }
  }
}

namespace {

// The scenario keys that name files, relative to the file that sets them (docs/formats.md).
constexpr std::pair<std::string_view, std::string_view> path_keys[] = {{"stand", "survey"}, {"soil", "file"}};

// The composed scenario lives elsewhere than its layers: a relative path becomes absolute from its layer's folder.
toml::table with_absolute_paths(toml::table layer, const fs::path& base_folder) {
  for (const auto& [table_key, key] : path_keys) {
    toml::table* table = layer.get_as<toml::table>(table_key);
    if (!table) continue;
    toml::value<std::string>* text = table->get_as<std::string>(key);
    if (!text) continue;  // absent, or a wrong type the run's own check will report
    const fs::path path(text->get());
    if (path.is_relative()) *text = fs::absolute(base_folder / path).lexically_normal().string();
  }
  return layer;
}

}  // namespace

toml::table compose_scenario(const BatchManifest& manifest, const BatchStand& stand, const BatchScenario& scenario) {
  toml::table stand_scenario = read_toml_file(stand.scenario_file, stand.scenario_file.string(), "scenario");
  toml::table composed = with_absolute_paths(std::move(stand_scenario), stand.scenario_file.parent_path());
  const auto apply = [&](const ScenarioLayer& layer) {
    merge_scenario_layer(composed, with_absolute_paths(layer.table, layer.base_folder));
  };
  if (stand.override_layer) apply(*stand.override_layer);
  for (const ScenarioLayer& layer : scenario.layers) apply(layer);
  if (manifest.override_layer) apply(*manifest.override_layer);
  return composed;
}

std::vector<BatchRun> list_batch_runs(const BatchManifest& manifest) {
  std::vector<BatchRun> runs;
  std::vector<InputProblem> problems;
  for (const BatchStand& stand : manifest.stands) {
    for (const BatchScenario& scenario : manifest.scenarios) {
      std::string text;
      try {
        std::ostringstream out;
        out << "# Composed by heliostand batch from " << manifest.file.string() << ": stand " << stand.name
            << ", scenario " << scenario.name << "\n"
            << compose_scenario(manifest, stand, scenario) << "\n";
        text = out.str();
      } catch (const InputError& error) {
        problems.insert(problems.end(), error.problems().begin(), error.problems().end());
        continue;
      }
      for (const std::uint64_t seed : manifest.seeds) runs.push_back({stand.name, scenario.name, seed, text});
    }
  }
  if (!problems.empty()) throw InputError(problems, "key");
  return runs;
}

}  // namespace heliostand
