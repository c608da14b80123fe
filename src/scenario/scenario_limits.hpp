#pragma once
// Upper limits of scenario numbers (issue 11, "Plausibility"): the physical or model fact behind each, stated once
// and reused wherever the same bound recurs. A value above its limit is an error before anything runs, and the
// message quotes the reason. docs/formats.md gives every key's range. Limits are generous: no real stand or species
// is refused; they catch slips (a unit, a digit) and values that would overflow or stall the model.
// The survey's limits (tree height, DBH, crown radius, age) are survey/plausible_limits.hpp; the same facts are used
// here through its constants.
#include <string_view>

#include "light/light_parameters.hpp"
#include "scenario/toml_table_reader.hpp"
#include "survey/plausible_limits.hpp"

namespace heliostand::limit {

struct ScenarioLimit {
  double max;
  std::string_view why;  // quoted after the limit in the error message
};

// Facts about trees (shared with the survey).
inline constexpr ScenarioLimit tree_lifetime{max_tree_age_years, "the oldest known non-clonal tree is about 4,850 "
                                                                 "years old"};
inline constexpr ScenarioLimit tree_height{max_tree_height_m, "the tallest measured tree, a coast redwood, is 116 m"};
inline constexpr ScenarioLimit dbh_cm{max_dbh_cm, "the thickest measured stems are about 11-12 m across"};
inline constexpr ScenarioLimit stem_width_m{max_dbh_cm / 100, "the thickest measured stems are about 11-12 m across"};
inline constexpr ScenarioLimit stem_radius_m{max_dbh_cm / 200, "no root is thicker than the thickest stems, about "
                                                               "11-12 m across"};
inline constexpr ScenarioLimit crown_radius_m{max_crown_radius_m, "a leaf ball is part of a crown, and the widest "
                                                                  "measured crowns are about 60 m across"};
inline constexpr ScenarioLimit coordinate_m{max_coordinate_m, "coordinates in metres stay below 10,000 km, the range "
                                                              "of UTM northings"};
// The fastest-growing trees (Eucalyptus, Paulownia) add about 3-5 m of height a year; roots elongate less.
inline constexpr ScenarioLimit annual_growth_m{10, "no tree's annual shoot or root segment is longer than 10 m (the "
                                                   "fastest trees grow about 5 m a year)"};

// What the model can grow (measured on this project's shared 2-core machine, Release build, three 20-year trees of
// stands/tiny grown one year with --device reference): beyond these a run does not crash but does not end either.
inline constexpr ScenarioLimit grown_tree_age{100, "the model grows every surveyed tree from age 0, about ten times, "
                                                   "to fit it: three trees took 52 s at 100 years, 90-120 s at 150 "
                                                   "and over 300 s at 300"};
inline constexpr ScenarioLimit branches_per_whorl{20, "conifers carry 3-8 first-order branches per whorl; three trees "
                                                      "took 15 s at 20 per whorl and 263 s at 103"};
// eq. 9: a first-order branch's first shoot is dH sin(theta) / sin(180° - theta - d0), which diverges as the crown
// angle theta and d0 close the triangle (a crown_angle_beta of 1 grew crowns 2e14 m wide at age 20).
inline constexpr double min_branch_triangle_opening_deg = 5;  // the shoot at most 11.5 times the year's height growth

// Stands and their management.
inline constexpr ScenarioLimit neighbourhood_m{100, "competition and spacing radii in use are 3-15 m; 100 m is a "
                                                    "neighbourhood of 3 ha"};
inline constexpr ScenarioLimit stems_per_ha{100'000, "one stem per 0.1 m², five times the densest plantings "
                                                     "(short-rotation coppice, about 20,000/ha)"};
inline constexpr ScenarioLimit basal_area_m2_per_ha{10'000, "stems cannot cover more ground than the hectare itself"};
inline constexpr ScenarioLimit planting_rows{1000, "rows are at least 1 m apart: 1000 rows span a kilometre, more "
                                                   "than any plot grown tree by tree"};
inline constexpr ScenarioLimit competitors{1000, "a crop tree is released from its 1-6 strongest competitors in "
                                                 "practice"};
inline constexpr ScenarioLimit plot_margin_m{1e4, "10 km around a stand's trees is a slip, not a plot"};
inline constexpr ScenarioLimit stand_density_index{5000, "the largest published Reineke maxima are about 1,000 "
                                                         "stems per acre (2,470/ha)"};

// Coefficients of the architecture model (seed 001).
inline constexpr ScenarioLimit height_k{1, "eq. 1: k = 1/year closes 63 % of the gap to the asymptote every year; "
                                           "fitted height curves have k of about 0.01-0.1"};
inline constexpr ScenarioLimit height_shape{0.8, "eq. 1: p = 1/(1 - m) <= 5; fitted height curves have p of about "
                                                 "1-3, and beyond it the calibrated asymptote of a young tree runs to "
                                                 "kilometres"};
inline constexpr ScenarioLimit taper_coefficient_cm{max_dbh_cm, "eq. 2: a2 is the stem diameter (cm) 1 m below the "
                                                                "top, and the thickest stems are about 11-12 m "
                                                                "across"};
inline constexpr ScenarioLimit allometric_exponent{3, "diameter-length exponents of stems and branches run from 0.5 "
                                                      "(paraboloid) to 1.5 (neiloid)"};
inline constexpr ScenarioLimit crown_shape_ratio{2, "eq. 3 x: crown width over crown length; broad open-grown crowns "
                                                    "reach about 1"};
inline constexpr ScenarioLimit whorl_coefficient{100, "eq. 3 gives branches per whorl; conifers carry 3-8"};
inline constexpr ScenarioLimit annual_droop_deg{180, "an angle from the stem axis cannot change by more than 180° "
                                                     "in a year"};
inline constexpr ScenarioLimit elongation_exponent{2, "eq. 8: annual shoots grow as alpha n^(alpha-1); at 2 each is "
                                                      "longer in proportion to the branch age (seed: 0.9)"};
inline constexpr ScenarioLimit crown_angle_exponent{1, "eq. 10: at 1 the crown angle grows in proportion to the tree "
                                                       "age (seed: 0.18)"};
inline constexpr ScenarioLimit branch_tip_diameter_cm{10, "eq. 11: a11 is the branch diameter (cm) 1 cm behind the "
                                                          "tip (seed: 0.06)"};
inline constexpr ScenarioLimit lateral_ratio{1, "apical control: a lateral's first shoot is no longer than the "
                                                "shoot bearing it (seed Fig. 5: 0.45)"};
inline constexpr ScenarioLimit leaf_ball_ratio{10, "leaf-ball radius per metre of shoot (seed 000 Table 1: 2); the "
                                                   "ball is clamped to its min and max radii anyway"};
inline constexpr ScenarioLimit mortality_scale{100, "1 - exp(-m1) is 1 to double precision from m1 = 37: larger "
                                                    "values change nothing"};
inline constexpr ScenarioLimit mortality_growth_decay{100, "exp(-m2 G) is below 1e-43 from G = 1 mm/year: beyond, "
                                                           "the rule is a step"};

// The light field (seed 000) and the crown-root coupling (seed 003).
inline constexpr const char* sky_patches_in_private_memory =
    "the light kernels keep a value per sky patch in private memory, at most 64 x 128 (light/light_parameters.hpp)";
inline constexpr ScenarioLimit sky_bands{max_sky_bands, sky_patches_in_private_memory};
inline constexpr ScenarioLimit sky_sectors{max_sky_sectors, sky_patches_in_private_memory};
inline constexpr ScenarioLimit intensity_ratio{1000, "C2 = C1/L: from L = 1000 the light from below is under 0.1 % "
                                                     "of the sky's (seed 000: 1.5)"};
inline constexpr ScenarioLimit sky_scale{10, "seed 003's experiments dim the sky to x0.5 and x0.7; x10 is ten full "
                                             "skies"};
inline constexpr ScenarioLimit light_distance_m{max_light_distance_m,
                                                "1 km is wider than any stand grown leaf ball by leaf ball"};
inline constexpr ScenarioLimit far_field_table_mb{1e6, "a terabyte is more memory than any machine this runs on"};
inline constexpr ScenarioLimit coupling_coefficient{1000, "only the ratio of rho and tau matters, and from 1000 every "
                                                          "path's balance is pinned at its clamp"};

// Roots and soil (seed 003).
inline constexpr ScenarioLimit soil_depth_m{50, "the deepest roots measured reach about 60-70 m; the voxel grid's "
                                                "depth"};
inline constexpr ScenarioLimit root_reach_m{100, "the widest-spreading root systems measured reach some tens of "
                                                 "metres from the stem"};
inline constexpr ScenarioLimit roots_per_year{10, "new roots per apex or segment and year (the seed's branching "
                                                  "probability; defaults 0.05-1.5)"};
inline constexpr ScenarioLimit main_root_forks{2, "max_woody_order does not bound the main root, whose apices "
                                                  "multiply until max_segments and keep elongating: three trees took "
                                                  "3 s at 2 forks a year, 10 s at 3, 48 s at 5 and over 120 s at 10 "
                                                  "(seed default 0)"};
inline constexpr ScenarioLimit woody_root_order{10, "woody root systems branch to about 4-6 orders"};
inline constexpr ScenarioLimit root_segments{50'000, "a safety cap per tree; three trees whose laterals branch 10 "
                                                     "times a year reach it in a year: 17 s at 20,000, 59 s at 50,000, "
                                                     "over 200 s at 200,000"};
inline constexpr ScenarioLimit root_perception_m{1, "the root cap senses over centimetres; the seed's sphere is "
                                                    "decimetres (defaults 0.1-0.3 m)"};
inline constexpr ScenarioLimit uptake_rate_per_m{1, "one metre of fully active root takes at most all the moisture "
                                                    "at its tip in a year"};

}  // namespace heliostand::limit

namespace heliostand {

// (min, limit] and [min, limit], with the limit's reason.
constexpr NumberRange above_up_to(double min, limit::ScenarioLimit limit) {
  return {min, limit.max, true, false, true, limit.why};
}
constexpr NumberRange from_up_to(double min, limit::ScenarioLimit limit) {
  return {min, limit.max, false, false, true, limit.why};
}
constexpr NumberRange positive_up_to(limit::ScenarioLimit limit) { return above_up_to(0.0, limit); }
constexpr NumberRange non_negative_up_to(limit::ScenarioLimit limit) { return from_up_to(0.0, limit); }
// [-limit, limit]: a signed quantity bounded in magnitude.
constexpr NumberRange magnitude_up_to(limit::ScenarioLimit limit) { return from_up_to(-limit.max, limit); }

}  // namespace heliostand
