#include "stand/trunk_mesh.hpp"

#include <spdlog/spdlog.h>

#include "hollow/conifer_trunk.hpp"

namespace heliostand {

std::shared_ptr<const hollow::HollowMesh> trunk_mesh_of(const StandTree& stand_tree) {
  const ConiferTree& tree = stand_tree.conifer;
  if (tree.height_m() <= 0.0) return nullptr;
  const hollow::TrunkSurface trunk = hollow::conifer_trunk(tree.species(), tree.height_m(), tree.crown_base_m(), tree.stem_scale());
  auto plain_stem = [&] {
    return std::make_shared<const hollow::HollowMesh>(hollow::build_trunk_mesh(trunk, plain_trunk_tolerance_m));
  };
  if (stand_tree.hollows.empty()) return plain_stem();
  try {
    return std::make_shared<const hollow::HollowMesh>(hollow::build_stem_with_hollows(stand_tree.hollows, trunk));
  } catch (const InputError& error) {
    spdlog::warn("tree '{}': its hollows no longer fit its trunk at height {:.1f} m ({}); trunk written without them",
                 stand_tree.label, tree.height_m(), error.problems().front().format("field"));
    return plain_stem();
  }
}

}  // namespace heliostand
