#pragma once
// The lighter blocks of the yearly multiblock, for the levels of detail below `full` (scenario/output_detail.hpp):
// a tree drawn as its stem axis and a closed crown envelope, or as one cone. Every cell carries its tree's
// attributes (tree_cell_data.hpp), so Threshold and selections by tree work on them. Arrays: docs/formats.md.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "records/stand_snapshot.hpp"

namespace heliostand {

// The stem (shoots of axis 0) of every tree as two-point lines. Point data: radius (m, for Tube's "Vary
// Radius: By Absolute Scalar"). Cell data: the tree attributes.
vtkSmartPointer<vtkPolyData> build_stem_block(const StandSnapshot& snapshot);

// One closed convex surface per tree around its foliage: the hull of its leaf balls (each ball's six extreme
// points), from VTK's vtkHull with 66 plane directions, triangulated by Qhull (geometry/convex_hull.hpp) with every
// triangle facing out. Point data: light (at each corner the nearest leaf ball's).
// Each envelope is checked to be closed; the log warns of one that is not, naming its tree.
// Cell data: the tree attributes.
// A tree gone since the previous output year gets the envelope of the crown it had (TreeSnapshot::crown_when_gone).
vtkSmartPointer<vtkPolyData> build_crown_envelope_block(const StandSnapshot& snapshot);

// One capped eight-sided cone per tree from its crown base to its top, of its crown radius (vtkConeSource).
// Cell data: the tree attributes. Trees without a crown (height or crown radius 0) have none.
vtkSmartPointer<vtkPolyData> build_crown_cone_block(const StandSnapshot& snapshot);

}  // namespace heliostand
