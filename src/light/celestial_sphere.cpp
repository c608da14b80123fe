#include "light/celestial_sphere.hpp"

#include <cmath>

#include "geometry/angles.hpp"

namespace heliostand {

CelestialSphere::CelestialSphere(const LightParameters& parameters)
    : bands_(parameters.sky_bands), sectors_(parameters.sky_sectors) {
  patches_.reserve(static_cast<std::size_t>(bands_ * sectors_));
  for (int v = 0; v < bands_; ++v) {
    const double top = v * band_width(), bottom = (v + 1) * band_width(), middle = (v + 0.5) * band_width();
    const double solid_angle = sector_width() * (std::cos(top) - std::cos(bottom));
    const double intensity = v < bands_ / 2 ? parameters.sky_radiance(middle) : parameters.ground_light();
    for (int h = 0; h < sectors_; ++h) {
      const double azimuth = (h + 0.5) * sector_width();
      const glm::dvec3 direction{std::sin(middle) * std::cos(azimuth), std::sin(middle) * std::sin(azimuth),
                                 std::cos(middle)};
      patches_.push_back({v, h, direction, solid_angle, intensity});
    }
  }
}

double CelestialSphere::band_width() const { return pi / bands_; }
double CelestialSphere::sector_width() const { return 2.0 * pi / sectors_; }

double CelestialSphere::unshaded_total() const {
  double total = 0;
  for (const auto& patch : patches_) total += patch.initial_intensity * patch.solid_angle;
  return total;
}

}  // namespace heliostand
