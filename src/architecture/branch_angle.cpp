#include "architecture/branch_angle.hpp"

namespace heliostand {

double branch_angle_rate_deg_per_year(const SpeciesParameters& species) {
  return (species.final_branch_angle_deg - species.initial_branch_angle_deg) / species.lifespan_years;
}

double branch_droop_deg(const SpeciesParameters& species, double years_since_emergence) {
  return years_since_emergence * species.annual_droop_deg;
}

double first_order_branch_angle_deg(const SpeciesParameters& species, double years_since_emergence) {
  return years_since_emergence * branch_angle_rate_deg_per_year(species) + species.initial_branch_angle_deg +
         branch_droop_deg(species, years_since_emergence);
}

}  // namespace heliostand
