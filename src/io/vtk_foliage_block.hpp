#pragma once
// The `foliage` block of the yearly multiblock (detail `full`): the needles a person sees on a conifer, drawn
// where the model keeps them. Each living shoot of the foliage years that carries a leaf ball becomes a spray of
// needles around its axis, as wide as the ball it stands for (the ball also holds the foliage of the twigs the
// shoot bears), coloured by the light that ball receives. Arrays and sizes: docs/formats.md, "Block `foliage`".
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "records/stand_snapshot.hpp"

namespace heliostand {

// One closed-sided frustum per leaf ball of every living tree, around the ball's shoot from its base to its tip:
// an elliptic cross-section as wide as the ball's radius across the shoot and flatter up and down (a fir's
// flat spray), narrowing towards the shoot tip, as one triangle strip (one cell, 12 triangles). Point data:
// light (the ball's relative light, 0..1, never NaN). Cell data: foliage_age (years since the shoot flushed,
// 0 = this year's needles) and the tree attributes (tree_cell_data.hpp).
vtkSmartPointer<vtkPolyData> build_foliage_block(const StandSnapshot& snapshot);

}  // namespace heliostand
