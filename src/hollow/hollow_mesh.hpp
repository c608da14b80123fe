#pragma once
// A hollow on a stem, as one triangle mesh: the stem surface (grid in the stem chart), the bark patch in it
// whose lines flow around the wound, the strips that join the bark to the callus foot, and the callus roll.
// The cavity inside the outline is left open (out of the seed's scope).
//
// Integration: validate(spec, trunk) first (reports name the HollowSpec field), then build_hollow().
#include <array>
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

}  // namespace heliostand::hollow
