#pragma once
// The attributes of a tree repeated on every cell drawn for it, so that a ParaView Threshold or a selection
// by tree works on every block: tree_id, status (TreeStatus code), habitat_tree (1 when it carries a hollow)
// and light (the tree's mean leaf-ball light, 0..1; NaN when unknown).
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkSmartPointer.h>

#include "io/stand_snapshot.hpp"

namespace heliostand {

class TreeCellData {
 public:
  TreeCellData();
  // Appends `cell_count` cells' worth of the tree's attributes.
  void add(const TreeSnapshot& tree, vtkIdType cell_count);
  void attach_to(vtkCellData& cells) const;

 private:
  vtkSmartPointer<vtkIntArray> tree_id_, status_, habitat_tree_;
  vtkSmartPointer<vtkDoubleArray> light_;
};

}  // namespace heliostand
