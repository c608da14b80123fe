#pragma once
// One conifer grown by the seed-001 rules (Ohsaki et al.): a stem growing by the Chapman–Richards
// height curve, whorls of first-order branches, opposite pairs of lower-order branches, growth stop by
// order, dead branches that persist and then fall tip-first.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "architecture/shoot.hpp"
#include "architecture/species.hpp"

namespace heliostand {

// What calibration fits per tree (stand/calibration.hpp) on top of its species.
struct TreeCalibration {
  double site_asymptote_m = 28.0;   // eq. 1 A: fitted so the height at survey age equals the surveyed height
  double elongation_scale = 1.0;    // multiplies branch elongation: fitted to the surveyed crown radius
  double growth_stop_years_first_order = 18.0;  // eq. 12 base: fitted to the surveyed crown base
};

class ConiferTree {
 public:
  ConiferTree(const SpeciesParameters& species, const TreeCalibration& calibration,
              glm::dvec3 stem_base, std::uint64_t seed, int tree_id);

  // Advance one year: age + 1, stem and branch elongation, new whorl, growth stop, death, fall.
  void grow_year();

  int age() const { return age_; }
  double height_m() const;
  double dbh_cm() const;            // stem diameter at 1.3 m (eq. 2); 0 while shorter than 1.3 m
  double crown_base_m() const;      // height of the lowest living first-order branch (height if none)
  double crown_radius_m() const;    // projected crown radius of living foliage (definition in docs/model.md)
  double stem_volume_m3() const;    // stem volume by integrating eq. 2 along the stem

  const std::vector<Shoot>& shoots() const { return shoots_; }
  std::vector<LeafBall> leaf_balls() const;  // one per living shoot tip that carries foliage
  glm::dvec3 stem_base() const { return stem_base_; }
  int id() const { return tree_id_; }

 private:
  SpeciesParameters species_;
  TreeCalibration calibration_;
  glm::dvec3 stem_base_;
  std::uint64_t seed_;
  int tree_id_;
  int age_ = 0;
  std::vector<Shoot> shoots_;
};

}  // namespace heliostand
