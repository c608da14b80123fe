#include "io/vtk_crown_blocks.hpp"

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <spdlog/spdlog.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkConeSource.h>
#include <vtkDoubleArray.h>
#include <vtkHull.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include "core/parallel_for.hpp"
#include "geometry/convex_hull.hpp"
#include "io/open_edges.hpp"
#include "io/tree_cell_data.hpp"
#include "io/vtk_named_array.hpp"

namespace heliostand {
namespace {

// vtkHull's plane directions: the vertices of an octahedron subdivided twice (level 0: 6, 1: 18, 2: 66), round
// enough for a crown at a few dozen polygons a tree.
constexpr int hull_sphere_levels = 2;
constexpr int cone_sides = 8;

// The leaf balls a crown is drawn around: the living foliage, or for a tree gone since the previous output year
// the crown it had when it went (so the year shows the stand before its thinning).
const std::vector<LeafBall>& crown_balls(const TreeSnapshot& tree) {
  return tree.leaf_balls.empty() ? tree.crown_when_gone : tree.leaf_balls;
}

// Points of a tree's foliage: each leaf ball's six extreme points, so the hull encloses the balls, not only
// their centres.
vtkSmartPointer<vtkPolyData> foliage_extremes(const TreeSnapshot& tree) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (const LeafBall& ball : crown_balls(tree))
    for (int axis = 0; axis < 3; ++axis)
      for (double side : {-1.0, 1.0}) {
        glm::dvec3 p = ball.centre;
        p[axis] += side * ball.radius;
        points->InsertNextPoint(p.x, p.y, p.z);
      }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  return cloud;
}

// The light at each corner of a crown envelope: that of the leaf ball whose surface is nearest (every corner is an
// extreme point of some ball), so the envelope shows a lit top and a shaded base, not one mean colour. NaN when the
// tree has no light values (a tree gone since the previous output year).
vtkSmartPointer<vtkDoubleArray> light_at_corners(const TreeSnapshot& tree, vtkPolyData& envelope) {
  const std::vector<LeafBall>& balls = crown_balls(tree);
  const bool lit = tree.leaf_ball_light.size() == balls.size();
  auto light = named_array<vtkDoubleArray>("light", envelope.GetNumberOfPoints());
  for (vtkIdType p = 0; p < envelope.GetNumberOfPoints(); ++p) {
    double corner[3];
    envelope.GetPoint(p, corner);
    const glm::dvec3 at(corner[0], corner[1], corner[2]);
    std::size_t nearest = 0;
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < balls.size(); ++b) {
      const double d = glm::length(at - balls[b].centre) - balls[b].radius;
      if (d < gap) gap = d, nearest = b;
    }
    light->InsertNextValue(lit ? tree.leaf_ball_light[nearest] : std::numeric_limits<double>::quiet_NaN());
  }
  return light;
}

// The corners of vtkHull's polytope (a few dozen, repeated where its polygons meet) as a closed triangle mesh.
// vtkHull's own polygons meet at T-junctions and do not share corners, so the surface is their convex hull again,
// triangulated by Qhull (geometry/convex_hull.hpp). vtkDelaunay3D did this before and left holes in a few crowns
// whose symmetric whorls put corners nearly on one sphere (docs/performance.md, "The crown envelopes by Qhull").
vtkSmartPointer<vtkPolyData> closed_surface(vtkPoints& corners) {
  std::vector<glm::dvec3> points(static_cast<std::size_t>(corners.GetNumberOfPoints()));
  for (std::size_t p = 0; p < points.size(); ++p) corners.GetPoint(static_cast<vtkIdType>(p), &points[p].x);
  const ConvexHull hull = convex_hull(points);
  auto surface_points = vtkSmartPointer<vtkPoints>::New();
  surface_points->SetDataTypeToDouble();
  surface_points->SetNumberOfPoints(static_cast<vtkIdType>(hull.corners.size()));
  for (std::size_t c = 0; c < hull.corners.size(); ++c)
    surface_points->SetPoint(static_cast<vtkIdType>(c), hull.corners[c].x, hull.corners[c].y, hull.corners[c].z);
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->AllocateExact(static_cast<vtkIdType>(hull.triangles.size()), 3 * hull.triangles.size());
  for (const std::array<int, 3>& t : hull.triangles) triangles->InsertNextCell({t[0], t[1], t[2]});
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(surface_points);
  surface->SetPolys(triangles);
  return surface;
}

vtkSmartPointer<vtkPolyData> crown_envelope(const TreeSnapshot& tree, int stand_age) {
  auto hull = vtkSmartPointer<vtkHull>::New();
  hull->SetInputData(foliage_extremes(tree));
  hull->AddRecursiveSpherePlanes(hull_sphere_levels);
  hull->Update();
  vtkSmartPointer<vtkPolyData> envelope;
  try {
    envelope = closed_surface(*hull->GetOutput()->GetPoints());
  } catch (const FlatPointSet& flat) {  // leaf balls have a radius, so their extremes always span a volume
    spdlog::warn("VTK output, age {}: tree '{}' has no crown envelope ({})", stand_age, tree.label, flat.what());
    return nullptr;
  }
  if (const vtkIdType open = open_edges(*envelope); open > 0)
    spdlog::warn("VTK output, age {}: the crown envelope of tree '{}' is not a closed surface ({} open edges)",
                 stand_age, tree.label, open);
  envelope->GetPointData()->AddArray(light_at_corners(tree, *envelope));
  return envelope;
}

vtkSmartPointer<vtkPolyData> crown_cone(const TreeSnapshot& tree) {
  const double length = tree.height_m - tree.crown_base_m;
  auto cone = vtkSmartPointer<vtkConeSource>::New();
  cone->SetResolution(cone_sides);
  cone->SetHeight(length);
  cone->SetRadius(tree.crown_radius_m);
  cone->SetDirection(0, 0, 1);  // apex up
  cone->SetCenter(tree.position.x, tree.position.y, tree.position.z + tree.crown_base_m + 0.5 * length);
  cone->CappingOn();
  cone->Update();
  return cone->GetOutput();
}

// One polydata from the trees' pieces, each piece's cells carrying its tree's attributes. The pieces are made on the
// worker threads (core/parallel_for.hpp), each tree's with VTK objects of its own, and appended in the trees' order,
// so the block is the same for any number of threads: the crown envelopes were most of a hectare's output year
// (docs/performance.md, "The crown envelopes on the worker threads").
template <typename PieceOf>
vtkSmartPointer<vtkPolyData> append_per_tree(const StandSnapshot& snapshot, PieceOf piece_of) {
  std::vector<vtkSmartPointer<vtkPolyData>> pieces(snapshot.trees.size());
  parallel_for(pieces.size(), [&](std::size_t t) { pieces[t] = piece_of(snapshot.trees[t]); });
  auto append = vtkSmartPointer<vtkAppendPolyData>::New();
  TreeCellData cells;
  for (std::size_t t = 0; t < pieces.size(); ++t) {
    const vtkSmartPointer<vtkPolyData>& piece = pieces[t];
    if (!piece || piece->GetNumberOfCells() == 0) continue;
    append->AddInputData(piece);
    cells.add(snapshot.trees[t], piece->GetNumberOfCells());
  }
  auto block = vtkSmartPointer<vtkPolyData>::New();
  if (append->GetNumberOfInputConnections(0) == 0) return block;
  append->Update();
  block->ShallowCopy(append->GetOutput());
  vtkSmartPointer<vtkDataArray> light = block->GetPointData()->GetArray("light");  // the envelope's, per corner
  block->GetPointData()->Initialize();  // the sources' normals and texture coordinates are not ours
  if (light) block->GetPointData()->AddArray(light);
  block->GetCellData()->Initialize();
  cells.attach_to(*block->GetCellData());
  return block;
}

}  // namespace

vtkSmartPointer<vtkPolyData> build_stem_block(const StandSnapshot& snapshot) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto radius = vtkSmartPointer<vtkDoubleArray>::New();
  radius->SetName("radius");
  TreeCellData cells;
  for (const TreeSnapshot& tree : snapshot.trees) {
    vtkIdType stem_shoots = 0;
    for (const Shoot& shoot : tree.shoots) {
      if (shoot.axis != 0) continue;
      const vtkIdType base = points->InsertNextPoint(shoot.base.x, shoot.base.y, shoot.base.z);
      points->InsertNextPoint(shoot.tip.x, shoot.tip.y, shoot.tip.z);
      radius->InsertNextValue(shoot.base_radius_m);
      radius->InsertNextValue(shoot.tip_radius_m);
      const vtkIdType line[2] = {base, base + 1};
      lines->InsertNextCell(2, line);
      ++stem_shoots;
    }
    cells.add(tree, stem_shoots);
  }
  auto block = vtkSmartPointer<vtkPolyData>::New();
  block->SetPoints(points);
  block->SetLines(lines);
  block->GetPointData()->AddArray(radius);
  block->GetPointData()->SetActiveScalars("radius");
  cells.attach_to(*block->GetCellData());
  return block;
}

vtkSmartPointer<vtkPolyData> build_crown_envelope_block(const StandSnapshot& snapshot) {
  return append_per_tree(snapshot, [&](const TreeSnapshot& tree) -> vtkSmartPointer<vtkPolyData> {
    if (crown_balls(tree).empty()) return nullptr;
    return crown_envelope(tree, snapshot.stand_age);
  });
}

vtkSmartPointer<vtkPolyData> build_crown_cone_block(const StandSnapshot& snapshot) {
  return append_per_tree(snapshot, [](const TreeSnapshot& tree) -> vtkSmartPointer<vtkPolyData> {
    if (!(tree.height_m > tree.crown_base_m) || !(tree.crown_radius_m > 0)) return nullptr;
    return crown_cone(tree);
  });
}

}  // namespace heliostand
