#include "hollow/conifer_trunk.hpp"

#include "architecture/stem_taper.hpp"

namespace heliostand::hollow {

TrunkSurface conifer_trunk(const SpeciesParameters& species, double tree_height_m, double crown_base_m,
                           double diameter_scale) {
  const StemTaper taper{tree_height_m, crown_base_m};
  auto radius_m = [taper, species, diameter_scale](double h) { return diameter_scale * taper.diameter_cm(species, h) / 200.0; };
  return TrunkSurface(radius_m, tree_height_m, conifer_root_collar);
}

}  // namespace heliostand::hollow
