#include <fmt/format.h>

#include <array>

#include "scenario/parameter_fields.hpp"
#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"

namespace heliostand::scenario_detail {

namespace {

using L = LightParameters;

// Every LightParameters field, with its allowed range.
const std::array<ParameterField<L>, 17> light_fields{{
    {"sky_bands", &L::sky_bands, from_up_to(2.0, limit::sky_bands)},
    {"sky_sectors", &L::sky_sectors, from_up_to(4.0, limit::sky_sectors)},
    {"intensity_ratio", &L::intensity_ratio, positive_up_to(limit::intensity_ratio)},
    {"sky_scale", &L::sky_scale, positive_up_to(limit::sky_scale)},
    {"transmittance", &L::transmittance, {0.0, 1.0, true, false}},  // (0, 1]: log(t) per occluder needs t > 0
    {"ground_albedo", &L::ground_albedo, between(0.0, 1.0)},
    {"exact", &L::exact},
    {"cutoff_m", &L::cutoff_m, positive_up_to(limit::light_distance_m)},
    {"far_field_cell_m", &L::far_field_cell_m, positive_up_to(limit::light_distance_m)},
    {"far_field_bias_correction", &L::far_field_bias_correction},
    {"far_field_hand_over_cells", &L::far_field_hand_over_cells, between(0.0, max_far_field_hand_over_cells)},
    {"far_field_table_mb", &L::far_field_table_mb, from_up_to(1.0, limit::far_field_table_mb)},
    {"periodic", &L::periodic},
    {"plot_x_min", &L::plot_x_min, magnitude_up_to(limit::coordinate_m)},
    {"plot_y_min", &L::plot_y_min, magnitude_up_to(limit::coordinate_m)},
    {"plot_x_max", &L::plot_x_max, magnitude_up_to(limit::coordinate_m)},
    {"plot_y_max", &L::plot_y_max, magnitude_up_to(limit::coordinate_m)},
}};

constexpr NamedChoices<LightParameters::Sky, 2> sky_names{
    {{LightParameters::Sky::standard_overcast, "overcast"}, {LightParameters::Sky::kanamaru, "kanamaru"}}};

}  // namespace

void parse_light(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  LightParameters& light = draft.scenario.light;
  // The periodic light domain is the surveyed plot unless [light] says otherwise.
  const PlotBounds& plot = draft.scenario.stand.plot;
  light.plot_x_min = plot.x_min;
  light.plot_y_min = plot.y_min;
  light.plot_x_max = plot.x_max;
  light.plot_y_max = plot.y_max;

  // A stand sees the standard overcast sky unless [light] asks for seed 000's two-level sky (docs/light.md).
  light.sky = LightParameters::Sky::standard_overcast;
  const toml::table* table = as_table(node, "light", problems);
  if (!table) return;
  TomlTableReader reader(*table, "light", problems);
  read_parameter_fields<L>(reader, light_fields, light);
  if (auto sky = reader.choice("sky", sky_names)) light.sky = *sky;
  reader.report_unknown_keys();

  // The first V/2 bands are the upper hemisphere: V must split evenly.
  if (light.sky_bands % 2 != 0) {
    reader.problem("sky_bands", fmt::format("must be even (the upper hemisphere is the first half), got {}", light.sky_bands));
  }
  const bool own_domain = table->contains("plot_x_min") || table->contains("plot_y_min") ||
                          table->contains("plot_x_max") || table->contains("plot_y_max");
  if (own_domain && light.plot_x_max <= light.plot_x_min) {
    reader.problem("plot_x_max", fmt::format("must be greater than plot_x_min ({:g}), got {:g}", light.plot_x_min,
                                             light.plot_x_max));
  }
  if (own_domain && light.plot_y_max <= light.plot_y_min) {
    reader.problem("plot_y_max", fmt::format("must be greater than plot_y_min ({:g}), got {:g}", light.plot_y_min,
                                             light.plot_y_max));
  }
}

}  // namespace heliostand::scenario_detail
