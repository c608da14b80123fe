#pragma once
// [competition]: how far a tree's competitors reach, for its Hegyi index in trees.csv (stand/hegyi_index.hpp) and as
// the default release radius of crop-tree thinning.
namespace heliostand {

// Hegyi (1974) counted competitors within a fixed radius of the subject tree and left its size to the stand; fixed
// radii in later use run from about 3 to 10 m. 6 m is three times the 2 m planting spacing of the example stand
// (stands/sobetsu): the first two rings of planted neighbours.
constexpr double default_competition_radius_m = 6.0;

struct CompetitionSettings {
  double hegyi_radius_m = default_competition_radius_m;
};

}  // namespace heliostand
