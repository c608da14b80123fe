#include "hollow/hollow_spec.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "geometry/angles.hpp"
#include "hollow/trunk_surface.hpp"

namespace heliostand::hollow {

namespace {

// Cylindrical placement bends the bark flow around the wound inside a band that may wrap the whole stem;
// the flow stays one-to-one while the wound's half-width (with callus) is below 80 % of half the circumference.
constexpr double max_wrap_fraction = 0.8;
constexpr double widest_outline_fraction = 12.5 / 32.0;

struct Problems {
  std::vector<InputProblem> list;
  void add(const std::string& field, std::string reason) { list.push_back({"", 0, field, std::move(reason)}); }
};

bool finite(double x) { return std::isfinite(x); }

void check_sizes(const HollowSpec& s, Problems& p) {
  const double min_size = 4.0 * seed_unit_m;
  if (!finite(s.width_m) || s.width_m < min_size)
    p.add("width_m", fmt::format("expected a width ≥ {} m (4 seed units), got {}", min_size, s.width_m));
  if (!finite(s.wound_height_m) || s.wound_height_m < min_size)
    p.add("wound_height_m", fmt::format("expected a height ≥ {} m (4 seed units), got {}", min_size, s.wound_height_m));
  const double quarter = s.width_m / 4.0;
  if (!finite(s.callus_radius_m) || s.callus_radius_m < seed_unit_m || s.callus_radius_m > quarter)
    p.add("callus_radius_m", fmt::format("expected r in [{}, W/4 = {}] m, got {}", seed_unit_m, quarter, s.callus_radius_m));
  const double max_bulge = quarter - s.callus_radius_m;
  if (!finite(s.bulge_m) || s.bulge_m < 0.0 || s.bulge_m > max_bulge + 1e-12)
    p.add("bulge_m", fmt::format("expected I in [0, W/4 − r = {}] m, got {}", std::max(max_bulge, 0.0), s.bulge_m));
  if (s.polygon_corners < 4 || s.polygon_corners > 36)
    p.add("polygon_corners", fmt::format("expected M in [4, 36] (±5° jitter keeps corners ordered), got {}", s.polygon_corners));
  if (!finite(s.bark_line_spacing_m) || s.bark_line_spacing_m < 0.002 || s.bark_line_spacing_m > s.width_m)
    p.add("bark_line_spacing_m", fmt::format("expected l in [0.002, W = {}] m, got {}", s.width_m, s.bark_line_spacing_m));
  if (!finite(s.bark_segment_m) || s.bark_segment_m < 0.002 || s.bark_segment_m > s.wound_height_m)
    p.add("bark_segment_m", fmt::format("expected q in [0.002, H = {}] m, got {}", s.wound_height_m, s.bark_segment_m));
  if (!finite(s.outline_step_m) || s.outline_step_m < 0.0002 || s.outline_step_m > s.width_m / 20.0)
    p.add("outline_step_m", fmt::format("expected a step in [0.0002, W/20 = {}] m, got {}", s.width_m / 20.0, s.outline_step_m));
  if (!finite(s.surface_tolerance_m) || s.surface_tolerance_m < 1e-5)
    p.add("surface_tolerance_m", fmt::format("expected a tolerance ≥ 1e-5 m, got {}", s.surface_tolerance_m));
  if (!finite(s.azimuth_deg)) p.add("azimuth_deg", "expected a finite angle in degrees");
}

void check_on_trunk(const HollowSpec& s, const TrunkSurface& trunk, Problems& p) {
  if (!finite(s.height_m) || s.height_m < 0.0) {
    p.add("height_m", fmt::format("expected a height ≥ 0 m above the ground, got {}", s.height_m));
    return;
  }
  const double callus = nominal_max_callus_radius(s, trunk);
  const double top = s.height_m + s.wound_height_m / 2.0 + 2.0 * callus;
  const double bottom = s.height_m - s.wound_height_m / 2.0 - 2.0 * callus;
  // Keep a little stem above the hollow: the taper runs to zero radius at the tip.
  const double usable_top = 0.95 * trunk.tree_height();
  if (top > usable_top)
    p.add("height_m", fmt::format("the hollow reaches {:.3f} m (outline + callus) but the tree is {:.3f} m tall; "
                                  "it must stay below {:.3f} m", top, trunk.tree_height(), usable_top));
  if (bottom < 0.0)
    p.add("height_m", fmt::format("the hollow's lowest point (outline + callus) is {:.3f} m below ground; raise "
                                  "height_m to at least {:.3f} m", -bottom, s.height_m - bottom));
  if (!p.list.empty()) return;

  // The thinnest stem section the hollow spans decides how wide it may be.
  double thinnest = trunk.radius(s.height_m);
  for (int i = 0; i <= 20; ++i) thinnest = std::min(thinnest, trunk.radius(bottom + (top - bottom) * i / 20.0));
  if (thinnest < 2.0 * callus)
    p.add("callus_radius_m", fmt::format("the stem radius drops to {:.3f} m within the hollow, less than twice the "
                                         "callus radius {:.3f} m", thinnest, callus));
  if (s.placement == Placement::tangent_plane) {
    const double diameter = 2.0 * trunk.radius(s.height_m);
    if (s.width_m >= diameter)
      p.add("width_m", fmt::format("{} m is not narrower than the trunk diameter {:.3f} m at the hollow: tangent-plane "
                                   "placement (seed 004) cannot wrap a wound around half the stem or more; use "
                                   "cylindrical placement", s.width_m, diameter));
  } else {
    // The outline's widest point is K(1/2): x′ = (5/4 + 5 + 5 + 5/4)/32 · W = 0.390625 W from its centre line.
    // The bark flow must fit that, the callus foot r and one bark line within 80 % of half the circumference,
    // measured at the hollow's centre radius (the chart's angles are the same at every height).
    const double half_round = pi * trunk.radius(s.height_m);
    const double foot = s.callus_radius_m * trunk.flare_factor(std::max(s.height_m - s.wound_height_m / 2.0, 0.0));
    const double reach = widest_outline_fraction * s.width_m + foot + s.bark_line_spacing_m;
    if (reach > max_wrap_fraction * half_round)
      p.add("width_m", fmt::format("{} m is too wide for this stem: the wound's widest half (0.39·W) plus callus "
                                   "foot and one bark line ({:.3f} m) must stay within 80 % of half the "
                                   "circumference ({:.3f} m)", s.width_m, reach, max_wrap_fraction * half_round));
  }
}

}  // namespace

double nominal_max_callus_radius(const HollowSpec& spec, const TrunkSurface& trunk) {
  const double lowest = std::max(spec.height_m - spec.wound_height_m / 2.0, 0.0);
  return (1.1 * spec.callus_radius_m + std::max(spec.bulge_m, 0.0)) * trunk.flare_factor(lowest);
}

std::vector<InputProblem> validate(const HollowSpec& spec, const TrunkSurface& trunk) {
  Problems p;
  check_sizes(spec, p);
  if (p.list.empty()) check_on_trunk(spec, trunk, p);
  return p.list;
}

}  // namespace heliostand::hollow
