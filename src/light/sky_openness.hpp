#pragma once
// Per-tree summary of the light field: a tree's sky openness is the mean light of its leaf balls (0..1).
#include <cstddef>
#include <span>
#include <vector>

#include "light/light_solver.hpp"

namespace heliostand {

// tree_of_ball[k] is the tree (0 .. tree_count-1) owning ball k. Trees without leaf balls get NaN: they have
// no foliage to see the sky with. Throws std::invalid_argument on mismatched sizes or an out-of-range tree.
std::vector<double> sky_openness(std::span<const LightSample> samples, std::span<const int> tree_of_ball,
                                 std::size_t tree_count);

}  // namespace heliostand
