#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "scenario/parameter_fields.hpp"
#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"

namespace heliostand::scenario_detail {

namespace {

using S = SpeciesParameters;

// Every SpeciesParameters field except `name` (which is the table's key), with its allowed range. Upper limits
// without a named reason are the field's own domain (angles, fractions, the light response's 0..1).
const std::array<ParameterField<S>, 52> species_fields{{
    {"site_asymptote_m", &S::site_asymptote_m, positive_up_to(limit::tree_height)},
    {"height_k", &S::height_k, positive_up_to(limit::height_k)},
    {"height_m", &S::height_exponent_m, non_negative_up_to(limit::height_shape)},
    {"stem_a_in_crown", &S::stem_a_in_crown, positive_up_to(limit::taper_coefficient_cm)},
    {"stem_b_in_crown", &S::stem_b_in_crown, positive_up_to(limit::allometric_exponent)},
    {"stem_a_below_crown", &S::stem_a_below_crown, positive_up_to(limit::taper_coefficient_cm)},
    {"stem_b_below_crown", &S::stem_b_below_crown, positive_up_to(limit::allometric_exponent)},
    {"crown_shape_ratio", &S::crown_shape_ratio, positive_up_to(limit::crown_shape_ratio)},
    {"whorl_a3", &S::whorl_a3, magnitude_up_to(limit::whorl_coefficient)},
    {"whorl_b3", &S::whorl_b3, magnitude_up_to(limit::whorl_coefficient)},
    {"initial_branch_angle_deg", &S::initial_branch_angle_deg, {0.0, 180.0, true, true}},
    {"final_branch_angle_deg", &S::final_branch_angle_deg, {0.0, 180.0, true, true}},
    {"lifespan_years", &S::lifespan_years, positive_up_to(limit::tree_lifetime)},
    {"annual_droop_deg", &S::annual_droop_deg, non_negative_up_to(limit::annual_droop_deg)},
    {"elongation_alpha", &S::elongation_alpha, positive_up_to(limit::elongation_exponent)},
    {"initial_crown_angle_deg", &S::initial_crown_angle_deg, {0.0, 90.0, true, true}},
    {"crown_angle_beta", &S::crown_angle_beta, non_negative_up_to(limit::crown_angle_exponent)},
    {"branch_a11", &S::branch_a11, positive_up_to(limit::branch_tip_diameter_cm)},
    {"branch_b11", &S::branch_b11, positive_up_to(limit::allometric_exponent)},
    {"growth_stop_years_first_order", &S::growth_stop_years_first_order, positive_up_to(limit::tree_lifetime)},
    {"activity", &S::activity, magnitude_up_to(limit::tree_lifetime)},
    {"dead_branch_attached_years", &S::dead_branch_attached_years, positive_up_to(limit::tree_lifetime)},
    {"second_order_elongation_ratio", &S::second_order_elongation_ratio, non_negative_up_to(limit::lateral_ratio)},
    {"second_order_branch_angle_deg", &S::second_order_branch_angle_deg, {0.0, 180.0, true, true}},
    {"min_parent_length_m", &S::min_parent_length_m, non_negative_up_to(limit::annual_growth_m)},
    {"first_order_upward_offset_deg", &S::first_order_upward_offset_deg, between(-90.0, 90.0)},
    {"second_order_jitter_deg", &S::second_order_jitter_deg, between(0.0, 90.0)},
    {"max_order", &S::max_order, between(1.0, 10.0)},
    {"leaf_ball_radius_ratio", &S::leaf_ball_radius_ratio, positive_up_to(limit::leaf_ball_ratio)},
    {"leaf_ball_min_radius_m", &S::leaf_ball_min_radius_m, positive_up_to(limit::crown_radius_m)},
    {"leaf_ball_max_radius_m", &S::leaf_ball_max_radius_m, positive_up_to(limit::crown_radius_m)},
    {"whorl_azimuth_jitter", &S::whorl_azimuth_jitter, between(0.0, 1.0)},
    {"lower_order_elongation_alpha", &S::lower_order_elongation_alpha, positive_up_to(limit::elongation_exponent)},
    {"foliage_years", &S::foliage_years, between(1.0, 100.0)},
    {"foliage_max_order", &S::foliage_max_order, between(0.0, 10.0)},
    {"heliotropism_strength", &S::heliotropism_strength, between(0.0, 1.0)},
    {"death_threshold", &S::death_threshold, between(0.0, 1.0)},
    {"death_threshold_dither", &S::death_threshold_dither, between(0.0, 1.0)},
    {"suppressed_years_to_death", &S::suppressed_years_to_death, between(1.0, 1000.0)},
    {"elongation_light_zero", &S::elongation_light_zero, between(0.0, 1.0)},
    {"elongation_light_saturation", &S::elongation_light_saturation, between(0.0, 1.0)},
    {"height_light_zero", &S::height_light_zero, between(0.0, 1.0)},
    {"height_light_saturation", &S::height_light_saturation, between(0.0, 1.0)},
    {"diameter_light_compensation", &S::diameter_light_compensation, between(0.0, 1.0)},
    {"diameter_light_saturation", &S::diameter_light_saturation, between(0.0, 1.0)},
    {"branch_starved_years_to_death", &S::branch_starved_years_to_death, between(1.0, 1000.0)},
    {"suppression_m1", &S::suppression_m1, non_negative_up_to(limit::mortality_scale)},
    {"suppression_m2", &S::suppression_m2, non_negative_up_to(limit::mortality_growth_decay)},
    {"suppression_growth_years", &S::suppression_growth_years, between(1.0, 10.0)},
    {"background_mortality", &S::background_mortality, between(0.0, 1.0)},
    {"max_stand_density_index", &S::max_stand_density_index, positive_up_to(limit::stand_density_index)},
    {"self_thinning_limit", &S::self_thinning_limit, {0.0, 1.0, true, false}},
}};

std::span<const ParameterField<S>> fields() { return species_fields; }

// Relations between fields that single ranges cannot express.
void check_consistency(TomlTableReader& reader, const SpeciesParameters& species) {
  const double branches_per_whorl = species.whorl_a3 * species.crown_shape_ratio + species.whorl_b3;
  if (branches_per_whorl < 1.0 || branches_per_whorl > limit::branches_per_whorl.max) {
    reader.problems().add(reader.line(), reader.key_path("whorl_b3"),
                          fmt::format("first-order branches per whorl a3 x + b3 = {:g} (eq. 3) must be in [1, {:g}] "
                                      "({})",
                                      branches_per_whorl, limit::branches_per_whorl.max, limit::branches_per_whorl.why));
  }
  if (species.leaf_ball_max_radius_m < species.leaf_ball_min_radius_m) {
    reader.problem("leaf_ball_max_radius_m", fmt::format("must not be below leaf_ball_min_radius_m ({:g}), got {:g}",
                                                         species.leaf_ball_min_radius_m, species.leaf_ball_max_radius_m));
  }
  if (species.final_branch_angle_deg < species.initial_branch_angle_deg) {
    reader.problem("final_branch_angle_deg", fmt::format("must not be below initial_branch_angle_deg ({:g}), got {:g}",
                                                         species.initial_branch_angle_deg, species.final_branch_angle_deg));
  }
}

void resolve_default_species(ScenarioDraft& draft, ScenarioProblems& problems) {
  auto& species = draft.scenario.species;
  if (species.empty()) {
    // No [species] tables: the stand is Todomatsu with the seed-001 defaults.
    species.emplace("todomatsu", SpeciesParameters{});
    draft.species_order.emplace_back("todomatsu", 0);
  }
  if (draft.default_species_key) {
    if (species.count(*draft.default_species_key)) {
      draft.scenario.stand.default_species = *draft.default_species_key;
    } else {
      std::vector<std::string> names;
      for (const auto& [name, _] : species) names.push_back(name);
      problems.add(draft.default_species_line, "stand.default_species",
                   fmt::format("\"{}\" is not a defined species (defined: {})", *draft.default_species_key,
                               fmt::join(names, ", ")));
    }
    return;
  }
  // The first [species.NAME] table in the file (toml++ keeps tables sorted by name, so use lines).
  const auto first = std::min_element(draft.species_order.begin(), draft.species_order.end(),
                                      [](const auto& a, const auto& b) { return a.second < b.second; });
  draft.scenario.stand.default_species = first->first;
}

}  // namespace

void parse_species(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  if (const toml::table* table = as_table(node, "species", problems)) {
    for (auto&& [key, value] : *table) {
      const std::string name(key.str());
      const std::string path = "species." + name;
      if (name == whole_stand_species) {
        problems.add(key.source(), path,
                     fmt::format("\"{}\" is the whole stand's name in stand_table.csv; give the species another name",
                                 whole_stand_species));
        continue;
      }
      const toml::table* parameters = value.as_table();
      if (!parameters) {
        problems.add(key.source(), path,
                     fmt::format("expected a table of species parameters ([species.NAME]), got {}",
                                 toml_type_phrase(value)));
        continue;
      }
      SpeciesParameters species;
      species.name = name;
      TomlTableReader reader(*parameters, path, problems);
      read_parameter_fields<S>(reader, fields(), species);
      reader.report_unknown_keys();
      check_consistency(reader, species);
      draft.scenario.species.emplace(name, species);
      draft.species_order.emplace_back(name, static_cast<int>(parameters->source().begin.line));
    }
  }
  resolve_default_species(draft, problems);
}

}  // namespace heliostand::scenario_detail
