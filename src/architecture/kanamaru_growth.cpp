#include "architecture/kanamaru_growth.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <thread>

#include <glm/geometric.hpp>

#include "architecture/heliotropism.hpp"
#include "geometry/angles.hpp"
#include "light/celestial_sphere.hpp"
#include "light/light_sum.hpp"
#include "light/occluders.hpp"
#include "light/reference_light_solver.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {

LightParameters KanamaruParameters::default_kanamaru_light() {
  LightParameters light;
  light.sky_bands = 16;
  light.sky_sectors = 32;
  light.intensity_ratio = 1.5;  // L = 3/2
  light.transmittance = 0.5;    // calibrated against Fig. 10(e) (docs/model.md, seed 000)
  light.exact = true;
  return light;
}

KanamaruGrowth::KanamaruGrowth(const KanamaruParameters& parameters, std::uint64_t seed)
    : parameters_(parameters), seed_(seed) {
  validate(parameters_.light);
}

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
LightSample kanamaru_light(const CelestialSphere& sky, const std::vector<LeafBall>& balls, std::size_t receiver,
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

// Every current tip carries a leaf ball; the new branches are the receivers, split over the cores (solving is
// independent per receiver).
std::vector<LightSample> KanamaruGrowth::light_of(const DichotomyTree& tree, const std::vector<int>& receivers) {
  const std::vector<int> tips = tree.tips();
  const std::vector<LeafBall> balls = tree.leaf_balls(tips, parameters_.leaf_ball_radius);
  std::vector<std::uint32_t> slots;
  for (int r : receivers) {
    const auto found = std::lower_bound(tips.begin(), tips.end(), r);
    slots.push_back(static_cast<std::uint32_t>(found - tips.begin()));
  }
  const CelestialSphere sky(parameters_.light);
  const std::size_t workers = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
  const std::size_t chunk = std::max<std::size_t>(1, (slots.size() + workers - 1) / workers);
  std::vector<LightSample> samples(slots.size());
  std::vector<std::thread> threads;
  for (std::size_t begin = 0; begin < slots.size(); begin += chunk) {
    const std::size_t end = std::min(slots.size(), begin + chunk);
    threads.emplace_back([&, begin, end] {
      if (parameters_.enclosing_balls_shade) {
        ReferenceLightSolver solver(parameters_.light);
        const auto part = solver.solve_for(balls, std::span(slots).subspan(begin, end - begin));
        std::copy(part.begin(), part.end(), samples.begin() + static_cast<std::ptrdiff_t>(begin));
      } else {
        for (std::size_t k = begin; k < end; ++k)
          samples[k] = kanamaru_light(sky, balls, slots[k], parameters_.light.transmittance);
      }
    });
  }
  for (auto& thread : threads) thread.join();
  return samples;
}

GenerationRecord KanamaruGrowth::grow_generation(DichotomyTree& tree) {
  const std::vector<int> added = tree.add_generation(parameters_.death);
  GenerationRecord record;
  record.generation = tree.generation();
  record.added = static_cast<int>(added.size());
  // Light for every new branch first, then the decisions (Fig. 9): a removal this generation does not
  // brighten its siblings until the next one.
  const std::vector<LightSample> light = light_of(tree, added);
  std::vector<char> dies(added.size(), 0);
  if (parameters_.pruning == Pruning::light) {
    for (std::size_t k = 0; k < added.size(); ++k)
      dies[k] = dies_of_shade(light[k].light, tree.branches()[added[k]].threshold);
  } else if (parameters_.pruning == Pruning::random) {
    RandomStream random(seed_, {0x4A4Du, static_cast<std::uint64_t>(tree.generation())});
    const auto g = static_cast<std::size_t>(tree.generation());
    if (g < random_survivors.size()) {
      // Keep exactly the prescribed number, chosen uniformly (partial Fisher-Yates).
      std::vector<std::size_t> order(added.size());
      std::iota(order.begin(), order.end(), 0);
      for (std::size_t k = 0; k + 1 < order.size(); ++k)
        std::swap(order[k], order[k + static_cast<std::size_t>(random.below(static_cast<int>(order.size() - k)))]);
      std::fill(dies.begin(), dies.end(), 1);
      const std::size_t keep = std::min<std::size_t>(order.size(), static_cast<std::size_t>(std::max(0, random_survivors[g])));
      for (std::size_t k = 0; k < keep; ++k) dies[order[k]] = 0;
    } else {
      for (auto& d : dies) d = !random.chance(parameters_.random_survival);
    }
  }
  for (std::size_t k = 0; k < added.size(); ++k) {
    record.mean_light += light[k].light / std::max<std::size_t>(added.size(), 1);
    if (dies[k]) {
      tree.remove_branch(added[k]);
    } else {
      ++record.survived;
      tree.turn_branch(added[k], heliotropic_direction(tree.direction(added[k]), light[k].vector,
                                                        parameters_.heliotropism));
    }
  }
  history_.push_back(record);
  return record;
}

void KanamaruGrowth::grow(DichotomyTree& tree, int generation,
                          const std::function<void(const DichotomyTree&)>& after) {
  while (tree.generation() < generation) {
    grow_generation(tree);
    if (after) after(tree);
  }
}

}  // namespace heliostand
