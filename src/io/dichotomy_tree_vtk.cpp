#include "io/dichotomy_tree_vtk.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include "io/output_folder.hpp"
#include "io/vtk_write_check.hpp"

namespace heliostand {

namespace {

// Living tips carried by every branch (itself, if it is a tip): children always come after their parent in
// the branch list, so one pass from the end adds each branch's count to its parent.
std::vector<int> tips_carried(const DichotomyTree& tree) {
  const auto& branches = tree.branches();
  std::vector<int> carried(branches.size(), 0);
  for (std::size_t i = branches.size(); i-- > 0;) {
    const DichotomyBranch& b = branches[i];
    if (!b.alive) continue;
    if (b.children == 0) carried[i] += 1;
    if (b.parent >= 0) carried[static_cast<std::size_t>(b.parent)] += carried[i];
  }
  return carried;
}

// Under a temporary name, renamed into place once VTK has written it whole (io/vtk_write_check.hpp): a crown that
// cannot be written is an error naming it, never a truncated file under its name.
void write_polydata(vtkPolyData* data, const std::filesystem::path& path) {
  AtomicFile file(path);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(file.temporary_path().string().c_str());
  writer->SetInputData(data);
  write_checked(*writer, path);
  file.commit();
}

}  // namespace

void write_crown_vtp(const DichotomyTree& tree, double leaf_ball_radius, const std::filesystem::path& path) {
  const std::vector<int> carried = tips_carried(tree);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> generation, group, tip;
  vtkNew<vtkDoubleArray> radius, drawn_radius;
  generation->SetName("generation");
  group->SetName("group");
  tip->SetName("is_tip");
  radius->SetName("leaf_ball_radius");
  drawn_radius->SetName("radius");
  const auto& branches = tree.branches();
  for (std::size_t i = 0; i < branches.size(); ++i) {
    const DichotomyBranch& b = branches[i];
    if (!b.alive) continue;
    const vtkIdType first = points->InsertNextPoint(b.base.x, b.base.y, b.base.z);
    points->InsertNextPoint(b.tip.x, b.tip.y, b.tip.z);
    const vtkIdType ids[2] = {first, first + 1};
    lines->InsertNextCell(2, ids);
    generation->InsertNextValue(b.generation);
    group->InsertNextValue(b.group);
    tip->InsertNextValue(b.children == 0);
    radius->InsertNextValue(b.children == 0 ? leaf_ball_radius : 0.0);
    // The model has no wood: for drawing only, the pipe model (cross-section proportional to the tips carried).
    const double r = kanamaru_tip_drawing_radius * std::sqrt(static_cast<double>(std::max(1, carried[i])));
    drawn_radius->InsertNextValue(r);
    drawn_radius->InsertNextValue(r);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetLines(lines);
  data->GetCellData()->AddArray(generation);
  data->GetCellData()->AddArray(group);
  data->GetCellData()->AddArray(tip);
  data->GetCellData()->AddArray(radius);
  data->GetPointData()->AddArray(drawn_radius);
  write_polydata(data, path);
}

void write_tips_vtp(const DichotomyTree& tree, const std::filesystem::path& path) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkIntArray> group;
  group->SetName("group");
  for (int i : tree.tips()) {
    const DichotomyBranch& b = tree.branches()[static_cast<std::size_t>(i)];
    const vtkIdType id = points->InsertNextPoint(b.tip.x, b.tip.y, b.tip.z);
    vertices->InsertNextCell(1, &id);
    group->InsertNextValue(b.group);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetVerts(vertices);
  data->GetPointData()->AddArray(group);
  write_polydata(data, path);
}

}  // namespace heliostand
