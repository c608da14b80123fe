#pragma once
// A hollow on a stem, as one triangle mesh: the stem surface (grid in the stem chart), the bark patch in it
// whose lines flow around the wound, the strips that join the bark to the callus foot, and the callus roll.
// The cavity inside the outline is left open (out of the seed's scope).
//
// Integration: validate(spec, trunk) first (reports name the HollowSpec field), then build_hollow().
#include <array>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "hollow/callus.hpp"
#include "hollow/hollow_spec.hpp"
#include "hollow/trunk_surface.hpp"

namespace heliostand::hollow {

enum class MeshPart : int { trunk = 0, bark = 1, callus = 2 };

struct HollowMesh {
  std::vector<glm::dvec3> vertices;          // m, tree frame (stem base at the origin, z up)
  std::vector<std::array<int, 3>> triangles; // counter-clockwise seen from outside the wood
  // Per-vertex data (same length as vertices):
  std::vector<int> part;                     // MeshPart
  std::vector<double> callus_thickness_m;    // corner radius R_m on the callus, 0 elsewhere
  std::vector<double> bark_shift_m;          // sideways displacement of the bark line (along the circumference)
  std::vector<double> bark_lift_m;           // eq. 3.18 rise of the bark off the stem surface
  std::vector<int> bark_line;                // stem-grid column (bark line index), −1 on the callus
};

// The bark lines as the seed draws them: original position x (chart) and displaced X per row height y.
struct BarkLines {
  std::vector<double> x;                  // column positions, chart x (patch columns only)
  std::vector<double> y;                  // row heights, chart y (rows inside the patch)
  std::vector<std::vector<double>> X;     // X[column][row]; NaN where the split line is cut by the wound
  int split_column = 0;                   // the line through the wound's top vertex (x = 0)
  double spacing = 0.0;                   // effective l
};

struct HollowModel {
  HollowMesh mesh;
  Callus callus;
  std::vector<glm::dvec2> outline_xy;   // V_j in chart coordinates
  BarkLines bark;
  double patch_half_width = 0.0;        // P (chart x)
  double chart_radius = 0.0;            // ρ0
  int refinement_passes = 0;            // convexity subdivision passes that split at least one edge
};

struct BuildOptions {
  bool follow_convexity = true;  // subdivide stem/bark faces until within surface_tolerance_m (off: seed)
  bool limit_callus = true;      // keep callus polygons from crossing (off: seed)
};

// Throws InputError (field kind "field") when validate() reports problems.
HollowModel build_hollow(const HollowSpec& spec, const TrunkSurface& trunk, BuildOptions options = {});

// A plain stem without a hollow, same grid rules (for trees without hollows in the stand output).
HollowMesh build_trunk_mesh(const TrunkSurface& trunk, double tolerance_m = 0.0005);

// Several hollows on one stem are stacked in height: each hollow's bark patch (patch_bounds in
// stem_mesh_builder.hpp) gets a band of the stem of its own, and neighbouring bands are joined by a strip of
// plain stem at least this tall. Side by side at one height is not supported.
inline constexpr double min_hollow_gap_m = 0.02;

// A problem of one hollow among several: its index in the list, and the problem as validate() states it
// (field = the HollowSpec member, no prefix).
struct HollowProblem {
  std::size_t hollow = 0;
  InputProblem problem;
};

// Each hollow's own problems (validate()), and a problem on "height_m" of every hollow whose bark patch comes
// within min_hollow_gap_m of another's; the reason names that other hollow as `name_of(its index)` and gives
// the centre distance needed. Callers name the hollows as their user wrote them. Empty when the stem can be built.
std::vector<HollowProblem> hollow_problems(const std::vector<HollowSpec>& hollows, const TrunkSurface& trunk,
                                           const std::function<std::string(std::size_t)>& name_of);

// hollow_problems() with the hollows named "hollows[i]" and each field prefixed "hollows[i].".
std::vector<InputProblem> validate_hollows(const std::vector<HollowSpec>& hollows, const TrunkSurface& trunk);

// One manifold mesh of the stem with all its hollows (in any order): none → build_trunk_mesh(trunk); one →
// build_hollow(spec, trunk).mesh; several → a band per hollow (sorted by height) built like build_hollow,
// joined by zipping the rings that face each other across each gap. Borders: the base ring and each cavity
// lip. Throws InputError (field kind "field") with validate_hollows()'s problems.
HollowMesh build_stem_with_hollows(const std::vector<HollowSpec>& hollows, const TrunkSurface& trunk);

}  // namespace heliostand::hollow
