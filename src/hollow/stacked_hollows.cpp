// Several hollows on one stem. Each hollow is built as build_hollow() builds it, but only over a band of the
// stem around it; the bands are stacked in height and neighbouring ones are joined across a short gap of
// plain stem by zipping the ring at the top of the lower band to the ring at the bottom of the upper one.
// The two rings have different columns (each band lays its bark lines around its own wound), so the zip
// merges them by azimuth.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

#include "geometry/angles.hpp"
#include "hollow/hollow_mesh.hpp"
#include "hollow/stem_mesh_builder.hpp"
#include "core/input_error.hpp"

namespace heliostand::hollow {

using namespace detail;

namespace {

// Indices of `hollows` in order of height (stable: at equal heights the one listed first is "below").
std::vector<int> by_height(const std::vector<HollowSpec>& hollows) {
  std::vector<int> order(hollows.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return hollows[a].height_m < hollows[b].height_m; });
  return order;
}

void append(HollowMesh& to, const HollowMesh& from) {
  const int offset = static_cast<int>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  for (const auto& t : from.triangles) to.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  to.part.insert(to.part.end(), from.part.begin(), from.part.end());
  to.callus_thickness_m.insert(to.callus_thickness_m.end(), from.callus_thickness_m.begin(), from.callus_thickness_m.end());
  to.bark_shift_m.insert(to.bark_shift_m.end(), from.bark_shift_m.begin(), from.bark_shift_m.end());
  to.bark_lift_m.insert(to.bark_lift_m.end(), from.bark_lift_m.begin(), from.bark_lift_m.end());
  to.bark_line.insert(to.bark_line.end(), from.bark_line.begin(), from.bark_line.end());
}

double azimuth(const glm::dvec3& p) { return std::atan2(p.y, p.x); }

// The open ring of a band at `height` (its bottom or top edge), in order of azimuth. Read off the mesh's
// border rather than the grid, because the convexity subdivision may have split the ring's edges.
std::vector<int> border_ring(const HollowMesh& mesh, double height) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) ++uses[{std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])}];
  std::vector<int> ring;
  // stem_heights() merges rows closer than 1e-6 m, so the edge row may sit that far from `height`; no other
  // border comes near a band's edge (lips stay inside the patch, a quarter of the clearance away).
  auto on_ring = [&](int v) { return std::abs(mesh.vertices[v].z - height) < 1e-5; };
  for (const auto& [edge, n] : uses)
    if (n == 1 && on_ring(edge.first) && on_ring(edge.second)) ring.push_back(edge.first), ring.push_back(edge.second);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  std::sort(ring.begin(), ring.end(),
            [&](int a, int b) { return azimuth(mesh.vertices[a]) < azimuth(mesh.vertices[b]); });
  if (ring.size() < 3) throw std::logic_error("hollow: a stem band has no open ring at its edge");
  return ring;
}

// Joins a lower and an upper ring (both counter-clockwise seen from above, i.e. increasing azimuth) with
// triangles, each taking the next vertex from whichever ring comes first by azimuth: one triangle per ring
// edge, counter-clockwise seen from outside, the same orientation as the grid quads beside them.
void zip_rings(HollowMesh& mesh, const std::vector<int>& lower, const std::vector<int>& upper) {
  const int nl = static_cast<int>(lower.size()), nu = static_cast<int>(upper.size());
  auto angle = [&](int v) { return azimuth(mesh.vertices[v]); };
  // Unwrapped angles: lower from its first vertex, upper from the vertex nearest to it.
  int j0 = 0;
  for (int j = 1; j < nu; ++j)
    if (std::abs(std::remainder(angle(upper[j]) - angle(lower[0]), 2 * pi)) <
        std::abs(std::remainder(angle(upper[j0]) - angle(lower[0]), 2 * pi)))
      j0 = j;
  const double a0 = angle(lower[0]);
  const double b0 = a0 + std::remainder(angle(upper[j0]) - a0, 2 * pi);
  auto positive = [](double d) { return d < 0 ? d + 2 * pi : d; };
  auto lower_at = [&](int i) { return i == nl ? a0 + 2 * pi : a0 + positive(angle(lower[i]) - angle(lower[0])); };
  auto upper_at = [&](int j) {
    return j == nu ? b0 + 2 * pi : b0 + positive(angle(upper[(j0 + j) % nu]) - angle(upper[j0]));
  };
  auto U = [&](int j) { return upper[(j0 + j) % nu]; };
  auto L = [&](int i) { return lower[i % nl]; };
  int i = 0, j = 0;
  while (i < nl || j < nu) {
    const bool advance_lower = j == nu || (i < nl && lower_at(i + 1) <= upper_at(j + 1));
    if (advance_lower) {
      mesh.triangles.push_back({L(i), L(i + 1), U(j)});
      ++i;
    } else {
      mesh.triangles.push_back({L(i), U(j + 1), U(j)});
      ++j;
    }
  }
}

}  // namespace

std::vector<HollowProblem> hollow_problems(const std::vector<HollowSpec>& hollows, const TrunkSurface& trunk,
                                           const std::function<std::string(std::size_t)>& name_of) {
  std::vector<HollowProblem> problems;
  std::vector<bool> valid(hollows.size());
  for (std::size_t i = 0; i < hollows.size(); ++i) {
    auto own = validate(hollows[i], trunk);
    valid[i] = own.empty();
    for (auto& p : own) problems.push_back({i, std::move(p)});
  }
  const std::vector<int> order = by_height(hollows);
  for (std::size_t a = 0; a < order.size(); ++a) {
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const int lo = order[a], hi = order[b];
      if (!valid[lo] || !valid[hi]) continue;
      const PatchBounds below = patch_bounds(hollows[lo], trunk), above = patch_bounds(hollows[hi], trunk);
      if (below.hi + min_hollow_gap_m <= above.lo) continue;
      const double needed = (below.hi - hollows[lo].height_m) + (hollows[hi].height_m - above.lo) + min_hollow_gap_m;
      problems.push_back(
          {static_cast<std::size_t>(hi),
           {"", 0, "height_m",
            fmt::format("its bark patch ({:.3f}–{:.3f} m) comes within {} m of the patch of {} at {} m "
                        "({:.3f}–{:.3f} m); hollows on one stem are stacked in height (side by side at one height "
                        "is not supported), so their centres must be at least {:.3f} m apart, got {:.3f} m",
                        above.lo, above.hi, min_hollow_gap_m, name_of(static_cast<std::size_t>(lo)),
                        hollows[lo].height_m, below.lo, below.hi, needed, hollows[hi].height_m - hollows[lo].height_m)}});
    }
  }
  return problems;
}

std::vector<InputProblem> validate_hollows(const std::vector<HollowSpec>& hollows, const TrunkSurface& trunk) {
  auto internal_name = [](std::size_t i) { return fmt::format("hollows[{}]", i); };
  std::vector<InputProblem> problems;
  for (auto& [i, problem] : hollow_problems(hollows, trunk, internal_name)) {
    problem.field = internal_name(i) + "." + problem.field;
    problems.push_back(std::move(problem));
  }
  return problems;
}

HollowMesh build_stem_with_hollows(const std::vector<HollowSpec>& hollows, const TrunkSurface& trunk) {
  if (auto problems = validate_hollows(hollows, trunk); !problems.empty())
    throw InputError(std::move(problems), "field");
  if (hollows.empty()) return build_trunk_mesh(trunk);
  if (hollows.size() == 1) return build_hollow(hollows[0], trunk).mesh;

  const std::vector<int> order = by_height(hollows);
  // Band edges: the gap between two patches is split in the middle; the joining strip takes at most 2 cm of
  // it (bands keep at least a quarter of the clearance beyond their patch, so no row crowds the patch's).
  std::vector<StemBand> bands(order.size());
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    const double top = patch_bounds(hollows[order[k]], trunk).hi;
    const double bottom = patch_bounds(hollows[order[k + 1]], trunk).lo;
    const double middle = 0.5 * (top + bottom), half_strip = std::min(0.25 * (bottom - top), 0.01);
    bands[k].hi = middle - half_strip;
    bands[k + 1].lo = middle + half_strip;
  }
  HollowMesh stem;
  std::vector<int> previous_top;  // ring at the top of the band below, as indices into `stem`
  for (std::size_t k = 0; k < order.size(); ++k) {
    const HollowMesh band = build_hollow_band(hollows[order[k]], trunk, {}, bands[k]).mesh;
    const int offset = static_cast<int>(stem.vertices.size());
    auto shifted = [offset](std::vector<int> ring) {
      for (int& v : ring) v += offset;
      return ring;
    };
    const std::vector<int> bottom = k > 0 ? shifted(border_ring(band, bands[k].lo)) : std::vector<int>{};
    const std::vector<int> top = bands[k].reaches_tip() ? std::vector<int>{} : shifted(border_ring(band, bands[k].hi));
    append(stem, band);
    if (k > 0) zip_rings(stem, previous_top, bottom);
    previous_top = top;
  }
  return stem;
}

}  // namespace heliostand::hollow
