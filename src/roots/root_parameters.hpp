#pragma once
// Per-type root parameters of the seed-003 growth model, with defaults for a tap-rooted conifer
// (docs/roots.md gives the source or reasoning for every default). Lengths in metres, angles in
// degrees (as in files), times in years.
#include <array>
#include <string>

#include "roots/root_type.hpp"

namespace heliostand::roots {

// Weights of V = α Vn + β Vg + γ Vd + δ Vw + ε Vt; the seed requires α+β+γ+δ+ε = 1.
struct TropismWeights {
  double alpha = 1.0;    // α  growth-direction (inherited) term Vn
  double beta = 0.0;     // β  gravitropism Vg
  double gamma = 0.0;    // γ  diagravitropism Vd (horizontal)
  double delta = 0.0;    // δ  hydrotropism Vw
  double epsilon = 0.0;  // ε  thigmotropism Vt (contact avoidance)

  double sum() const { return alpha + beta + gamma + delta + epsilon; }
};

enum class Tropism { alpha, beta, gamma, delta, epsilon };

// Sets one weight and rescales the other four proportionally so that the sum stays 1 — how the
// seed's demonstrations vary "only the hydrotropism coefficient of the laterals" (Fig. 4–6).
TropismWeights with_weight(TropismWeights weights, Tropism which, double value);

struct AngleRangeDeg {
  double min = 0.0;
  double max = 0.0;
};

struct RootTypeParameters {
  // Expected number of new roots of each child type a growing tip starts per year (the seed's
  // branching probability; values > 1 mean several). Only children allowed by may_branch_into count.
  std::array<double, root_type_count> branching_frequency{};
  AngleRangeDeg branching_angle_deg;     // a new root of this type leaves its parent at this angle (Vn)
  AngleRangeDeg continuation_angle_deg;  // wander of the tip from one year's segment to the next (Vn)
  double elongation_m_per_year = 0.1;    // segment length: one segment per tip per year
  double radius_m = 0.001;               // segment radius (drawn as tube radius)
  double lifespan_years = 1000.0;        // a segment older than this dies, with everything it carries
  double growth_years = 1000.0;          // an axis stops elongating this many years after it started
  // Expected new fine roots per year started by each living segment that is NOT an apex (our extension:
  // the woody framework keeps renewing its fine roots after its axes stop; only where the rules allow
  // this type → fine). 0 = fine roots only at apices, as in the seed's 15-generation demonstrations.
  double fine_root_sprouting_per_year = 0.0;
  double perception_radius_m = 0.2;      // radius of the perception sphere around the root cap
  double absorptive_weight = 0.0;        // uptake capacity per metre of a newly formed segment (0..1)
  TropismWeights tropisms;
};

struct RootParameters {
  std::string name = "tap-rooted conifer";
  std::array<RootTypeParameters, root_type_count> types;

  int moisture_probes = 16;              // K probe vectors per tip (even: cast in antithetic pairs)
  double uptake_decay_years = 0.5;       // τ_u in W = w_type · length · exp(-age / τ_u)
  double uptake_rate_per_m = 0.05;       // fraction of vertex moisture one metre of fully active root
                                         // removes per year (scaled by trilinear weight)
  int max_woody_order = 3;               // laterals and sinkers start only up to this order (main = 0);
                                         // bounds the framework (fine roots are bounded by their lifespan)
  int max_segments = 20000;              // safety cap per tree: beyond it apices only elongate
  double min_depth_m = 0.02;             // roots keep at least this depth below the soil surface

  const RootTypeParameters& of(RootType type) const { return types[index_of(type)]; }
  RootTypeParameters& of(RootType type) { return types[index_of(type)]; }

  // Throws std::invalid_argument naming the type and field if a value is out of range
  // (negative lengths, weights not summing to 1, min > max angle, ...).
  void validate() const;
};

// Defaults for a tap-rooted conifer (Abies / young Pinus; docs/roots.md).
RootParameters tap_rooted_conifer();

}  // namespace heliostand::roots
