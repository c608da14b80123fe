#include "roots/root_parameters.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace heliostand::roots {

TropismWeights with_weight(TropismWeights weights, Tropism which, double value) {
  double* fields[] = {&weights.alpha, &weights.beta, &weights.gamma, &weights.delta, &weights.epsilon};
  double& chosen = *fields[static_cast<int>(which)];
  const double others = weights.sum() - chosen;
  const double scale = others > 0.0 ? (1.0 - value) / others : 0.0;
  for (double* field : fields) *field *= scale;
  chosen = value;
  if (others <= 0.0) weights.alpha += 1.0 - value;  // nothing to rescale: the inherited direction takes the rest
  return weights;
}

void RootParameters::validate() const {
  auto fail = [](RootType type, std::string_view field, std::string_view reason) {
    throw std::invalid_argument(fmt::format("root parameters, type '{}': {}: {}", name_of(type), field, reason));
  };
  for (RootType type : all_root_types) {
    const RootTypeParameters& p = of(type);
    const TropismWeights& w = p.tropisms;
    for (double weight : {w.alpha, w.beta, w.gamma, w.delta, w.epsilon})
      if (!(weight >= 0.0)) fail(type, "tropisms", "every weight must be >= 0");
    if (std::abs(w.sum() - 1.0) > 1e-6) fail(type, "tropisms", fmt::format("weights sum to {}, must be 1", w.sum()));
    for (double frequency : p.branching_frequency)
      if (!(frequency >= 0.0)) fail(type, "branching_frequency", "must be >= 0");
    for (const AngleRangeDeg& range : {p.branching_angle_deg, p.continuation_angle_deg})
      if (!(range.min >= 0.0 && range.min <= range.max && range.max <= 180.0))
        fail(type, "angle range", "need 0 <= min <= max <= 180 degrees");
    if (!(p.elongation_m_per_year > 0.0)) fail(type, "elongation_m_per_year", "must be > 0");
    if (!(p.radius_m > 0.0)) fail(type, "radius_m", "must be > 0");
    if (!(p.lifespan_years > 0.0)) fail(type, "lifespan_years", "must be > 0");
    if (!(p.growth_years > 0.0)) fail(type, "growth_years", "must be > 0");
    if (!(p.perception_radius_m > 0.0)) fail(type, "perception_radius_m", "must be > 0");
    if (!(p.absorptive_weight >= 0.0)) fail(type, "absorptive_weight", "must be >= 0");
    if (!(p.fine_root_sprouting_per_year >= 0.0)) fail(type, "fine_root_sprouting_per_year", "must be >= 0");
  }
  if (moisture_probes < 2 || moisture_probes % 2 != 0)
    throw std::invalid_argument("root parameters: moisture_probes must be an even number >= 2");
  if (!(uptake_decay_years > 0.0)) throw std::invalid_argument("root parameters: uptake_decay_years must be > 0");
  if (!(uptake_rate_per_m >= 0.0)) throw std::invalid_argument("root parameters: uptake_rate_per_m must be >= 0");
  if (max_woody_order < 1) throw std::invalid_argument("root parameters: max_woody_order must be >= 1");
  if (max_segments < 1) throw std::invalid_argument("root parameters: max_segments must be >= 1");
}

// Every value is explained in docs/roots.md ("Default parameters").
RootParameters tap_rooted_conifer() {
  RootParameters parameters;
  auto frequencies = [](double main, double lateral, double sinker, double fine) {
    return std::array<double, root_type_count>{main, lateral, sinker, fine};
  };

  RootTypeParameters& tap = parameters.of(RootType::main);
  tap.branching_frequency = frequencies(0.0, 1.5, 0.0, 0.0);
  tap.branching_angle_deg = {0.0, 20.0};
  tap.continuation_angle_deg = {0.0, 10.0};
  tap.elongation_m_per_year = 0.15;
  tap.radius_m = 0.02;
  tap.lifespan_years = 1000.0;
  tap.growth_years = 6.0;
  tap.perception_radius_m = 0.3;
  tap.absorptive_weight = 0.5;
  tap.tropisms = {.alpha = 0.3, .beta = 0.7};

  RootTypeParameters& lateral = parameters.of(RootType::lateral);
  lateral.branching_frequency = frequencies(0.0, 0.2, 0.1, 1.0);
  lateral.branching_angle_deg = {75.0, 95.0};
  lateral.continuation_angle_deg = {0.0, 20.0};
  lateral.elongation_m_per_year = 0.25;
  lateral.radius_m = 0.008;
  lateral.lifespan_years = 1000.0;
  lateral.growth_years = 25.0;
  lateral.fine_root_sprouting_per_year = 0.1;
  lateral.perception_radius_m = 0.3;
  lateral.absorptive_weight = 0.5;
  lateral.tropisms = {.alpha = 0.5, .gamma = 0.4, .delta = 0.05, .epsilon = 0.05};

  RootTypeParameters& sinker = parameters.of(RootType::sinker);
  sinker.branching_frequency = frequencies(0.0, 0.0, 0.05, 0.5);
  sinker.branching_angle_deg = {60.0, 90.0};
  sinker.continuation_angle_deg = {0.0, 10.0};
  sinker.elongation_m_per_year = 0.12;
  sinker.radius_m = 0.005;
  sinker.lifespan_years = 1000.0;
  sinker.growth_years = 5.0;
  sinker.fine_root_sprouting_per_year = 0.1;
  sinker.perception_radius_m = 0.2;
  sinker.absorptive_weight = 0.5;
  sinker.tropisms = {.alpha = 0.3, .beta = 0.6, .delta = 0.05, .epsilon = 0.05};

  RootTypeParameters& fine = parameters.of(RootType::fine);
  fine.branching_frequency = frequencies(0.0, 0.0, 0.0, 0.3);
  fine.branching_angle_deg = {30.0, 90.0};
  fine.continuation_angle_deg = {0.0, 30.0};
  fine.elongation_m_per_year = 0.06;
  fine.radius_m = 0.0005;
  fine.lifespan_years = 2.0;
  fine.growth_years = 2.0;
  fine.perception_radius_m = 0.1;
  fine.absorptive_weight = 1.0;
  fine.tropisms = {.alpha = 0.6, .delta = 0.2, .epsilon = 0.2};
  return parameters;
}

}  // namespace heliostand::roots
