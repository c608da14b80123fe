#include "io/root_vtk.hpp"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace heliostand::roots {
namespace {

TEST(RootVtk, OneLinePerSegmentWithRadiusTypeTreeAndAgeOnItsPoints) {
  const RootSystem a(4, {0.0, 0.0, 0.0}, tap_rooted_conifer(), 0);
  const RootSystem b(9, {2.0, 0.0, 0.0}, tap_rooted_conifer(), 0);
  const RootSystem* trees[] = {&a, &b};
  const auto data = root_polylines(trees);
  EXPECT_EQ(data->GetNumberOfLines(), 2);
  EXPECT_EQ(data->GetNumberOfPoints(), 4);
  double end[3];
  data->GetPoint(3, end);
  EXPECT_DOUBLE_EQ(end[0], 2.0);
  EXPECT_DOUBLE_EQ(end[2], -0.15);
  vtkPointData* points = data->GetPointData();
  EXPECT_DOUBLE_EQ(points->GetArray("radius")->GetTuple1(0), 0.02);
  EXPECT_EQ(points->GetArray("type")->GetTuple1(1), 0.0);
  EXPECT_EQ(points->GetArray("tree_id")->GetTuple1(2), 9.0);
  EXPECT_EQ(points->GetArray("age")->GetTuple1(3), 0.0);
  EXPECT_EQ(points->GetArray("path")->GetTuple1(3), -1.0);
}

TEST(RootVtk, SoilImageHasTheGridsVerticesAndValues) {
  SoilGrid soil({{-1.0, -2.0, -3.0}, 0.5, {4, 2, 6}}, 1.0, 0.5);
  soil.fill_gradient(SoilField::moisture, 0, 1.0, 0.0);
  const auto image = soil_image(soil);
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 5);
  EXPECT_EQ(dims[1], 3);
  EXPECT_EQ(dims[2], 7);
  const vtkIdType id = image->ComputePointId(std::array<int, 3>{3, 1, 2}.data());
  EXPECT_DOUBLE_EQ(image->GetPointData()->GetArray("moisture")->GetTuple1(id), 0.25);
  EXPECT_DOUBLE_EQ(image->GetPointData()->GetArray("nutrient")->GetTuple1(id), 0.5);
  double point[3];
  image->GetPoint(id, point);
  EXPECT_DOUBLE_EQ(point[0], 0.5);
  EXPECT_DOUBLE_EQ(point[2], -2.0);
}

}  // namespace
}  // namespace heliostand::roots
