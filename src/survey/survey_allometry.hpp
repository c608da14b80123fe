#pragma once
// Allometry that fills in what a survey did not measure (docs/formats.md, "Imputation").
//
// Height and DBH come from one curve, seed 001 eq. 2 with the below-crown coefficients of the species
// (stem diameter at height h = a2 (H - h)^b2, Hakodate co-dominant Todomatsu: a2 = 3.336, b2 = 0.771)
// evaluated at breast height h = 1.3 m, and its inverse. Using the same curve both ways means a tree
// imputed either way lies on it. Crown radius and crown base have no seed value: the coefficients below
// are ours, chosen so that a 35-year Todomatsu plantation (heights 14-18 m, DBH 16-26 cm) gets crown radii
// of 1.4-2.1 m and crown bases of 6-8 m, the sizes of Hokkaido plantation surveys.
#include "architecture/species.hpp"
#include "architecture/stem_taper.hpp"  // breast_height_m

namespace heliostand {

struct SurveyAllometry {
  double crown_radius_intercept_m = 0.25;  // crown radius (m) = intercept + slope * DBH (cm)
  double crown_radius_per_dbh_m_per_cm = 0.07;
  double crown_base_height_ratio = 0.45;   // crown base = ratio * height (live-crown ratio 0.55)
};

// DBH (cm) of a tree of height H (m): a2 (H - 1.3)^b2. Zero for trees not taller than breast height.
double dbh_from_height_cm(double height_m, const SpeciesParameters& species);

// Height (m) of a tree of DBH D (cm): 1.3 + (D / a2)^(1 / b2), the inverse of dbh_from_height_cm.
double height_from_dbh_m(double dbh_cm, const SpeciesParameters& species);

double crown_radius_from_dbh_m(double dbh_cm, const SurveyAllometry& allometry);
double crown_base_from_height_m(double height_m, const SurveyAllometry& allometry);

}  // namespace heliostand
