#include "light/light_parameters.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace heliostand {
namespace {

void require(bool ok, const char* field, const std::string& reason) {
  if (!ok) throw std::invalid_argument(std::string("light.") + field + ": " + reason);
}

}  // namespace

void validate(const LightParameters& p) {
  require(p.sky_bands >= 2 && p.sky_bands <= max_sky_bands && p.sky_bands % 2 == 0, "sky_bands",
          "expected an even number in 2.." + std::to_string(max_sky_bands) + ", got " + std::to_string(p.sky_bands));
  require(p.sky_sectors >= 1 && p.sky_sectors <= max_sky_sectors, "sky_sectors",
          "expected a number in 1.." + std::to_string(max_sky_sectors) + ", got " + std::to_string(p.sky_sectors));
  require(p.intensity_ratio > 0, "intensity_ratio", "expected a number > 0");
  require(p.sky_scale > 0, "sky_scale", "expected a number > 0");
  require(p.transmittance > 0 && p.transmittance <= 1, "transmittance", "expected a number in (0, 1]");
  require(p.ground_albedo >= 0 && p.ground_albedo <= 1, "ground_albedo", "expected a number in 0..1");
  const std::string distance = fmt::format("expected a distance in (0, {}] m", max_light_distance_m);
  require(p.cutoff_m > 0 && p.cutoff_m <= max_light_distance_m, "cutoff_m", distance);
  require(p.far_field_cell_m > 0 && p.far_field_cell_m <= max_light_distance_m, "far_field_cell_m", distance);
  require(p.far_field_hand_over_cells >= 0 && p.far_field_hand_over_cells <= max_far_field_hand_over_cells,
          "far_field_hand_over_cells",
          "expected a number of cell edges in 0.." + std::to_string(max_far_field_hand_over_cells));
  require(p.far_field_table_mb >= 1, "far_field_table_mb", "expected at least 1 MB");
  if (p.periodic) {
    require(p.plot_x_max > p.plot_x_min, "plot_x_max", "periodic edges need plot_x_max > plot_x_min");
    require(p.plot_y_max > p.plot_y_min, "plot_y_max", "periodic edges need plot_y_max > plot_y_min");
  }
}

double LightParameters::sky_radiance(double theta) const {
  if (sky == Sky::kanamaru) return sky_light();
  return sky_light() * (1.0 + 2.0 * std::cos(theta)) / 3.0;
}

}  // namespace heliostand
