#include "io/vtk_stand_blocks.hpp"

#include "io/tree_cell_data.hpp"
#include "io/vtk_crown_blocks.hpp"
#include "io/vtk_foliage_block.hpp"
#include "io/vtk_named_array.hpp"

#include <limits>
#include <string_view>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>

namespace heliostand {
namespace {

void add_point(vtkPoints& points, const glm::dvec3& p) { points.InsertNextPoint(p.x, p.y, p.z); }

// Point clouds get one vertex cell per point so they show without a Glyph filter.
vtkSmartPointer<vtkCellArray> one_vertex_per_point(vtkIdType count) {
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  for (vtkIdType i = 0; i < count; ++i) vertices->InsertNextCell(1, &i);
  return vertices;
}

void add_field_value(vtkFieldData& fields, std::string_view name, double value) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(std::string(name).c_str());
  array->InsertNextValue(value);
  fields.AddArray(array);
}

void stamp_time(vtkDataObject& object, const StandSnapshot& snapshot) {
  if (object.GetFieldData() == nullptr) object.SetFieldData(vtkSmartPointer<vtkFieldData>::New());
  add_field_value(*object.GetFieldData(), "TimeValue", snapshot.stand_age);
  add_field_value(*object.GetFieldData(), "year_index", snapshot.year_index);
}

}  // namespace

vtkSmartPointer<vtkPolyData> build_branches_block(const StandSnapshot& snapshot) {
  vtkIdType shoot_count = 0;
  for (const TreeSnapshot& tree : snapshot.trees) shoot_count += static_cast<vtkIdType>(tree.shoots.size());

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->Allocate(2 * shoot_count);
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto radius = named_array<vtkDoubleArray>("radius", 2 * shoot_count);
  auto tree_id = named_array<vtkIntArray>("tree_id", shoot_count);
  auto order = named_array<vtkIntArray>("order", shoot_count);
  auto axis = named_array<vtkIntArray>("axis", shoot_count);
  auto year_formed = named_array<vtkIntArray>("year_formed", shoot_count);
  auto alive = named_array<vtkIntArray>("alive", shoot_count);

  for (const TreeSnapshot& tree : snapshot.trees) {
    for (const Shoot& shoot : tree.shoots) {
      const vtkIdType base = points->GetNumberOfPoints();
      add_point(*points, shoot.base);
      add_point(*points, shoot.tip);
      radius->InsertNextValue(shoot.base_radius_m);
      radius->InsertNextValue(shoot.tip_radius_m);
      const vtkIdType line[2] = {base, base + 1};
      lines->InsertNextCell(2, line);
      tree_id->InsertNextValue(tree.id);
      order->InsertNextValue(shoot.order);
      axis->InsertNextValue(shoot.axis);
      year_formed->InsertNextValue(shoot.year_formed);
      alive->InsertNextValue(shoot.alive ? 1 : 0);
    }
  }

  auto block = vtkSmartPointer<vtkPolyData>::New();
  block->SetPoints(points);
  block->SetLines(lines);
  block->GetPointData()->AddArray(radius);
  block->GetPointData()->SetActiveScalars("radius");  // what the Tube filter varies by
  for (auto* array : {tree_id.Get(), order.Get(), axis.Get(), year_formed.Get(), alive.Get()}) {
    block->GetCellData()->AddArray(array);
  }
  return block;
}

vtkSmartPointer<vtkPolyData> build_leaf_balls_block(const StandSnapshot& snapshot) {
  vtkIdType ball_count = 0;
  for (const TreeSnapshot& tree : snapshot.trees) ball_count += static_cast<vtkIdType>(tree.leaf_balls.size());

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->Allocate(ball_count);
  auto radius = named_array<vtkDoubleArray>("radius", ball_count);
  auto light = named_array<vtkDoubleArray>("light", ball_count);
  auto relative_light = named_array<vtkDoubleArray>("relative_light", ball_count);
  auto tree_id = named_array<vtkIntArray>("tree_id", ball_count);

  constexpr double unknown = std::numeric_limits<double>::quiet_NaN();
  for (const TreeSnapshot& tree : snapshot.trees) {
    const bool has_light = tree.leaf_ball_light.size() == tree.leaf_balls.size();
    const bool has_relative = tree.leaf_ball_relative_light.size() == tree.leaf_balls.size();
    for (std::size_t i = 0; i < tree.leaf_balls.size(); ++i) {
      add_point(*points, tree.leaf_balls[i].centre);
      radius->InsertNextValue(tree.leaf_balls[i].radius);
      light->InsertNextValue(has_light ? tree.leaf_ball_light[i] : unknown);
      relative_light->InsertNextValue(has_relative ? tree.leaf_ball_relative_light[i] : unknown);
      tree_id->InsertNextValue(tree.id);
    }
  }

  auto block = vtkSmartPointer<vtkPolyData>::New();
  block->SetPoints(points);
  block->SetVerts(one_vertex_per_point(ball_count));
  block->GetPointData()->AddArray(radius);
  block->GetPointData()->AddArray(light);
  block->GetPointData()->AddArray(relative_light);
  block->GetPointData()->AddArray(tree_id);
  return block;
}

vtkSmartPointer<vtkPolyData> build_trees_block(const StandSnapshot& snapshot) {
  const auto tree_count = static_cast<vtkIdType>(snapshot.trees.size());
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->Allocate(tree_count);
  auto tree_id = named_array<vtkIntArray>("tree_id", tree_count);
  auto status = named_array<vtkIntArray>("status", tree_count);
  auto hollow_count = named_array<vtkIntArray>("hollow_count", tree_count);
  auto habitat_tree = named_array<vtkIntArray>("habitat_tree", tree_count);
  auto label = vtkSmartPointer<vtkStringArray>::New();
  label->SetName("label");
  struct Measure {
    const char* name;
    double TreeSnapshot::*field;
  };
  const Measure measures[] = {
      {"age_years", &TreeSnapshot::age_years},       {"height_m", &TreeSnapshot::height_m},
      {"dbh_cm", &TreeSnapshot::dbh_cm},             {"crown_base_m", &TreeSnapshot::crown_base_m},
      {"crown_radius_m", &TreeSnapshot::crown_radius_m}, {"volume_m3", &TreeSnapshot::volume_m3},
      {"mean_light", &TreeSnapshot::mean_light},     {"light_budget", &TreeSnapshot::light_budget},
      {"relative_light", &TreeSnapshot::relative_light}, {"dbh_increment_cm", &TreeSnapshot::dbh_increment_cm},
  };
  std::vector<vtkSmartPointer<vtkDoubleArray>> measure_arrays;
  for (const Measure& m : measures) measure_arrays.push_back(named_array<vtkDoubleArray>(m.name, tree_count));

  for (const TreeSnapshot& tree : snapshot.trees) {
    add_point(*points, tree.position);
    tree_id->InsertNextValue(tree.id);
    status->InsertNextValue(status_code(tree.status));
    hollow_count->InsertNextValue(tree.hollow_count);
    habitat_tree->InsertNextValue(tree.hollow_count > 0 ? 1 : 0);
    label->InsertNextValue(tree.label);
    for (std::size_t m = 0; m < std::size(measures); ++m) measure_arrays[m]->InsertNextValue(tree.*(measures[m].field));
  }

  auto block = vtkSmartPointer<vtkPolyData>::New();
  block->SetPoints(points);
  block->SetVerts(one_vertex_per_point(tree_count));
  block->GetPointData()->AddArray(tree_id);
  block->GetPointData()->AddArray(label);
  block->GetPointData()->AddArray(status);
  block->GetPointData()->AddArray(hollow_count);
  block->GetPointData()->AddArray(habitat_tree);
  for (const auto& array : measure_arrays) block->GetPointData()->AddArray(array);
  return block;
}

vtkSmartPointer<vtkPolyData> build_trunk_block(const StandSnapshot& snapshot) {
  vtkIdType vertex_count = 0, triangle_count = 0;
  for (const TreeSnapshot& tree : snapshot.trees)
    if (tree.trunk) {
      vertex_count += static_cast<vtkIdType>(tree.trunk->vertices.size());
      triangle_count += static_cast<vtkIdType>(tree.trunk->triangles.size());
    }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->Allocate(vertex_count);
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->AllocateEstimate(triangle_count, 3);
  auto tree_id = named_array<vtkIntArray>("tree_id", vertex_count);
  auto part = named_array<vtkIntArray>("part", vertex_count);
  auto callus = named_array<vtkDoubleArray>("callus_thickness_m", vertex_count);
  auto shift = named_array<vtkDoubleArray>("bark_shift_m", vertex_count);
  auto lift = named_array<vtkDoubleArray>("bark_lift_m", vertex_count);

  for (const TreeSnapshot& tree : snapshot.trees) {
    if (!tree.trunk) continue;
    const hollow::HollowMesh& mesh = *tree.trunk;
    const vtkIdType first = points->GetNumberOfPoints();
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      add_point(*points, tree.position + mesh.vertices[v]);
      tree_id->InsertNextValue(tree.id);
      part->InsertNextValue(mesh.part[v]);
      callus->InsertNextValue(mesh.callus_thickness_m[v]);
      shift->InsertNextValue(mesh.bark_shift_m[v]);
      lift->InsertNextValue(mesh.bark_lift_m[v]);
    }
    for (const auto& t : mesh.triangles) {
      const vtkIdType ids[3] = {first + t[0], first + t[1], first + t[2]};
      triangles->InsertNextCell(3, ids);
    }
  }
  auto block = vtkSmartPointer<vtkPolyData>::New();
  block->SetPoints(points);
  block->SetPolys(triangles);
  for (auto array : {tree_id, part}) block->GetPointData()->AddArray(array);
  for (auto array : {callus, shift, lift}) block->GetPointData()->AddArray(array);
  return block;
}

std::vector<StandBlock> default_stand_blocks() {
  return {
      {"branches", [](const StandSnapshot& s) -> vtkSmartPointer<vtkDataObject> { return build_branches_block(s); }},
      {"leaf_balls", [](const StandSnapshot& s) -> vtkSmartPointer<vtkDataObject> { return build_leaf_balls_block(s); }},
      {"trees", [](const StandSnapshot& s) -> vtkSmartPointer<vtkDataObject> { return build_trees_block(s); }},
      {"trunk", [](const StandSnapshot& s) -> vtkSmartPointer<vtkDataObject> { return build_trunk_block(s); }},
  };
}

std::vector<StandBlock> stand_blocks(OutputDetail detail) {
  auto block = [](const char* name, vtkSmartPointer<vtkPolyData> (*build)(const StandSnapshot&)) {
    return StandBlock{name, [build](const StandSnapshot& s) -> vtkSmartPointer<vtkDataObject> { return build(s); }};
  };
  switch (detail) {
    case OutputDetail::full: {
      // The model's own view, and around each crown its envelope (issue 15: a crown a person recognises).
      std::vector<StandBlock> blocks = default_stand_blocks();
      blocks.push_back(block("crown_envelope", build_crown_envelope_block));
      blocks.push_back(block("foliage", build_foliage_block));  // needle sprays where the leaf balls are
      return blocks;
    }
    case OutputDetail::envelope:
      return {block("trees", build_trees_block), block("stem", build_stem_block),
              block("crown_envelope", build_crown_envelope_block)};
    case OutputDetail::cone: return {block("trees", build_trees_block), block("crown_cone", build_crown_cone_block)};
  }
  return default_stand_blocks();
}

vtkSmartPointer<vtkMultiBlockDataSet> build_stand_multiblock(const StandSnapshot& snapshot,
                                                             const std::vector<StandBlock>& all_blocks) {
  std::vector<const StandBlock*> blocks;
  for (const StandBlock& block : all_blocks)
    if (block.written_at(snapshot.stand_age)) blocks.push_back(&block);
  auto multiblock = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  multiblock->SetNumberOfBlocks(static_cast<unsigned>(blocks.size()));
  for (unsigned i = 0; i < blocks.size(); ++i) {
    vtkSmartPointer<vtkDataObject> block = blocks[i]->build(snapshot);
    if (auto* cells = vtkPolyData::SafeDownCast(block)) add_tree_cell_data(*cells, snapshot);
    stamp_time(*block, snapshot);
    multiblock->SetBlock(i, block);
    multiblock->GetMetaData(i)->Set(vtkCompositeDataSet::NAME(), blocks[i]->name.c_str());
  }
  stamp_time(*multiblock, snapshot);
  return multiblock;
}

}  // namespace heliostand
