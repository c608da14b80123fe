#pragma once
// The attributes of a tree repeated on every cell drawn for it, so that a ParaView Threshold or a selection by
// tree works on every block of the yearly multiblock (issue 15: "before / after thinning" is a Threshold on
// `status`). A block only has to say which tree each cell belongs to — a cell array `tree_id`, or a point array
// `tree_id` (its cell's first point decides) — and build_stand_multiblock adds the rest to it:
//   tree_id, status (TreeStatus code), habitat_tree (1 with a hollow), light (the tree's mean leaf-ball light,
//   0..1, NaN unknown), species (index into the field array `species_names`), removal_age (stand age of its
//   death or removal, -1 while alive), removal_reason (index into the field array `removal_reasons`, 0 = none).
// A cell whose tree is not in the snapshot gets status -1 and the "none" values. Arrays: docs/formats.md.
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "records/stand_snapshot.hpp"

namespace heliostand {

// For a builder that appends trees' cells one tree at a time: collects the cell array `tree_id`, which is all a
// builder has to say; add_tree_cell_data writes the attributes from it, once, for every block alike.
class TreeCellData {
 public:
  TreeCellData();
  // Appends `cell_count` cells drawn for `tree`.
  void add(const TreeSnapshot& tree, vtkIdType cell_count);
  void attach_to(vtkCellData& cells) const;

 private:
  vtkSmartPointer<vtkIntArray> tree_id_;
};

// Status of a cell whose tree_id names no tree of the snapshot.
inline constexpr int unknown_tree_status = -1;

// Adds the tree attributes to the cells of `block` and the two name lists to its field data. A block without
// any `tree_id` array (the soil grid) is left as it is. Returns whether it added them.
bool add_tree_cell_data(vtkPolyData& block, const StandSnapshot& snapshot);

}  // namespace heliostand
