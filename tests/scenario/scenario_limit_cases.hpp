#pragma once
// Every numeric scenario key with its upper limit (issue 11, "Plausibility"), as test cases: the scenario text that
// sets the key, '@' where its value goes. scenario_limits_test.cpp checks that a value just above each limit is an
// error naming the key and that no numeric key lacks a case; limits_cli_test.cpp grows a stand with each key at its
// limit. The limits come from src/scenario/scenario_limits.hpp where they are named there, else they are the key's
// own domain (fractions, angles) and are written here as in the parser.
#include <cmath>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scenario/scenario_limits.hpp"

namespace heliostand::testing {

enum class Bound { inclusive, exclusive, integer };

struct LimitCase {
  std::string key_path;  // as the error names it: "species.todomatsu.site_asymptote_m"
  std::string toml;      // the table (or tables) setting the key, '@' for its value; "[stand]" / "[run]" replace those
  double max;
  Bound bound = Bound::inclusive;

  // The largest accepted value and the smallest refused one, as TOML text ("{}": the shortest text that reads back).
  std::string at_limit() const {
    if (bound == Bound::integer) return fmt::format("{}", static_cast<long long>(max));
    return fmt::format("{}", bound == Bound::exclusive ? std::nextafter(max, -INFINITY) : max);
  }
  std::string above_limit() const {
    if (bound == Bound::integer) return fmt::format("{}", static_cast<long long>(max) + 1);
    return fmt::format("{}", bound == Bound::exclusive ? max : std::nextafter(max, INFINITY));
  }
};

// Test names and failure messages show the key, not the bytes of the case.
inline void PrintTo(const LimitCase& c, std::ostream* out) { *out << c.key_path; }

// A stand of three of stands/tiny's trees (age 20, 10 m x 10 m plot), run for one year.
inline const std::string limits_survey =
    "id,x,y,height,dbh,crown_radius,crown_base,species\n"
    "1,1.5,1.5,9.2,12.4,1.1,4.0,todomatsu\n"
    "2,4.6,1.4,8.1,10.8,0.9,3.7,todomatsu\n"
    "5,4.4,4.4,10.1,14.2,1.3,4.4,todomatsu\n";

inline std::string stand_table(const std::string& key = "", const std::string& lines = "") {
  std::string text = "[stand]\nsurvey = \"survey.csv\"\n";
  for (const char* line : {"age_at_survey = 20", "x_min = 0", "y_min = 0", "x_max = 10", "y_max = 10"}) {
    const std::string name = std::string(line).substr(0, std::string(line).find(' '));
    if (name == key || (key == "plot_margin_m" && name != "age_at_survey")) continue;
    text += std::string(line) + "\n";
  }
  return text + lines;
}

inline const std::string default_run = "[run]\nyears = 1\nseed = 7\n";
// A coarse sky, as stands/tiny's, keeps the reference solver fast; [light] cases bring their own.
inline const std::string default_light = "[light]\nsky_bands = 8\nsky_sectors = 16\n";

// The scenario of `c` with `value` in place of '@'.
inline std::string scenario_text(const LimitCase& c, const std::string& value) {
  std::string text = c.toml;
  for (auto at = text.find('@'); at != std::string::npos; at = text.find('@')) text.replace(at, 1, value);
  const bool own_stand = text.rfind("[stand]", 0) == 0, own_run = text.rfind("[run]", 0) == 0;
  const bool own_light = text.rfind("[light]", 0) == 0;
  return (own_stand ? "" : stand_table()) + (own_run ? "" : default_run) + (own_light ? "" : default_light) + text;
}

namespace limit_cases_detail {

using namespace heliostand::limit;

inline void add_species(std::vector<LimitCase>& cases) {
  struct Field {
    const char* key;
    double max;
    Bound bound;
  };
  const Bound in = Bound::inclusive, ex = Bound::exclusive, n = Bound::integer;
  const Field fields[] = {
      {"site_asymptote_m", tree_height.max, in},        {"height_k", height_k.max, in},
      {"height_m", height_shape.max, in},               {"stem_a_in_crown", taper_coefficient_cm.max, in},
      {"stem_b_in_crown", allometric_exponent.max, in}, {"stem_a_below_crown", taper_coefficient_cm.max, in},
      {"stem_b_below_crown", allometric_exponent.max, in}, {"crown_shape_ratio", crown_shape_ratio.max, in},
      {"whorl_a3", whorl_coefficient.max, in},          {"whorl_b3", whorl_coefficient.max, in},
      {"initial_branch_angle_deg", 180, ex},            {"final_branch_angle_deg", 180, ex},
      {"lifespan_years", tree_lifetime.max, in},        {"annual_droop_deg", annual_droop_deg.max, in},
      {"elongation_alpha", elongation_exponent.max, in}, {"initial_crown_angle_deg", 90, ex},
      {"crown_angle_beta", crown_angle_exponent.max, in}, {"branch_a11", branch_tip_diameter_cm.max, in},
      {"branch_b11", allometric_exponent.max, in},      {"growth_stop_years_first_order", tree_lifetime.max, in},
      {"activity", tree_lifetime.max, in},              {"dead_branch_attached_years", tree_lifetime.max, in},
      {"second_order_elongation_ratio", lateral_ratio.max, in}, {"second_order_branch_angle_deg", 180, ex},
      {"min_parent_length_m", annual_growth_m.max, in}, {"first_order_upward_offset_deg", 90, in},
      {"second_order_jitter_deg", 90, in},              {"max_order", 10, n},
      {"leaf_ball_radius_ratio", leaf_ball_ratio.max, in}, {"leaf_ball_min_radius_m", crown_radius_m.max, in},
      {"leaf_ball_max_radius_m", crown_radius_m.max, in}, {"whorl_azimuth_jitter", 1, in},
      {"lower_order_elongation_alpha", elongation_exponent.max, in}, {"foliage_years", 100, n},
      {"foliage_max_order", 10, n},                     {"heliotropism_strength", 1, in},
      {"death_threshold", 1, in},                       {"death_threshold_dither", 1, in},
      {"suppressed_years_to_death", 1000, n},           {"elongation_light_zero", 1, in},
      {"elongation_light_saturation", 1, in},           {"height_light_zero", 1, in},
      {"height_light_saturation", 1, in},               {"diameter_light_compensation", 1, in},
      {"diameter_light_saturation", 1, in},             {"branch_starved_years_to_death", 1000, n},
      {"suppression_m1", mortality_scale.max, in},      {"suppression_m2", mortality_growth_decay.max, in},
      {"suppression_growth_years", 10, n},              {"background_mortality", 1, in},
      {"max_stand_density_index", stand_density_index.max, in}, {"self_thinning_limit", 1, in},
  };
  for (const Field& f : fields)
    cases.push_back({std::string("species.todomatsu.") + f.key,
                     std::string("[species.todomatsu]\n") + f.key + " = @\n", f.max, f.bound});
}

inline void add_stand_run_light(std::vector<LimitCase>& cases) {
  cases.push_back({"stand.age_at_survey", stand_table("age_at_survey", "age_at_survey = @\n"), grown_tree_age.max,
                   Bound::integer});
  for (const char* key : {"x_min", "y_min", "x_max", "y_max"})
    cases.push_back({std::string("stand.") + key, stand_table(key, std::string(key) + " = @\n"), coordinate_m.max});
  cases.push_back({"stand.plot_margin_m", stand_table("plot_margin_m", "plot_margin_m = @\n"), plot_margin_m.max});
  cases.push_back({"run.years", "[run]\nyears = @\n", tree_lifetime.max, Bound::integer});
  cases.push_back({"run.output_interval", "[run]\nyears = 1\noutput_interval = @\n", tree_lifetime.max,
                   Bound::integer});
  cases.push_back({"run.roots_output_interval", "[run]\nyears = 1\nroots_output_interval = @\n", tree_lifetime.max,
                   Bound::integer});
  const std::string light = "[light]\nsky_bands = 8\nsky_sectors = 16\n";
  cases.push_back({"light.sky_bands", "[light]\nsky_bands = @\nsky_sectors = 16\n", sky_bands.max, Bound::integer});
  cases.push_back({"light.sky_sectors", "[light]\nsky_bands = 8\nsky_sectors = @\n", sky_sectors.max, Bound::integer});
  const std::pair<const char*, double> numbers[] = {
      {"intensity_ratio", intensity_ratio.max}, {"sky_scale", sky_scale.max},
      {"transmittance", 1},                     {"ground_albedo", 1},
      {"cutoff_m", light_distance_m.max},       {"far_field_cell_m", light_distance_m.max},
      {"plot_x_min", coordinate_m.max},         {"plot_y_min", coordinate_m.max},
      {"plot_x_max", coordinate_m.max},         {"plot_y_max", coordinate_m.max},
      {"far_field_table_mb", far_field_table_mb.max}, {"far_field_hand_over_cells", max_far_field_hand_over_cells}};
  for (const auto& [key, max] : numbers)
    cases.push_back({std::string("light.") + key, light + key + " = @\n", max});
  cases.push_back({"competition.hegyi_radius_m", "[competition]\nhegyi_radius_m = @\n", neighbourhood_m.max});
}

inline void add_thinning(std::vector<LimitCase>& cases) {
  auto add = [&](const char* key, const std::string& rest, double max, Bound bound = Bound::inclusive) {
    cases.push_back({std::string("thinning[1].") + key, "[[thinning]]\n" + rest + key + " = @\n", max, bound});
  };
  const std::string by_ids = "method = \"ids\"\nids = [\"2\"]\n";
  add("age", by_ids, tree_lifetime.max, Bound::integer);
  add("when_basal_area_exceeds_m2_per_ha", by_ids, basal_area_m2_per_ha.max);
  add("when_top_height_reaches_m", by_ids, tree_height.max);
  add("repeat_every_years", "age = 21\n" + by_ids, tree_lifetime.max, Bound::integer);
  const std::string from_below = "age = 21\nmethod = \"from_below\"\n";
  add("target_stems_per_ha", from_below, stems_per_ha.max);
  add("target_basal_area_m2_per_ha", from_below, basal_area_m2_per_ha.max);
  add("remove_fraction", from_below, 1);
  add("remove_basal_area_fraction", from_below, 1);
  const std::string crop = "age = 21\nmethod = \"crop_tree\"\n";
  add("crop_trees_per_ha", crop + "crop_tree_spacing_m = 2\n", stems_per_ha.max);
  add("crop_tree_spacing_m", crop + "crop_trees_per_ha = 100\n", neighbourhood_m.max);
  add("competitor_radius_m", crop + "crop_trees_per_ha = 100\ncrop_tree_spacing_m = 2\n", neighbourhood_m.max);
  add("competitors_per_crop_tree", crop + "crop_trees_per_ha = 100\ncrop_tree_spacing_m = 2\n", competitors.max,
      Bound::integer);
  add("dbh_min_cm", "age = 21\nmethod = \"dbh_class\"\n", dbh_cm.max);
  add("dbh_max_cm", "age = 21\nmethod = \"dbh_class\"\n", dbh_cm.max);
  const std::string rows = "age = 21\nmethod = \"rows\"\n";
  add("row_interval", rows, planting_rows.max, Bound::integer);
  add("first_row", rows + "row_interval = 2\n", planting_rows.max, Bound::integer);
  add("row_azimuth_deg", rows + "row_interval = 2\n", 360, Bound::exclusive);
  add("row_tolerance_m", rows + "row_interval = 2\n", neighbourhood_m.max);
}

inline void add_hollow(std::vector<LimitCase>& cases) {
  const std::string head = "[[hollow]]\ntree = \"5\"\n";
  cases.push_back({"hollow[1].height_m", head + "azimuth_deg = 45\nheight_m = @\n", tree_height.max});
  cases.push_back({"hollow[1].azimuth_deg", head + "height_m = 1.2\nazimuth_deg = @\n", 360});
  const std::string placed = head + "height_m = 1.2\nazimuth_deg = 45\n";
  for (const char* key : {"width_m", "wound_height_m", "callus_radius_m", "bark_line_spacing_m", "bark_segment_m",
                          "outline_step_m", "surface_tolerance_m", "bulge_m"})
    cases.push_back({std::string("hollow[1].") + key, placed + key + " = @\n", stem_width_m.max});
  cases.push_back({"hollow[1].polygon_corners", placed + "polygon_corners = @\n", 36, Bound::integer});
}

inline void add_roots(std::vector<LimitCase>& cases) {
  const std::pair<const char*, LimitCase> per_species[] = {
      {"moisture_probes", {"", "", 256, Bound::integer}},
      {"uptake_decay_years", {"", "", tree_lifetime.max}},
      {"uptake_rate_per_m", {"", "", uptake_rate_per_m.max}},
      {"max_woody_order", {"", "", woody_root_order.max, Bound::integer}},
      {"max_segments", {"", "", root_segments.max, Bound::integer}},
      {"min_depth_m", {"", "", soil_depth_m.max}}};
  for (const auto& [key, c] : per_species)
    cases.push_back({std::string("roots.todomatsu.") + key, std::string("[roots.todomatsu]\n") + key + " = @\n",
                     c.max, c.bound});
  const std::pair<const char*, double> per_type[] = {
      {"branching_to_main", main_root_forks.max}, {"branching_to_lateral", roots_per_year.max},
      {"branching_to_sinker", roots_per_year.max}, {"branching_to_fine", roots_per_year.max},
      {"branching_angle_min_deg", 180},           {"branching_angle_max_deg", 180},
      {"continuation_angle_min_deg", 180},        {"continuation_angle_max_deg", 180},
      {"elongation_m_per_year", annual_growth_m.max}, {"radius_m", stem_radius_m.max},
      {"lifespan_years", tree_lifetime.max},      {"growth_years", tree_lifetime.max},
      {"fine_root_sprouting_per_year", roots_per_year.max}, {"perception_radius_m", root_perception_m.max},
      {"absorptive_weight", 1}};
  for (const char* type : {"main", "lateral", "sinker", "fine"}) {
    const std::string table = fmt::format("[roots.todomatsu.{}]\n", type);
    for (const auto& [key, max] : per_type)
      cases.push_back({fmt::format("roots.todomatsu.{}.{}", type, key), table + key + " = @\n", max});
    // The five tropism weights must sum to 1: the one at its limit takes all of it.
    const char* weights[] = {"alpha", "beta", "gamma", "delta", "epsilon"};
    for (const char* weight : weights) {
      std::string lines;
      for (const char* other : weights) lines += std::string(other) + (other == weight ? " = @\n" : " = 0\n");
      cases.push_back({fmt::format("roots.todomatsu.{}.{}", type, weight), table + lines, 1});
    }
  }
}

inline void add_soil_coupling_pruning(std::vector<LimitCase>& cases) {
  cases.push_back({"soil.spacing_m", "[soil]\nspacing_m = @\n", 5});
  cases.push_back({"soil.depth_m", "[soil]\ndepth_m = @\n", soil_depth_m.max});
  cases.push_back({"soil.moisture", "[soil]\nmoisture = @\n", 1});
  cases.push_back({"soil.nutrient", "[soil]\nnutrient = @\n", 1});
  cases.push_back({"soil.moisture.min_face", "[soil]\nmoisture = { gradient = \"z\", min_face = @, max_face = 1 }\n", 1});
  cases.push_back({"soil.moisture.max_face", "[soil]\nmoisture = { gradient = \"z\", min_face = 1, max_face = @ }\n", 1});
  cases.push_back({"soil.moisture.layer_bottoms_m",
                   "[soil]\nmoisture = { layer_bottoms_m = [@], values = [0.5] }\n", soil_depth_m.max});
  cases.push_back({"soil.moisture.values", "[soil]\nmoisture = { layer_bottoms_m = [1], values = [@] }\n", 1});
  cases.push_back({"soil.moisture_recharge", "[soil]\nmoisture_recharge = @\n", 1});
  cases.push_back({"soil.nutrient_recharge", "[soil]\nnutrient_recharge = @\n", 1});
  for (const char* key : {"rho", "tau"})
    cases.push_back({std::string("coupling.") + key, std::string("[coupling]\n") + key + " = @\n",
                     coupling_coefficient.max});
  cases.push_back({"coupling.alpha_b", "[coupling]\nalpha_b = @\n", 1});
  cases.push_back({"coupling.alpha_r", "[coupling]\nalpha_r = @\n", 10});
  cases.push_back({"root_pruning[1].age", "[[root_pruning]]\nage = @\n", tree_lifetime.max, Bound::integer});
  cases.push_back({"root_pruning[1].min_depth_m", "[[root_pruning]]\nevery_year = true\nmin_depth_m = @\n",
                   soil_depth_m.max});
  cases.push_back({"root_pruning[1].min_distance_m", "[[root_pruning]]\nevery_year = true\nmin_distance_m = @\n",
                   root_reach_m.max});
}

}  // namespace limit_cases_detail

inline const std::vector<LimitCase>& limit_cases() {
  static const std::vector<LimitCase> cases = [] {
    std::vector<LimitCase> all;
    limit_cases_detail::add_stand_run_light(all);
    limit_cases_detail::add_species(all);
    limit_cases_detail::add_thinning(all);
    limit_cases_detail::add_hollow(all);
    limit_cases_detail::add_roots(all);
    limit_cases_detail::add_soil_coupling_pruning(all);
    return all;
  }();
  return cases;
}

}  // namespace heliostand::testing
