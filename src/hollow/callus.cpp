#include "hollow/callus.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "geometry/angles.hpp"
#include "hollow/mesh_checks.hpp"
#include "hollow/wound_outline.hpp"
#include "rng/random_stream.hpp"

namespace heliostand::hollow {

namespace {

constexpr double max_corner_jitter = radians(5.0);
// A polygon may reach at most this fraction of the way to a neighbouring polygon's plane.
constexpr double crossing_margin = 0.5;
// Neighbours checked on each side for plane crossings; beyond them the across-the-wound clearance applies.
constexpr int plane_neighbours = 8;
// Smallest corner radius (fraction of r) the crossing limits may leave.
constexpr double min_squeezed_radius = 0.1;

int wrap(int j, int n) { return ((j % n) + n) % n; }

// Vertical alignment of the rim, eq. 3.9 with unit directions and |·|: the seed's F_j are steps of 0.1
// units, which would leave E_j at a tenth of I, and its signed dot product would thin the descending side.
std::vector<double> vertical_alignment(const std::vector<glm::dvec3>& v) {
  const int n = static_cast<int>(v.size());
  std::vector<double> step_z(n);
  for (int j = 0; j < n; ++j) step_z[j] = std::abs(glm::normalize(v[wrap(j + 1, n)] - v[j]).z);
  std::vector<double> aligned(n);
  for (int j = 0; j < n; ++j) aligned[j] = (step_z[wrap(j - 1, n)] + step_z[j] + step_z[wrap(j + 1, n)]) / 3.0;
  return aligned;
}

// Distance from each rim vertex to the rim across the wound (vertices further along the loop than `skip`).
std::vector<double> across_clearance(const std::vector<glm::dvec3>& v, int skip) {
  const int n = static_cast<int>(v.size());
  std::vector<double> clearance(n, 1e30);
  if (2 * skip >= n) return clearance;
  for (int j = 0; j < n; ++j)
    for (int k = j + skip; k <= j + n - skip; ++k)
      clearance[j] = std::min(clearance[j], glm::length(v[wrap(k, n)] - v[j]));
  return clearance;
}

// Largest radius along direction d that keeps ring j's corner on its own side of the planes of the
// nearest polygons (they are about one step apart, so these are the first to cross on a tight bend).
double plane_limit(int j, const glm::dvec3& d, const std::vector<glm::dvec3>& v, const std::vector<glm::dvec3>& axis) {
  const int n = static_cast<int>(v.size());
  double limit = 1e30;
  for (int k = 1; k <= plane_neighbours; ++k) {
    const int next = wrap(j + k, n), prev = wrap(j - k, n);
    const double ahead = glm::dot(v[next] - v[j], axis[next]);  // > 0: V_j behind the next plane
    const double toward_next = glm::dot(d, axis[next]);
    if (ahead > 0.0 && toward_next > 0.0) limit = std::min(limit, crossing_margin * ahead / toward_next);
    const double behind = glm::dot(v[j] - v[prev], axis[prev]);
    const double toward_prev = -glm::dot(d, axis[prev]);
    if (behind > 0.0 && toward_prev > 0.0) limit = std::min(limit, crossing_margin * behind / toward_prev);
  }
  return limit;
}

// A swept polygon folds over itself where its reach towards the centre of the rim's bend exceeds the bend's
// radius. The bend is measured over windows of 2K steps (K = 1, 2, 4, … up to the callus size), so that a
// gradual turn and a sharp apex are both seen: radius = arc length / turning angle.
double bend_limit(int j, const glm::dvec3& d, const std::vector<glm::dvec3>& v, const std::vector<glm::dvec3>& axis,
                  const std::vector<double>& arc, int max_window) {
  const int n = static_cast<int>(v.size());
  double limit = 1e30;
  for (int k = 1; k <= max_window && 2 * k < n; k *= 2) {
    const glm::dvec3 before = axis[wrap(j - k, n)], after = axis[wrap(j + k, n)];
    const double turn = std::acos(std::clamp(glm::dot(before, after), -1.0, 1.0));
    if (turn < 1e-9) continue;
    double length = 0.0;
    for (int i = j - k; i < j + k; ++i) length += arc[wrap(i, n)];
    const glm::dvec3 toward_centre = glm::normalize(after - before);
    const double reach = glm::dot(d, toward_centre);
    if (reach > 0.0) limit = std::min(limit, crossing_margin * (length / turn) / reach);
  }
  return limit;
}

}  // namespace

double Callus::mean_radius(int j) const {
  const auto& r = rings[j].radius;
  return std::accumulate(r.begin(), r.end(), 0.0) / static_cast<double>(r.size());
}

std::vector<double> corner_angle_jitter(int corners, RandomStream& rng) {
  std::vector<double> c(corners, 0.0);
  if (corners < 2) return c;
  for (int m = 1; m < corners; ++m) c[m] = rng.uniform(-max_corner_jitter, max_corner_jitter);
  // Σ c_m = 0 with c_0 = 0 held (corner 0 is where the bark joins): remove the mean of the others,
  // then shrink uniformly if that pushed one past ±5° (shrinking keeps the sum at zero).
  const double mean = std::accumulate(c.begin() + 1, c.end(), 0.0) / (corners - 1);
  double largest = 0.0;
  for (int m = 1; m < corners; ++m) largest = std::max(largest, std::abs(c[m] -= mean));
  if (largest > max_corner_jitter)
    for (double& x : c) x *= max_corner_jitter / largest;
  return c;  // |c| ≤ 5° and 360°/M ≥ 10° for M ≤ 36: θ_m stays non-decreasing
}

Callus build_callus(const std::vector<glm::dvec2>& outline_xy, const StemChart& chart, const HollowSpec& spec,
                    bool limit_crossings) {
  const int n = static_cast<int>(outline_xy.size());
  const int corners = spec.polygon_corners;
  Callus callus;
  callus.lip_corner = (3 * corners) / 4;
  RandomStream rng(spec.seed, {0x484f4c4cULL /* "HOLL" */, 1});

  std::vector<glm::dvec3> v(n);
  for (int j = 0; j < n; ++j) v[j] = chart.point(outline_xy[j]);
  // Polygon normal: the bisector of the steps before and after V_j (the seed's forward step tilts each
  // polygon half a step; the central direction keeps the tube symmetric).
  std::vector<glm::dvec3> axis(n);
  for (int j = 0; j < n; ++j)
    axis[j] = glm::normalize(glm::normalize(v[j] - v[wrap(j - 1, n)]) + glm::normalize(v[wrap(j + 1, n)] - v[j]));
  const std::vector<double> aligned = vertical_alignment(v);
  const std::vector<glm::dvec2> normals2d = outward_normals(outline_xy, 2.0 * chart.half_round());
  const double nominal = 1.1 * spec.callus_radius_m + spec.bulge_m;
  const int skip = static_cast<int>(std::ceil(3.0 * nominal / spec.outline_step_m)) + plane_neighbours;
  const std::vector<double> clearance = across_clearance(v, skip);
  std::vector<double> arc(n);  // |V_{j+1} − V_j|
  for (int j = 0; j < n; ++j) arc[j] = glm::length(v[wrap(j + 1, n)] - v[j]);

  callus.rings.resize(n);
  for (int j = 0; j < n; ++j) {
    CallusRing& ring = callus.rings[j];
    ring.centre_xy = outline_xy[j];
    ring.centre = v[j];
    ring.axis = axis[j];
    ring.bulge = spec.bulge_m * aligned[j];
    ring.flare = chart.trunk().flare_factor(v[j].z);
    const std::vector<double> c = corner_angle_jitter(corners, rng);
    ring.theta.resize(corners);
    ring.jitter.resize(corners, 1.0);
    for (int m = 0; m < corners; ++m) {
      ring.theta[m] = m * 2.0 * pi / corners + c[m];
      ring.jitter[m] = m == 0 ? 1.0 : rng.uniform(0.9, 1.1);
    }
    // Across the wound, two rolls may not overlap: each keeps within 40 % of the gap.
    const double across = limit_crossings ? 0.4 * clearance[j] : 1e30;

    // Corner 0, the foot: on the surface, r straight out from the wound, where the bark joins. The bulge E_j
    // raises the roll but does not widen its footprint: a footprint that widened with E_j would make the
    // foot dip beside the apexes (E_j grows fastest there), and the bark could no longer meet it row by row.
    // (The foot lies on the outer side of the rim, so the across-the-wound clearance does not bind it.)
    const double foot_radius = spec.callus_radius_m * ring.flare;
    ring.foot_xy = outline_xy[j] + foot_radius * normals2d[j];
    const glm::dvec3 foot = chart.point(ring.foot_xy);
    // T_j: the direction to the foot, made perpendicular to the polygon normal; the polygon then turns from
    // the foot over the outward surface normal into the wound and on into the wood.
    glm::dvec3 t = foot - v[j];
    t = glm::normalize(t - glm::dot(t, axis[j]) * axis[j]);
    glm::dvec3 up = chart.normal(outline_xy[j]);
    up = glm::normalize(up - glm::dot(up, axis[j]) * axis[j] - glm::dot(up, t) * t);
    const glm::dvec3 turn_axis = glm::normalize(glm::cross(t, up));  // turning t about it by 90° gives up

    ring.radius.assign(callus.lip_corner + 1, 0.0);
    ring.corners.assign(callus.lip_corner + 1, foot);
    ring.directions.assign(callus.lip_corner + 1, glm::normalize(foot - v[j]));
    ring.radius[0] = glm::length(foot - v[j]);
    const double width = spec.callus_radius_m * ring.flare;                // across the surface
    const double height = (spec.callus_radius_m + ring.bulge) * ring.flare;  // off the surface: R = r + E_j
    for (int m = 1; m <= callus.lip_corner; ++m) {
      const glm::dvec3 turned = glm::angleAxis(ring.theta[m], turn_axis) * t;  // Q(θ_m, G_j) T_j
      const glm::dvec3 wanted_offset =
          ring.jitter[m] * (width * glm::dot(turned, t) * t + height * glm::dot(turned, up) * up);
      const double wanted = glm::length(wanted_offset);
      const glm::dvec3 d = wanted_offset / wanted;
      // Squeezed towards a sharp apex, a corner keeps a floor of min_squeezed_radius · r: polygons shrunk to
      // (almost) a point would give roll triangles whose distinct corners coincide and touch their neighbours.
      const double floor = std::min(wanted, min_squeezed_radius * spec.callus_radius_m);
      const double allowed = limit_crossings ? std::max(floor, std::min({wanted, across, plane_limit(j, d, v, axis),
                                                                         bend_limit(j, d, v, axis, arc, skip)}))
                                             : wanted;
      ring.limit_scale = std::min(ring.limit_scale, allowed / wanted);
      ring.radius[m] = allowed;
      ring.directions[m] = d;
      ring.corners[m] = v[j] + allowed * d;
    }
  }
  if (limit_crossings) separate_polygons(callus);
  return callus;
}

namespace {
// The roll between polygons j and j+1 as the mesh will carry it (two triangles per corner step), each
// corner named by (ring, corner) so that triangles sharing a corner can be left out of the comparison.
using Corner = std::pair<int, int>;
using BandTriangle = std::array<Corner, 3>;

void band_triangles(const Callus& callus, int j, std::vector<BandTriangle>& out) {
  const int n = static_cast<int>(callus.rings.size());
  const int k = (j + 1) % n;
  out.clear();
  for (int m = 0; m + 1 < static_cast<int>(callus.rings[j].corners.size()); ++m) {
    out.push_back({Corner{j, m}, Corner{k, m}, Corner{k, m + 1}});
    out.push_back({Corner{j, m}, Corner{k, m + 1}, Corner{j, m + 1}});
  }
}

struct Box {
  glm::dvec3 lo{1e300}, hi{-1e300};
  bool overlaps(const Box& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y && lo.z <= o.hi.z && o.lo.z <= hi.z;
  }
};

Box band_box(const Callus& callus, int j) {
  Box box;
  const int n = static_cast<int>(callus.rings.size());
  for (int i : {j, (j + 1) % n})
    for (const auto& p : callus.rings[i].corners) box.lo = glm::min(box.lo, p), box.hi = glm::max(box.hi, p);
  return box;
}

bool bands_cross(const Callus& callus, int j, int k) {
  thread_local std::vector<BandTriangle> first, second;
  band_triangles(callus, j, first);
  band_triangles(callus, k, second);
  auto at = [&](Corner c) { return callus.rings[c.first].corners[c.second]; };
  for (const auto& s : first)
    for (const auto& t : second) {
      bool shared = false;
      for (const Corner& a : s)
        for (const Corner& b : t) shared = shared || a == b;
      if (shared) continue;
      if (triangles_intersect(at(s[0]), at(s[1]), at(s[2]), at(t[0]), at(t[1]), at(t[2]))) return true;
    }
  return false;
}

double reach(const CallusRing& ring) { return *std::max_element(ring.radius.begin(), ring.radius.end()); }
}  // namespace

int separate_polygons(Callus& callus, int max_rounds) {
  const int n = static_cast<int>(callus.rings.size());
  // Radii only shrink, so the bands close enough to cross can be listed once. A band is also compared with
  // itself and its neighbours (triangles sharing a corner left out): where a tight bend squeezes some corners
  // much more than others, a band can fold over itself.
  std::vector<std::pair<int, int>> close;
  std::vector<double> band_reach(n);
  for (int j = 0; j < n; ++j) band_reach[j] = std::max(reach(callus.rings[j]), reach(callus.rings[(j + 1) % n]));
  for (int j = 0; j < n; ++j)
    for (int k = j; k < n; ++k) {
      const double step = glm::length(callus.rings[(j + 1) % n].centre - callus.rings[j].centre) +
                          glm::length(callus.rings[(k + 1) % n].centre - callus.rings[k].centre);
      if (glm::length(callus.rings[j].centre - callus.rings[k].centre) < band_reach[j] + band_reach[k] + step)
        close.emplace_back(j, k);
    }
  int crossing = 0;
  for (int round = 0; round <= max_rounds; ++round) {
    std::vector<bool> shrink(n, false);
    std::vector<Box> boxes(n);
    for (int j = 0; j < n; ++j) boxes[j] = band_box(callus, j);
    crossing = 0;
    for (auto [j, k] : close) {
      if (!boxes[j].overlaps(boxes[k]) || !bands_cross(callus, j, k)) continue;
      ++crossing;
      shrink[j] = shrink[(j + 1) % n] = shrink[k] = shrink[(k + 1) % n] = true;
    }
    if (crossing == 0 || round == max_rounds) break;
    for (int j = 0; j < n; ++j) {
      if (!shrink[j]) continue;
      CallusRing& ring = callus.rings[j];
      for (std::size_t m = 1; m < ring.corners.size(); ++m) {
        ring.radius[m] *= 0.9;
        ring.corners[m] = ring.centre + ring.radius[m] * ring.directions[m];
      }
      ring.limit_scale *= 0.9;
    }
  }
  return crossing;
}

}  // namespace heliostand::hollow
