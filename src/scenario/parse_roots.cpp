// [roots]: the switch, the root-contact backend, and per-species root parameters
//   [roots.SPECIES]        per-tree fields of roots::RootParameters
//   [roots.SPECIES.TYPE]   per-type fields (TYPE = main, lateral, sinker, fine)
// Unset fields keep the tap-rooted conifer defaults (docs/roots.md). docs/formats.md lists every key.
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "roots/root_type.hpp"
#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand::scenario_detail {

namespace {

void read_angle_range(TomlTableReader& reader, std::string_view stem, roots::AngleRangeDeg& range) {
  const std::string min_key = fmt::format("{}_min_deg", stem), max_key = fmt::format("{}_max_deg", stem);
  if (auto v = reader.number(min_key, between(0.0, 180.0))) range.min = *v;
  if (auto v = reader.number(max_key, between(0.0, 180.0))) range.max = *v;
  if (range.min > range.max) reader.problem(max_key, fmt::format("must not be below {} ({:g}), got {:g}", min_key, range.min, range.max));
}

void read_type(TomlTableReader& reader, roots::RootTypeParameters& p) {
  for (roots::RootType child : roots::all_root_types) {
    const auto& most = child == roots::RootType::main ? limit::main_root_forks : limit::roots_per_year;
    if (auto v = reader.number(fmt::format("branching_to_{}", roots::name_of(child)), non_negative_up_to(most)))
      p.branching_frequency[roots::index_of(child)] = *v;
  }
  read_angle_range(reader, "branching_angle", p.branching_angle_deg);
  read_angle_range(reader, "continuation_angle", p.continuation_angle_deg);
  if (auto v = reader.number("elongation_m_per_year", positive_up_to(limit::annual_growth_m))) p.elongation_m_per_year = *v;
  if (auto v = reader.number("radius_m", positive_up_to(limit::stem_radius_m))) p.radius_m = *v;
  if (auto v = reader.number("lifespan_years", positive_up_to(limit::tree_lifetime))) p.lifespan_years = *v;
  if (auto v = reader.number("growth_years", positive_up_to(limit::tree_lifetime))) p.growth_years = *v;
  if (auto v = reader.number("fine_root_sprouting_per_year", non_negative_up_to(limit::roots_per_year))) p.fine_root_sprouting_per_year = *v;
  if (auto v = reader.number("perception_radius_m", positive_up_to(limit::root_perception_m))) p.perception_radius_m = *v;
  if (auto v = reader.number("absorptive_weight", between(0.0, 1.0))) p.absorptive_weight = *v;  // of a fine root
  roots::TropismWeights& w = p.tropisms;
  const roots::TropismWeights before = w;
  const bool any_weight = reader.table().contains("alpha") || reader.table().contains("beta") ||
                          reader.table().contains("gamma") || reader.table().contains("delta") ||
                          reader.table().contains("epsilon");
  if (auto v = reader.number("alpha", between(0.0, 1.0))) w.alpha = *v;
  if (auto v = reader.number("beta", between(0.0, 1.0))) w.beta = *v;
  if (auto v = reader.number("gamma", between(0.0, 1.0))) w.gamma = *v;
  if (auto v = reader.number("delta", between(0.0, 1.0))) w.delta = *v;
  if (auto v = reader.number("epsilon", between(0.0, 1.0))) w.epsilon = *v;
  if (any_weight && std::abs(w.sum() - 1.0) > 1e-6)
    reader.problem("alpha", fmt::format("tropism weights alpha + beta + gamma + delta + epsilon must sum to 1 (seed 003), "
                                        "got {:g} (give all five when changing one)", w.sum()));
  if (any_weight && std::abs(w.sum() - 1.0) > 1e-6) w = before;  // reported once, not again by validate()
}

void read_species(TomlTableReader& reader, roots::RootParameters& p) {
  if (auto v = reader.integer("moisture_probes", between(2.0, 256.0))) {
    p.moisture_probes = static_cast<int>(*v);
    if (p.moisture_probes % 2 != 0) reader.problem("moisture_probes", fmt::format("must be even (probes are cast in opposite pairs), got {}", *v));
  }
  if (auto v = reader.number("uptake_decay_years", positive_up_to(limit::tree_lifetime))) p.uptake_decay_years = *v;
  if (auto v = reader.number("uptake_rate_per_m", non_negative_up_to(limit::uptake_rate_per_m))) p.uptake_rate_per_m = *v;
  if (auto v = reader.integer("max_woody_order", from_up_to(1, limit::woody_root_order))) p.max_woody_order = static_cast<int>(*v);
  if (auto v = reader.integer("max_segments", from_up_to(1, limit::root_segments))) p.max_segments = static_cast<int>(*v);
  if (auto v = reader.number("min_depth_m", non_negative_up_to(limit::soil_depth_m))) p.min_depth_m = *v;
  for (roots::RootType type : roots::all_root_types) {
    const std::string name(roots::name_of(type));
    const toml::node* node = reader.node(name);
    if (!node) continue;
    const toml::table* table = node->as_table();
    if (!table) {
      reader.problem(name, fmt::format("expected a table of {} root parameters, got {}", name, toml_type_phrase(*node)));
      continue;
    }
    TomlTableReader type_reader(*table, reader.key_path(name), reader.problems());
    read_type(type_reader, p.of(type));
    type_reader.report_unknown_keys();
  }
}

}  // namespace

void parse_roots(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  if (!node) return;
  const toml::table* table = as_table(node, "roots", problems);
  if (!table) return;
  TomlTableReader reader(*table, "roots", problems);
  RootsSettings& settings = draft.scenario.roots;
  if (auto enabled = reader.boolean("enabled")) settings.enabled = *enabled;
  // Scenarios written before light and roots shared one device chose the root backend here.
  if (reader.node("solver"))
    reader.problem("solver", "no longer read: run.device (or grow --device) runs the light and the roots on one "
                             "backend");
  for (auto&& [key, value] : *table) {
    const std::string name(key.str());
    if (name == "enabled" || name == "solver") continue;
    if (!draft.scenario.species.count(name)) {
      reader.node(name);  // reported here, not again as unknown
      reader.problem(name, fmt::format("no species \"{}\" (a [roots.SPECIES] table names a [species] table, or "
                                       "todomatsu when there is none)", name));
      continue;
    }
    const toml::table* species_table = reader.node(name)->as_table();
    if (!species_table) {
      reader.problem(name, fmt::format("expected a table of root parameters, got {}", toml_type_phrase(value)));
      continue;
    }
    TomlTableReader species_reader(*species_table, reader.key_path(name), problems);
    roots::RootParameters parameters = roots::tap_rooted_conifer();
    parameters.name = name;
    read_species(species_reader, parameters);
    species_reader.report_unknown_keys();
    try {
      parameters.validate();
    } catch (const std::invalid_argument& error) {
      problems.add(species_reader.line(), reader.key_path(name), error.what());
    }
    settings.by_species[name] = std::move(parameters);
  }
  reader.report_unknown_keys();
}

}  // namespace heliostand::scenario_detail
