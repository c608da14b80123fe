#include "architecture/growth_stop.hpp"

#include <algorithm>

namespace heliostand {

double growth_stop_years(const SpeciesParameters& species, double first_order_years, int order) {
  return first_order_years + (std::max(order, 1) - 1) * species.activity;
}

bool still_growing(double years_since_emergence, double growth_stop_years) {
  return years_since_emergence < growth_stop_years;
}

double dead_branch_loss_fraction(const SpeciesParameters& species, double years_since_stop) {
  if (species.dead_branch_attached_years <= 0.0) return 1.0;  // dead branches drop at once
  return std::clamp(years_since_stop / species.dead_branch_attached_years, 0.0, 1.0);
}

}  // namespace heliostand
