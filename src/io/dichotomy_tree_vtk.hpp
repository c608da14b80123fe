#pragma once
// Seed 000's dichotomy tree (architecture/dichotomy_tree.hpp) as VTK XML PolyData for ParaView: what the seed-000
// experiments (experiments/kanamaru/) and the heliotropism validation write for each drawn generation.
#include <filesystem>

#include "architecture/dichotomy_tree.hpp"

namespace heliostand {

// Drawn radius of a branch carrying one tip, in branch lengths (a branch carrying n tips: this × sqrt(n)).
inline constexpr double kanamaru_tip_drawing_radius = 0.03;

// The living branches as lines (cell arrays generation, group, is_tip, leaf_ball_radius; point array `radius`,
// a drawing radius by the pipe model since the model has no wood).
void write_crown_vtp(const DichotomyTree& tree, double leaf_ball_radius, const std::filesystem::path& path);
// The living tips (leaf-ball centres) as vertices with a `group` point array.
void write_tips_vtp(const DichotomyTree& tree, const std::filesystem::path& path);

}  // namespace heliostand
