// io/open_edges.hpp, which the crown envelopes' closure check (vtk_crown_blocks.cpp) and the envelope tests rely on:
// a closed surface has no open edge; a hole's rim and a fin's seam are counted.
#include "io/open_edges.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>

namespace heliostand {
namespace {

using Triangle = std::array<vtkIdType, 3>;

// The four corners of a tetrahedron and a fifth point off it, with the given triangles.
vtkSmartPointer<vtkPolyData> surface_of(const std::vector<Triangle>& triangles) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (const auto& p : {std::array{0.0, 0.0, 0.0}, std::array{1.0, 0.0, 0.0}, std::array{0.0, 1.0, 0.0},
                        std::array{0.0, 0.0, 1.0}, std::array{-1.0, -1.0, 0.0}})
    points->InsertNextPoint(p.data());
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (const Triangle& t : triangles) cells->InsertNextCell(3, t.data());
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(cells);
  return surface;
}

const std::vector<Triangle> tetrahedron = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

TEST(OpenEdges, AClosedSurfaceHasNone) { EXPECT_EQ(open_edges(*surface_of(tetrahedron)), 0); }

TEST(OpenEdges, AMissingFaceLeavesItsThreeEdgesOpen) {
  EXPECT_EQ(open_edges(*surface_of({tetrahedron.begin(), tetrahedron.end() - 1})), 3);
}

TEST(OpenEdges, AFinOnAClosedSurfaceIsASeamAndTwoOpenEdges) {
  std::vector<Triangle> finned = tetrahedron;
  finned.push_back({0, 1, 4});  // a third cell on edge 0-1, and two edges of its own on one cell each
  EXPECT_EQ(open_edges(*surface_of(finned)), 3);
}

}  // namespace
}  // namespace heliostand
