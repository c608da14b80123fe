#include "architecture/elongation.hpp"

#include <cmath>

#include "geometry/angles.hpp"

namespace heliostand {

double crown_angle_deg(const SpeciesParameters& species, double tree_age_years) {
  return species.initial_crown_angle_deg * std::pow(std::max(tree_age_years, 1.0), species.crown_angle_beta);
}

double first_order_initial_elongation_m(const SpeciesParameters& species, double height_growth_m,
                                        double tree_age_years) {
  const double crown = radians(crown_angle_deg(species, tree_age_years));
  const double tip_angle = pi - crown - radians(species.initial_branch_angle_deg);  // angle at the branch tip
  // A crown angle so wide that the triangle closes no longer (angles ≥ 180°) gives no cone to reach.
  if (tip_angle <= 0.0 || height_growth_m <= 0.0) return 0.0;
  return height_growth_m / std::sin(tip_angle) * std::sin(crown);
}

double total_elongation_m(double initial_elongation_m, double branch_age, double alpha) {
  if (branch_age <= 0.0) return 0.0;
  return initial_elongation_m * std::pow(branch_age, alpha);
}

double annual_elongation_m(double initial_elongation_m, int branch_age, double alpha) {
  return total_elongation_m(initial_elongation_m, branch_age, alpha) -
         total_elongation_m(initial_elongation_m, branch_age - 1, alpha);
}

}  // namespace heliostand
