#include "light/kanamaru_light_solver.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include <glm/geometric.hpp>

#include "core/parallel_for.hpp"
#include "geometry/angles.hpp"
#include "light/light_sum.hpp"
#include "light/occluders.hpp"
#include "light/reference_light_solver.hpp"

namespace heliostand {

namespace {

// The sky patches whose centre ray can hit a ball seen from `from` at offset d (|d| > radius): the ray of
// direction N hits it exactly when the angle between N and d is at most asin(radius / |d|) (ray_hits_ball).
// Only a cone around d is visited, band by band; a small margin keeps the cull conservative, and the caller
// still runs the exact ray test on every candidate, so the light is the same as testing all patches.
template <typename Visit>
void visit_patches_near(const CelestialSphere& sky, const glm::dvec3& d, double radius, Visit&& visit) {
  constexpr double margin = 1e-6;  // rad; rounding in the angles below is ~1e-15
  const double distance = glm::length(d);
  const double cone = std::asin(std::min(1.0, radius / distance)) + margin;
  const double polar = std::acos(std::clamp(d.z / distance, -1.0, 1.0));
  const double azimuth = std::atan2(d.y, d.x);
  const double band_width = sky.band_width(), sector_width = sky.sector_width();
  const int sectors = sky.sectors();
  const int first_band = std::max(0, static_cast<int>(std::ceil((polar - cone) / band_width - 0.5)));
  const int last_band = std::min(sky.bands() - 1, static_cast<int>(std::floor((polar + cone) / band_width - 0.5)));
  for (int v = first_band; v <= last_band; ++v) {
    const double middle = (v + 0.5) * band_width;
    // Spherical law of cosines: cos(angle) = cos a cos b + sin a sin b cos(delta azimuth) <= cos(cone).
    const double across = std::sin(middle) * std::sin(polar);
    double half_span = pi;  // near a pole every sector may be hit
    if (across > 1e-9) {
      const double c = (std::cos(cone) - std::cos(middle) * std::cos(polar)) / across;
      if (c > 1.0) continue;
      if (c > -1.0) half_span = std::acos(c) + margin;
    }
    const int first = static_cast<int>(std::ceil((azimuth - half_span) / sector_width - 0.5));
    const int last = static_cast<int>(std::floor((azimuth + half_span) / sector_width - 0.5));
    const int count = std::min(sectors, last - first + 1);  // each sector at most once
    for (int k = 0; k < count; ++k) visit(static_cast<std::size_t>(v * sectors + ((first + k) % sectors + sectors) % sectors));
  }
}

}  // namespace

// Seed 000's light for one receiver, exact: every patch ray that can reach another tip's ball is tested against
// it (patches outside the ball's cone are skipped, visit_patches_near); balls that contain the receiver's centre
// cast no shadow (their projection on its celestial sphere is undefined). B <- B t once per ball hit.
LightSample kanamaru_light(const CelestialSphere& sky, std::span<const LeafBall> balls, std::size_t receiver,
                           double transmittance) {
  const glm::dvec3 centre = balls[receiver].centre;
  const auto& patches = sky.patches();
  std::vector<int> hits(patches.size(), 0);
  for (std::size_t j = 0; j < balls.size(); ++j) {
    const glm::dvec3 d = balls[j].centre - centre;
    if (j == receiver || glm::dot(d, d) <= balls[j].radius * balls[j].radius) continue;
    visit_patches_near(sky, d, balls[j].radius, [&](std::size_t p) {
      if (ray_hits_ball(centre, patches[p].direction, balls[j].centre, balls[j].radius)) ++hits[p];
    });
  }
  std::vector<double> intensity;
  intensity.reserve(patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p) {
    double b = patches[p].initial_intensity;
    for (int k = 0; k < hits[p]; ++k) b *= transmittance;
    intensity.push_back(b);
  }
  return light_sample(sky, intensity);
}

KanamaruLightSolver::KanamaruLightSolver(const LightParameters& parameters, bool enclosing_balls_shade)
    : parameters_(parameters), enclosing_balls_shade_(enclosing_balls_shade) {
  validate(parameters_);
}

std::vector<LightSample> KanamaruLightSolver::solve_for(std::span<const LeafBall> balls,
                                                        std::span<const std::uint32_t> receivers) {
  check_receivers(balls, receivers);
  const CelestialSphere sky(parameters_);
  // The receivers in one chunk a thread, on the hardware's threads (at most eight); the threads that can start share
  // the chunks of those that cannot (a process at its limit of threads), so the answer never depends on them.
  const std::size_t workers = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
  const std::size_t chunk = std::max<std::size_t>(1, (receivers.size() + workers - 1) / workers);
  const std::size_t chunks = (receivers.size() + chunk - 1) / chunk;
  std::vector<LightSample> samples(receivers.size());
  parallel_for_on(workers, chunks, [&](std::size_t c) {
    const std::size_t begin = c * chunk, end = std::min(receivers.size(), begin + chunk);
    if (enclosing_balls_shade_) {
      ReferenceLightSolver stand_rule(parameters_);
      const auto part = stand_rule.solve_for(balls, receivers.subspan(begin, end - begin));
      std::copy(part.begin(), part.end(), samples.begin() + static_cast<std::ptrdiff_t>(begin));
    } else {
      for (std::size_t k = begin; k < end; ++k)
        samples[k] = kanamaru_light(sky, balls, receivers[k], parameters_.transmittance);
    }
  });
  statistics_ = {};
  statistics_.mean_candidates = balls.empty() ? 0.0 : static_cast<double>(balls.size() - 1);
  return samples;
}

}  // namespace heliostand
