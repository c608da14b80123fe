#include "light/reference_light_solver.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include "light/celestial_sphere.hpp"
#include "light/far_field.hpp"
#include "light/light_sum.hpp"
#include "light/near_field.hpp"
#include "light/occluders.hpp"

namespace heliostand {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Exact mode: every ball of the stand, plus in periodic mode its 8 images across the plot edges
// (the receiver's own images included: on a torus they are other copies of the canopy).
template <typename Visit>
void for_each_exact_occluder(const OccluderSet& set, const PlotTorus& torus, std::uint32_t receiver, Visit visit) {
  const int reach = torus.periodic ? 1 : 0;
  for (std::size_t j = 0; j < set.ball_count; ++j)
    for (int sx = -reach; sx <= reach; ++sx)
      for (int sy = -reach; sy <= reach; ++sy) {
        if (j == receiver && sx == 0 && sy == 0) continue;
        visit(set.centres[j] + glm::dvec3(sx * torus.size.x, sy * torus.size.y, 0.0), set.radii[j]);
      }
}

}  // namespace

ReferenceLightSolver::ReferenceLightSolver(const LightParameters& parameters) : parameters_(parameters) {
  validate(parameters_);
}

std::vector<LightSample> ReferenceLightSolver::solve_for(std::span<const LeafBall> balls,
                                                         std::span<const std::uint32_t> receivers) {
  check_receivers(balls, receivers);
  const CelestialSphere sky(parameters_);
  const PlotTorus torus = PlotTorus::from(parameters_);
  const double t = parameters_.transmittance;
  statistics_ = {};
  std::vector<LightSample> samples;
  samples.reserve(receivers.size());

  if (parameters_.exact) {
    const OccluderSet set = make_occluder_set(balls, torus, 0.0);
    const auto start = Clock::now();
    for (auto i : receivers) {
      std::vector<double> intensity;  // B(h, v)
      for (const auto& patch : sky.patches()) {
        double b = patch.initial_intensity;
        for_each_exact_occluder(set, torus, i, [&](const glm::dvec3& centre, double radius) {
          if (ray_hits_ball(set.centres[i], patch.direction, centre, radius)) b *= t;
        });
        intensity.push_back(b);
      }
      samples.push_back(light_sample(sky, intensity));
    }
    statistics_.evaluate_seconds = seconds_since(start);
    statistics_.mean_candidates = torus.periodic ? 9.0 * balls.size() - 1 : double(balls.size()) - 1;
    return samples;
  }

  auto start = Clock::now();
  const OccluderSet set = make_occluder_set(balls, torus, parameters_.cutoff_m);
  const NearFieldSearch search(set, parameters_.cutoff_m);
  const CandidateLists near = search.candidates(receivers);
  const std::optional<FarField> far =
      parameters_.far_field ? std::optional<FarField>(std::in_place, set, parameters_, sky) : std::nullopt;
  statistics_.setup_seconds = seconds_since(start);
  statistics_.mean_candidates = receivers.empty() ? 0.0 : double(near.occluders.size()) / receivers.size();

  start = Clock::now();
  for (std::size_t slot = 0; slot < receivers.size(); ++slot) {
    const glm::dvec3 centre = set.centres[receivers[slot]];
    std::vector<double> intensity;
    for (std::size_t q = 0; q < sky.patches().size(); ++q) {
      const auto& patch = sky.patches()[q];
      double b = patch.initial_intensity;
      for (auto k = near.start[slot]; k < near.start[slot + 1]; ++k) {
        const auto j = near.occluders[k];
        if (ray_hits_ball(centre, patch.direction, set.centres[j], set.radii[j])) b *= t;
      }
      if (far) {
        const glm::dvec3 beyond_cutoff = torus.wrap(centre + parameters_.cutoff_m * patch.direction);
        b *= std::exp(-(1.0 - t) * far->optical_depth(beyond_cutoff, static_cast<int>(q)));
      }
      intensity.push_back(b);
    }
    samples.push_back(light_sample(sky, intensity));
  }
  statistics_.evaluate_seconds = seconds_since(start);
  return samples;
}

}  // namespace heliostand
