#pragma once
// The celestial sphere of seed 000 around one leaf ball: V latitude bands of equal polar angle x H
// longitude sectors. Patch (h, v) has centre direction N(h, v), exact solid angle S(h, v) and initial
// intensity B0 = C1 (upper hemisphere, v < V/2) or C2 (lower hemisphere: ground reflection).
#include <vector>

#include <glm/vec3.hpp>

#include "light/light_parameters.hpp"

namespace heliostand {

struct SkyPatch {
  int band = 0;                // v, 0-based from the zenith
  int sector = 0;              // h, 0-based from +x, counter-clockwise seen from above
  glm::dvec3 direction{0.0};   // N(h, v): unit vector to the patch centre (polar/azimuth mid-angles)
  double solid_angle = 0;      // S(h, v) = (2 pi / H) (cos theta_v - cos theta_{v+1}), sr
  double initial_intensity = 0;  // B0(h, v)
};

class CelestialSphere {
 public:
  explicit CelestialSphere(const LightParameters& parameters);

  int bands() const { return bands_; }
  int sectors() const { return sectors_; }
  double band_width() const;    // polar angle per band, rad
  double sector_width() const;  // azimuth per sector, rad
  const std::vector<SkyPatch>& patches() const { return patches_; }  // index = band * H + sector
  double unshaded_total() const;  // sum of B0 S: the denominator of light()

 private:
  int bands_;
  int sectors_;
  std::vector<SkyPatch> patches_;
};

}  // namespace heliostand
