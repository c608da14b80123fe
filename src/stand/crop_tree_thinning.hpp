#pragma once
// Crop-tree thinning (method crop_tree; German Z-Baum / Auslesedurchforstung): the stand's future is put on a few
// vigorous, well-spaced crop trees, and each is released by removing its strongest competitors.
//   1. Crop trees: living trees by vigour — largest DBH first (the dominant stems), ties to the one with the lower
//      Hegyi index (less crowded), then survey order — each taken when it stands at least crop_tree_spacing_m from
//      every crop tree already taken, until floor(crop_trees_per_ha × area) are chosen (fewer when spacing runs
//      out). A habitat tree may be a crop tree.
//   2. Competitors: the other trees closer than competitor_radius_m to a crop tree, strongest first by their term
//      in the crop tree's Hegyi index, d_j / (d_crop · dist) (stand/hegyi_index.hpp); competitors_per_crop_tree of
//      them, or all in the radius when not given. Crop trees and protected trees are never removed; a tree
//      competing with two crop trees leaves once and counts for both.
// Distances follow the plot's edges (geometry/neighbourhood.hpp).
#include <cstddef>
#include <vector>

#include "stand/thinning.hpp"

namespace heliostand {

// Indices (into `living`) of the crop trees, in the order chosen.
std::vector<std::size_t> select_crop_trees(const CropTreeSettings& settings,
                                           const std::vector<ThinningCandidate>& living, const ThinningPlot& plot);

// The competitors removed: crop tree by crop tree, strongest first.
std::vector<std::size_t> select_crop_tree_competitors(const ThinningRule& rule,
                                                      const std::vector<ThinningCandidate>& living,
                                                      const ThinningPlot& plot);

}  // namespace heliostand
