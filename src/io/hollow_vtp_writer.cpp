#include "io/hollow_vtp_writer.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include "io/vtk_named_array.hpp"
#include "io/vtk_write_check.hpp"

namespace heliostand::hollow {

namespace {
template <class Array, class T>
void add_array(vtkPolyData* poly, const char* name, const std::vector<T>& values) {
  auto array = sized_named_array<Array>(name, static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) array->SetValue(static_cast<vtkIdType>(i), values[i]);
  poly->GetPointData()->AddArray(array);
}
}  // namespace

void write_vtp(const HollowMesh& mesh, const std::string& path) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& v : mesh.vertices) points->InsertNextPoint(v.x, v.y, v.z);
  vtkNew<vtkCellArray> polys;
  for (const auto& t : mesh.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(polys);
  add_array<vtkIntArray>(poly, "part", mesh.part);
  add_array<vtkDoubleArray>(poly, "callus_thickness_m", mesh.callus_thickness_m);
  add_array<vtkDoubleArray>(poly, "bark_shift_m", mesh.bark_shift_m);
  add_array<vtkDoubleArray>(poly, "bark_lift_m", mesh.bark_lift_m);
  add_array<vtkIntArray>(poly, "bark_line", mesh.bark_line);

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(poly);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  write_checked(*writer, path);
}

}  // namespace heliostand::hollow
