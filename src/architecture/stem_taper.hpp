#pragma once
// Seed 001 eq. 2: stem diameter (cm) at height h above ground = a2 (H - h)^b2, with one coefficient set
// inside the live crown and another below it (Hakodate co-dominant trees). DBH is the value at 1.3 m.
#include "architecture/species.hpp"

namespace heliostand {

struct StemTaper {
  double height_m = 0;      // H, tree height
  double crown_base_m = 0;  // live-crown base: the in-crown coefficients apply at and above it

  double diameter_cm(const SpeciesParameters& species, double height_above_ground_m) const;
  double dbh_cm(const SpeciesParameters& species) const;  // 0 while the tree is shorter than 1.3 m
  // Volume (m3) of the solid of revolution of eq. 2 from the ground to the top (closed-form integral).
  double volume_m3(const SpeciesParameters& species) const;
};

inline constexpr double breast_height_m = 1.3;

}  // namespace heliostand
