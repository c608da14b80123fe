#include "io/vtk_foliage_block.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include "io/tree_cell_data.hpp"
#include "io/vtk_named_array.hpp"

namespace heliostand {
namespace {

// Why a hand-built strip and not vtkTubeFilter: the tube filter draws round tubes only, one strip per side (six
// cells a shoot, each repeating the tree's attributes) plus normals the block does not keep; a fir's foliage
// is a flat spray, and one strip around a six-sided elliptic frustum is 12 points and one cell.
constexpr int sides = 6;
// The spray narrows from the shoot base to its tip (the needles of an annual shoot and the twigs it bears are
// longest near its base), which gives a branch the saw-tooth outline of its yearly tiers.
constexpr double tip_width_fraction = 0.25;
// A horizontal shoot's spray is this thick (up and down) for its width (across); a vertical one (the leader)
// is round. Fir foliage spreads flat in two ranks; spruce would be rounder.
constexpr double flat_thickness_fraction = 0.5;

// Unit vectors across the shoot: `across` horizontal (the spray's width), `up` perpendicular to it and the axis.
struct ShootFrame {
  glm::dvec3 axis, across, up;
};

ShootFrame frame_of(const glm::dvec3& axis) {
  glm::dvec3 across = glm::cross(axis, glm::dvec3(0.0, 0.0, 1.0));
  // A vertical shoot has no horizontal side: any will do, its cross-section is round.
  across = glm::length(across) > 1e-9 ? glm::normalize(across) : glm::dvec3(1.0, 0.0, 0.0);
  return {axis, across, glm::cross(across, axis)};
}

// Relative light of the ball, 0..1: the light written for it, else its shoot's own (1 before the stand's first
// light field: the model's open-grown convention), so the colour array is never NaN.
double ball_light(const TreeSnapshot& tree, std::size_t ball, const Shoot& shoot) {
  double light = ball < tree.leaf_ball_light.size() ? tree.leaf_ball_light[ball] : shoot.light;
  if (!std::isfinite(light)) light = std::isfinite(shoot.light) ? shoot.light : 0.0;
  return std::clamp(light, 0.0, 1.0);
}

class FoliageMesh {
 public:
  FoliageMesh()
      : points_(vtkSmartPointer<vtkPoints>::New()), strips_(vtkSmartPointer<vtkCellArray>::New()),
        light_(named_array<vtkFloatArray>("light")), foliage_age_(named_array<vtkIntArray>("foliage_age")) {}

  // The frustum around `shoot`, `width` (m) its half-width at the base. False (nothing added) for a shoot of
  // no length, which has no axis to draw along.
  bool add(const Shoot& shoot, double width, double light, int foliage_age) {
    const glm::dvec3 along = shoot.tip - shoot.base;
    if (!(glm::length(along) > 1e-9)) return false;
    const ShootFrame frame = frame_of(glm::normalize(along));
    const double verticality = std::abs(frame.axis.z);
    const double thickness = width * (flat_thickness_fraction + (1.0 - flat_thickness_fraction) * verticality);
    const vtkIdType first = points_->GetNumberOfPoints();
    for (int k = 0; k < sides; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / sides;
      const glm::dvec3 spoke = frame.across * (width * std::cos(angle)) + frame.up * (thickness * std::sin(angle));
      add_point(shoot.base + spoke, light);
      add_point(shoot.tip + tip_width_fraction * spoke, light);
    }
    // Base and tip rings zipped round and closed: b0 t0 b1 t1 ... b5 t5 b0 t0.
    std::array<vtkIdType, 2 * sides + 2> strip{};
    for (int i = 0; i < 2 * sides; ++i) strip[i] = first + i;
    strip[2 * sides] = first;
    strip[2 * sides + 1] = first + 1;
    strips_->InsertNextCell(static_cast<vtkIdType>(strip.size()), strip.data());
    foliage_age_->InsertNextValue(foliage_age);
    return true;
  }

  vtkSmartPointer<vtkPolyData> polydata(const TreeCellData& cells) const {
    auto block = vtkSmartPointer<vtkPolyData>::New();
    block->SetPoints(points_);
    block->SetStrips(strips_);
    block->GetPointData()->AddArray(light_);
    block->GetPointData()->SetActiveScalars("light");
    block->GetCellData()->AddArray(foliage_age_);
    cells.attach_to(*block->GetCellData());
    return block;
  }

 private:
  void add_point(const glm::dvec3& p, double light) {
    points_->InsertNextPoint(p.x, p.y, p.z);
    light_->InsertNextValue(static_cast<float>(light));
  }

  vtkSmartPointer<vtkPoints> points_;  // single precision: millimetres at a landscape's kilometres, half the bytes
  vtkSmartPointer<vtkCellArray> strips_;
  vtkSmartPointer<vtkFloatArray> light_;
  vtkSmartPointer<vtkIntArray> foliage_age_;
};

// A dead or removed tree keeps no foliage; a ball whose shoot is not known (or has died) draws nothing.
vtkIdType add_tree(FoliageMesh& mesh, const TreeSnapshot& tree) {
  if (tree.status != TreeStatus::alive || tree.leaf_ball_shoot.size() != tree.leaf_balls.size()) return 0;
  vtkIdType pieces = 0;
  for (std::size_t i = 0; i < tree.leaf_balls.size(); ++i) {
    const int index = tree.leaf_ball_shoot[i];
    if (index < 0 || static_cast<std::size_t>(index) >= tree.shoots.size()) continue;
    const Shoot& shoot = tree.shoots[index];
    if (!shoot.alive) continue;
    const int foliage_age = static_cast<int>(std::lround(tree.age_years)) - shoot.year_formed;
    if (mesh.add(shoot, tree.leaf_balls[i].radius, ball_light(tree, i, shoot), std::max(0, foliage_age))) ++pieces;
  }
  return pieces;
}

}  // namespace

vtkSmartPointer<vtkPolyData> build_foliage_block(const StandSnapshot& snapshot) {
  FoliageMesh mesh;
  TreeCellData cells;
  for (const TreeSnapshot& tree : snapshot.trees) cells.add(tree, add_tree(mesh, tree));
  return mesh.polydata(cells);
}

}  // namespace heliostand
