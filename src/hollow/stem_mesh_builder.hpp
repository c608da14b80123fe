#pragma once
// Building blocks shared by the hollow meshes: the stem grid's rows and columns, a mesh under construction
// that remembers where each vertex lies in the stem chart, the zip that joins two chains of vertices, the
// bark lift around a wound and the subdivision that makes faces follow the stem's convexity.
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "hollow/callus.hpp"
#include "hollow/hollow_mesh.hpp"
#include "hollow/stem_chart.hpp"
#include "hollow/trunk_surface.hpp"

namespace heliostand::hollow::detail {

// Largest angular step whose chord stays within `tolerance` of a circle of radius rho.
double angular_step(double rho, double tolerance);
double max_stem_radius(const TrunkSurface& trunk);

// Stem rows (heights): every `patch_step` inside [lo, hi], coarser elsewhere (finer near a flaring collar),
// plus the given extra heights; up to `top` (default: just below the tip, which is closed by an apex vertex).
std::vector<double> stem_heights(const TrunkSurface& trunk, double lo, double hi, double patch_step,
                                 const std::vector<double>& extra, double top = -1.0);

// Mesh under construction, with the chart position of every vertex that lies on (or is lifted off) the stem.
struct Builder {
  HollowMesh mesh;
  std::vector<glm::dvec2> chart_xy;
  std::vector<bool> on_chart;
  std::vector<bool> frozen;  // edges between two frozen vertices are shared with unrefined faces: never split
  std::vector<bool> refinable_triangle;

  int add(const glm::dvec3& p, MeshPart part, bool chart, glm::dvec2 xy = {}, double shift = 0.0,
          double lift = 0.0, int line = -1, double thickness = 0.0) {
    mesh.vertices.push_back(p);
    mesh.part.push_back(static_cast<int>(part));
    mesh.callus_thickness_m.push_back(thickness);
    mesh.bark_shift_m.push_back(shift);
    mesh.bark_lift_m.push_back(lift);
    mesh.bark_line.push_back(line);
    chart_xy.push_back(xy);
    on_chart.push_back(chart);
    frozen.push_back(false);
    return static_cast<int>(mesh.vertices.size()) - 1;
  }
  void triangle(int a, int b, int c, bool refinable) {
    mesh.triangles.push_back({a, b, c});
    refinable_triangle.push_back(refinable);
  }
};

// Quads between neighbouring grid vertices (grid[column][row], columns periodic around the stem), two
// triangles each, counter-clockwise seen from outside; quads touching a missing vertex (−1) are left out.
void add_grid_quads(Builder& b, const std::vector<std::vector<int>>& grid);
// Closes the stem at its tip: a fan from the top row to an apex vertex (the top row is frozen).
void close_tip(Builder& b, const std::vector<std::vector<int>>& grid, double tree_height);

// The roll: two triangles per corner step between consecutive polygons, from the foot over the top into the
// wound.
void add_roll(Builder& b, const Callus& callus, const std::vector<std::vector<int>>& corner);

// Joins two chains that both run upwards (left chain on the left) with triangles, merging by height.
void zip(Builder& b, const std::vector<int>& left, const std::vector<int>& right);

// Everything the lift and the patch tests need about the hollow's surroundings.
struct Surroundings {
  const StemChart* chart;
  double patch_x, patch_up, patch_down;
  double callus_radius;
  const std::vector<glm::dvec2>* outline;
  std::vector<double> mean_radius;
  bool full_round = false;  // the patch is a band all around the stem (no fade towards its sides)

  double wrapped(double x) const { return std::remainder(x, 2.0 * chart->half_round()); }
  bool in_patch(glm::dvec2 xy) const {
    return (full_round || std::abs(wrapped(xy.x)) <= patch_x + 1e-9) && xy.y >= -patch_down - 1e-9 &&
           xy.y <= patch_up + 1e-9;
  }
  // Eq. 3.18 with a window that brings the rise to zero at the patch border, where the bark meets the stem.
  double lift(glm::dvec2 xy) const;
};

// The callus corners as mesh vertices (corner[j][m]); corner 0, the foot, is placed in the chart and lifted
// with the bark it joins.
std::vector<std::vector<int>> add_callus_corners(Builder& b, const Callus& callus, const StemChart& chart,
                                                 const Surroundings& around);

// Splits stem/bark edges whose midpoint is further than `tolerance` from the (lifted) surface, so that faces
// follow the stem's convexity; the split decision is per edge, so neighbouring faces stay conforming.
// Returns the number of passes that split at least one edge.
int follow_convexity(Builder& b, const Surroundings& around, double tolerance);

// A height range of the stem that one mesh piece covers (several hollows on one stem: one band each, joined
// by ring zips). The default band is the whole stem, closed at the tip.
struct StemBand {
  double lo = 0.0;
  double hi = std::numeric_limits<double>::infinity();
  bool reaches_tip() const { return std::isinf(hi); }
};

// Heights the hollow's bark patch can occupy at most (it is sized from the callus foot, known only once the
// callus is built; this bound uses the foot's largest possible reach).
struct PatchBounds {
  double lo, hi;
};
PatchBounds patch_bounds(const HollowSpec& spec, const TrunkSurface& trunk);

// build_hollow() restricted to a band: rows only within [lo, hi] (both edges are rows), the tip closed only if
// the band reaches it. The band must hold patch_bounds(). No hollow: build_trunk_mesh().
HollowModel build_hollow_band(const HollowSpec& spec, const TrunkSurface& trunk, BuildOptions options,
                              const StemBand& band);

}  // namespace heliostand::hollow::detail
