#include "survey/survey_allometry.hpp"

#include <cmath>

namespace heliostand {

double dbh_from_height_cm(double height_m, const SpeciesParameters& species) {
  if (height_m <= breast_height_m) return 0.0;
  return species.stem_a_below_crown * std::pow(height_m - breast_height_m, species.stem_b_below_crown);
}

double height_from_dbh_m(double dbh_cm, const SpeciesParameters& species) {
  return breast_height_m + std::pow(dbh_cm / species.stem_a_below_crown, 1.0 / species.stem_b_below_crown);
}

double crown_radius_from_dbh_m(double dbh_cm, const SurveyAllometry& allometry) {
  return allometry.crown_radius_intercept_m + allometry.crown_radius_per_dbh_m_per_cm * dbh_cm;
}

double crown_base_from_height_m(double height_m, const SurveyAllometry& allometry) {
  return allometry.crown_base_height_ratio * height_m;
}

}  // namespace heliostand
