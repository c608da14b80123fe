#pragma once
// Parameters of the seed-000 light model and of its numerical approximation. Scenario key: [light].
// docs/light.md describes every field (meaning, unit, default).
#include <optional>

namespace heliostand {

struct LightParameters {
  // The celestial sphere around each leaf ball: V latitude bands x H longitude sectors.
  int sky_bands = 16;          // V (upper hemisphere = first V/2 bands); even, 2..64
  int sky_sectors = 32;        // H; 1..128
  double intensity_ratio = 1.5;  // L = C1 / C2 (Table 1: 3/2); C1 = 1 for the sky, C2 = 1/L for ground reflection
  double sky_scale = 1.0;        // multiplies C1 and C2 (seed 003's "sky light x0.5 / x0.7" experiments)
  double transmittance = 0.5;    // t: factor per occluding ball on a patch (seed gives none; docs/model.md)

  // Culling: occluders whose centre lies within `cutoff_m` of a ball's centre are tested exactly; beyond it,
  // a voxel grid of leaf-ball density attenuates each patch direction (far field).
  // exact = true disables both (every ball vs every ball).
  bool exact = false;
  double cutoff_m = 4.0;
  bool far_field = true;           // false: nothing beyond the cut-off shades (to study the approximation)
  double far_field_table_mb = 512;  // memory cap of the far-field table; bigger stands get coarser cells
  double far_field_cell_m = 1.0;  // 2 m cells smear crowns and gaps: light 0.02 too low on average (docs/light.md)

  // Periodic stand edges: treat the plot as a torus for light (edge trees not unnaturally sunlit).
  bool periodic = false;
  double plot_x_min = 0, plot_y_min = 0, plot_x_max = 0, plot_y_max = 0;  // used when periodic

  double sky_light() const { return sky_scale; }                        // C1
  double ground_light() const { return sky_scale / intensity_ratio; }   // C2
};

// Throws std::invalid_argument naming the field and the reason when a value is out of its domain.
void validate(const LightParameters& parameters);

}  // namespace heliostand
