#include "light/reference_light_solver.hpp"

#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>
#include <span>

#include "core/parallel_for.hpp"
#include "core/seconds_since.hpp"
#include "light/celestial_sphere.hpp"
#include "light/far_field.hpp"
#include "light/light_sum.hpp"
#include "light/near_field.hpp"
#include "light/occluders.hpp"

namespace heliostand {
namespace {

using Clock = std::chrono::steady_clock;

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

// Culled mode, one receiver: its near-field occluders ray-tested per patch, then the far field from
// FarField::start_distance (the cut-off; one cell beyond it with the bias correction) outward.
LightSample culled_sample(const OccluderSet& set, std::span<const std::uint32_t> occluders,
                          const std::optional<FarField>& far, const glm::dvec3& centre, const CelestialSphere& sky,
                          const PlotTorus& torus, double t) {
  std::vector<double> intensity;
  intensity.reserve(sky.patches().size());
  for (std::size_t q = 0; q < sky.patches().size(); ++q) {
    const auto& patch = sky.patches()[q];
    double b = patch.initial_intensity;
    for (auto j : occluders)
      if (ray_hits_ball(centre, patch.direction, set.centres[j], set.radii[j])) b *= t;
    if (far) b *= std::exp(-(1.0 - t) * far->optical_depth(torus.wrap(centre), static_cast<int>(q)));
    intensity.push_back(b);
  }
  return light_sample(sky, intensity);
}

}  // namespace

ReferenceLightSolver::ReferenceLightSolver(const LightParameters& parameters) : parameters_(parameters) {
  validate(parameters_);
}

std::vector<LightSample> ReferenceLightSolver::solve_for(std::span<const LeafBall> balls,
                                                         std::span<const std::uint32_t> receivers) {
  check_receivers(balls, receivers);
  statistics_ = {};
  const CelestialSphere sky(parameters_);
  const PlotTorus torus = PlotTorus::from(parameters_);
  return parameters_.exact ? solve_exact(balls, receivers, sky, torus) : solve_culled(balls, receivers, sky, torus);
}

std::vector<LightSample> ReferenceLightSolver::solve_exact(std::span<const LeafBall> balls,
                                                           std::span<const std::uint32_t> receivers,
                                                           const CelestialSphere& sky, const PlotTorus& torus) {
  const double t = parameters_.transmittance;
  std::vector<LightSample> samples(receivers.size());  // each written by the thread that lights its receiver
  const OccluderSet set = make_occluder_set(balls, torus, 0.0);
  const auto start = Clock::now();
  // Receivers on the worker threads: each sample is its own receiver's alone, computed as on one thread.
  parallel_for(receivers.size(), [&](std::size_t k) {
    const std::uint32_t i = receivers[k];
    std::vector<double> intensity;  // B(h, v)
    intensity.reserve(sky.patches().size());
    for (const auto& patch : sky.patches()) {
      double b = patch.initial_intensity;
      for_each_exact_occluder(set, torus, i, [&](const glm::dvec3& centre, double radius) {
        if (ray_hits_ball(set.centres[i], patch.direction, centre, radius)) b *= t;
      });
      intensity.push_back(b);
    }
    samples[k] = light_sample(sky, intensity);
  });
  statistics_.evaluate_seconds = seconds_since(start);
  statistics_.mean_candidates = torus.periodic ? 9.0 * balls.size() - 1 : double(balls.size()) - 1;
  return samples;
}

std::vector<LightSample> ReferenceLightSolver::solve_culled(std::span<const LeafBall> balls,
                                                            std::span<const std::uint32_t> receivers,
                                                            const CelestialSphere& sky, const PlotTorus& torus) {
  const double t = parameters_.transmittance;
  std::vector<LightSample> samples(receivers.size());  // each written by the thread that lights its receiver
  auto start = Clock::now();
  const OccluderSet set = make_occluder_set(balls, torus, parameters_.cutoff_m);
  const NearFieldSearch search(set, parameters_.cutoff_m);
  const TileCandidates near = search.tile_candidates(receivers, tile_edge_for(parameters_.cutoff_m));
  statistics_.search_seconds = seconds_since(start);
  const auto far_start = Clock::now();
  const std::optional<FarField> far =
      parameters_.far_field ? std::optional<FarField>(std::in_place, set, parameters_, sky) : std::nullopt;
  statistics_.far_field_seconds = seconds_since(far_start);
  statistics_.far_field_cell_m = far ? far->grid().cell.z : 0.0;  // z is never stretched to fit a periodic plot
  statistics_.setup_seconds = seconds_since(start);

  start = Clock::now();
  // Tiles on the worker threads: each receiver's sample is computed as on one thread, into its own slot; the
  // counts are whole numbers, so their sums do not depend on the order either.
  std::vector<std::size_t> candidates_of_tile(near.tile_count()), scanned_of_tile(near.tile_count());
  parallel_for(near.tile_count(), [&](std::size_t tile) {
    std::vector<std::uint32_t> occluders;
    for (auto k = near.slot_start[tile]; k < near.slot_start[tile + 1]; ++k) {
      const std::uint32_t slot = near.slots[k];
      occluders.clear();
      for (auto c = near.start[tile]; c < near.scan_end[k]; ++c)  // the shells that can hold its near field
        if (search.within_cutoff(receivers[slot], near.occluders[c])) occluders.push_back(near.occluders[c]);
      candidates_of_tile[tile] += occluders.size();
      scanned_of_tile[tile] += near.scan_end[k] - near.start[tile];
      samples[slot] = culled_sample(set, occluders, far, set.centres[receivers[slot]], sky, torus, t);
    }
  });
  const std::size_t candidate_total = std::accumulate(candidates_of_tile.begin(), candidates_of_tile.end(), std::size_t{0});
  const std::size_t scanned_total = std::accumulate(scanned_of_tile.begin(), scanned_of_tile.end(), std::size_t{0});
  statistics_.mean_candidates = receivers.empty() ? 0.0 : double(candidate_total) / receivers.size();
  statistics_.mean_tile_candidates = receivers.empty() ? 0.0 : double(scanned_total) / receivers.size();
  statistics_.evaluate_seconds = seconds_since(start);
  return samples;
}

}  // namespace heliostand
