#include "io/tree_cell_data.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>

#include "io/vtk_named_array.hpp"

namespace heliostand {
namespace {

// Text attributes as small integers (Threshold and colouring need numbers) with their names in the block's field
// data: code k is names[k].
class Categories {
 public:
  explicit Categories(std::set<std::string> names) : names_(names.begin(), names.end()) {}
  int code_of(const std::string& name) const {
    return static_cast<int>(std::lower_bound(names_.begin(), names_.end(), name) - names_.begin());
  }
  vtkSmartPointer<vtkStringArray> as_field(const char* name) const {
    auto array = vtkSmartPointer<vtkStringArray>::New();
    array->SetName(name);
    for (const std::string& n : names_) array->InsertNextValue(n);
    return array;
  }

 private:
  std::vector<std::string> names_;  // sorted
};

// The tree each cell is drawn for: its cell `tree_id`, else its first point's. Empty when the block has neither.
std::vector<int> tree_of_each_cell(vtkPolyData& block) {
  std::vector<int> trees;
  if (vtkDataArray* ids = block.GetCellData()->GetArray("tree_id")) {
    for (vtkIdType c = 0; c < block.GetNumberOfCells(); ++c) trees.push_back(static_cast<int>(ids->GetTuple1(c)));
    return trees;
  }
  vtkDataArray* ids = block.GetPointData()->GetArray("tree_id");
  if (ids == nullptr) return trees;
  auto corners = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < block.GetNumberOfCells(); ++c) {
    block.GetCellPoints(c, corners);
    trees.push_back(corners->GetNumberOfIds() > 0 ? static_cast<int>(ids->GetTuple1(corners->GetId(0))) : -1);
  }
  return trees;
}

}  // namespace

TreeCellData::TreeCellData() : tree_id_(named_array<vtkIntArray>("tree_id")) {}

void TreeCellData::add(const TreeSnapshot& tree, vtkIdType cell_count) {
  for (vtkIdType i = 0; i < cell_count; ++i) tree_id_->InsertNextValue(tree.id);
}

void TreeCellData::attach_to(vtkCellData& cells) const { cells.AddArray(tree_id_); }

bool add_tree_cell_data(vtkPolyData& block, const StandSnapshot& snapshot) {
  const std::vector<int> trees = tree_of_each_cell(block);
  if (trees.empty()) return false;

  std::map<int, const TreeSnapshot*> by_id;
  std::set<std::string> species, reasons{""};  // reason code 0: none
  for (const TreeSnapshot& tree : snapshot.trees) {
    by_id[tree.id] = &tree;
    species.insert(tree.species);
    reasons.insert(tree.status_reason);
  }
  const Categories species_names(species), removal_reasons(reasons);

  const auto cells = static_cast<vtkIdType>(trees.size());
  auto tree_id = named_array<vtkIntArray>("tree_id", cells);
  auto status = named_array<vtkIntArray>("status", cells);
  auto habitat_tree = named_array<vtkIntArray>("habitat_tree", cells);
  auto light = named_array<vtkDoubleArray>("light", cells);
  auto species_code = named_array<vtkIntArray>("species", cells);
  auto removal_age = named_array<vtkIntArray>("removal_age", cells);
  auto removal_reason = named_array<vtkIntArray>("removal_reason", cells);
  for (const int id : trees) {
    const auto found = by_id.find(id);
    const TreeSnapshot* tree = found == by_id.end() ? nullptr : found->second;
    tree_id->InsertNextValue(id);
    status->InsertNextValue(tree ? status_code(tree->status) : unknown_tree_status);
    habitat_tree->InsertNextValue(tree && tree->hollow_count > 0 ? 1 : 0);
    light->InsertNextValue(tree ? tree->mean_light : std::numeric_limits<double>::quiet_NaN());
    species_code->InsertNextValue(tree ? species_names.code_of(tree->species) : -1);
    removal_age->InsertNextValue(tree ? tree->gone_at_age : -1);
    removal_reason->InsertNextValue(tree ? removal_reasons.code_of(tree->status_reason) : 0);
  }
  vtkCellData& data = *block.GetCellData();
  const vtkSmartPointer<vtkDataArray> arrays[] = {tree_id,      status,      habitat_tree,  light,
                                                  species_code, removal_age, removal_reason};
  for (const auto& array : arrays) {
    data.RemoveArray(array->GetName());  // a builder's tree_id (TreeCellData), replaced by the same values
    data.AddArray(array);
  }
  if (block.GetFieldData() == nullptr) block.SetFieldData(vtkSmartPointer<vtkFieldData>::New());
  block.GetFieldData()->AddArray(species_names.as_field("species_names"));
  block.GetFieldData()->AddArray(removal_reasons.as_field("removal_reasons"));
  return true;
}

}  // namespace heliostand
