#include "io/tree_cell_data.hpp"

#include "io/vtk_named_array.hpp"

namespace heliostand {

TreeCellData::TreeCellData()
    : tree_id_(named_array<vtkIntArray>("tree_id")),
      status_(named_array<vtkIntArray>("status")),
      habitat_tree_(named_array<vtkIntArray>("habitat_tree")),
      light_(named_array<vtkDoubleArray>("light")) {}

void TreeCellData::add(const TreeSnapshot& tree, vtkIdType cell_count) {
  for (vtkIdType i = 0; i < cell_count; ++i) {
    tree_id_->InsertNextValue(tree.id);
    status_->InsertNextValue(status_code(tree.status));
    habitat_tree_->InsertNextValue(tree.hollow_count > 0 ? 1 : 0);
    light_->InsertNextValue(tree.mean_light);
  }
}

void TreeCellData::attach_to(vtkCellData& cells) const {
  cells.AddArray(tree_id_);
  cells.AddArray(status_);
  cells.AddArray(habitat_tree_);
  cells.AddArray(light_);
}

}  // namespace heliostand
