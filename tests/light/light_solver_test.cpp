// One test body, run against both light solvers (reference and OpenCL) in exact and culled mode:
// the OpenMM pattern of shared platform tests.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <tuple>

#include <glm/geometric.hpp>

#include "compute/opencl_test_backend.hpp"
#include "geometry/angles.hpp"
#include "light/celestial_sphere.hpp"
#include "light/far_field.hpp"
#include "light/far_field_margin.hpp"
#include "light/make_light_solver.hpp"
#include "light/occluders.hpp"
#include "light/reference_light_solver.hpp"
#include "light_test_stands.hpp"

namespace heliostand {
namespace {

enum class Backend { reference, opencl };
enum class Mode { exact, culled };

class LightSolverTest : public ::testing::TestWithParam<std::tuple<Backend, Mode, bool>> {
 protected:
  void SetUp() override {
    if (backend() == Backend::reference) {
      compute_ = compute::ComputeBackend::reference();
    } else {
      compute_ = compute::opencl_backend_for_test();
      if (!compute_) GTEST_SKIP() << "no OpenCL device";
    }
  }
  Backend backend() const { return std::get<0>(GetParam()); }
  // Culled mode with a cut-off beyond the test scenes: every occluder is near field, the far field is empty,
  // so the hand-computed answers hold for both modes. Periodic runs use a plot so large that the images of
  // the scene (1000 m away, level with it) subtend no patch centre: the answers must not change.
  LightParameters parameters() const {
    LightParameters p;
    p.exact = std::get<1>(GetParam()) == Mode::exact;
    p.cutoff_m = 100.0;
    p.periodic = std::get<2>(GetParam());
    p.plot_x_min = p.plot_y_min = -500;
    p.plot_x_max = p.plot_y_max = 500;
    // (a far field over a 1 km torus would only add zeros, slowly: leave it out there)
    p.far_field = !p.periodic;
    return p;
  }
  std::vector<LightSample> solve(const LightParameters& p, const std::vector<LeafBall>& balls) {
    return make_light_solver(*compute_, p)->solve(balls);
  }
  std::optional<compute::ComputeBackend> compute_;
};

// Solid angle of band v, written out independently of CelestialSphere.
double band_solid_angle(int v, int bands, int sectors) {
  return 2.0 * pi / sectors * (std::cos(v * pi / bands) - std::cos((v + 1) * pi / bands));
}

TEST_P(LightSolverTest, LoneBallSeesTheWholeSkyAndLightComesFromTheBrighterHemisphere) {
  LightParameters p = parameters();
  const std::vector<LeafBall> balls{{{1, 2, 3}, 0.5}};
  p.intensity_ratio = 1.5;  // C1 > C2: brighter sky above
  auto samples = solve(p, balls);
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_NEAR(samples[0].light, 1.0, 1e-6);
  EXPECT_NEAR(samples[0].vector.z, 1.0, 1e-6);
  p.intensity_ratio = 1.0 / 1.5;  // brighter ground reflection than sky: light comes from below
  samples = solve(p, balls);
  EXPECT_NEAR(samples[0].light, 1.0, 1e-6);
  EXPECT_NEAR(samples[0].vector.z, -1.0, 1e-6);
  p.intensity_ratio = 1.0;  // C1 = C2: balanced, no preferred direction
  samples = solve(p, balls);
  EXPECT_NEAR(glm::length(samples[0].vector), 0.0, 1e-12);
}

TEST_P(LightSolverTest, BallInsideOneOccluderGetsTAndInsideTwoGetsTSquared) {
  LightParameters p = parameters();
  p.transmittance = 0.3;
  // The receiver sits inside two big balls and is shaded by both in every direction.
  const std::vector<LeafBall> nested{{{0, 0, 0}, 0.1}, {{0.2, 0, 0}, 1.0}, {{-0.5, 0.3, 0.4}, 3.0}};
  const auto twice = solve(p, nested);
  EXPECT_NEAR(twice[0].light, 0.09, 1e-6);
  EXPECT_NEAR(twice[0].vector.z, 1.0, 1e-6);
  // A lone pair: receiver inside its only occluder gets exactly t, and keeps the unshaded direction.
  const std::vector<LeafBall> pair{{{0, 0, 0}, 0.1}, {{0.3, 0.1, -0.2}, 2.0}};
  const auto enclosed = solve(p, pair);
  EXPECT_NEAR(enclosed[0].light, 0.3, 1e-6);
  EXPECT_NEAR(enclosed[0].vector.z, 1.0, 1e-6);
}

TEST_P(LightSolverTest, ShellOfOccludersOnePerPatchGivesExactlyT) {
  LightParameters p = parameters();
  p.transmittance = 0.4;
  // One small ball on every patch's centre ray, 3 m out: angular radius 0.57 deg, less than the closest
  // spacing of patch centres (1.1 deg, around the poles), so each ray hits exactly one ball.
  const CelestialSphere sky(p);
  std::vector<LeafBall> balls{{{0, 0, 0}, 0.1}};
  for (const auto& patch : sky.patches()) balls.push_back({3.0 * patch.direction, 0.03});
  const auto samples = solve(p, balls);
  EXPECT_NEAR(samples[0].light, 0.4, 1e-6);
  EXPECT_NEAR(samples[0].vector.z, 1.0, 1e-6);  // uniform dimming keeps the direction
}

TEST_P(LightSolverTest, OccluderStraightAboveShadesExactlyTheBandsWithinItsAngularRadius) {
  LightParameters p = parameters();
  p.transmittance = 0.5;
  // angular radius asin(r / z) = 20 deg: band centres 5.625 and 16.875 deg are inside, 28.125 is not
  const double z = 5.0, r = z * std::sin(20.0 * pi / 180.0);
  const std::vector<LeafBall> balls{{{0, 0, 0}, 0.1}, {{0, 0, z}, r}};
  const auto samples = solve(p, balls);
  const int V = p.sky_bands, H = p.sky_sectors;
  const double c1 = 1.0, c2 = 1.0 / p.intensity_ratio;
  double total = 0, upper_z = 0, lower_z = 0, lost = 0, lost_z = 0;
  for (int v = 0; v < V; ++v) {
    const double s = band_solid_angle(v, V, H) * H, cos_centre = std::cos((v + 0.5) * pi / V);
    total += (v < V / 2 ? c1 : c2) * s;
    (v < V / 2 ? upper_z : lower_z) += (v < V / 2 ? c1 : c2) * s * cos_centre;
    if (v < 2) lost += 0.5 * c1 * s, lost_z += 0.5 * c1 * s * cos_centre;
  }
  EXPECT_NEAR(samples[0].light, (total - lost) / total, 1e-6);
  // shading is symmetric about the vertical axis: the vector stays vertical, pointing to the net excess
  const double net_z = upper_z + lower_z - lost_z;
  EXPECT_NEAR(samples[0].vector.x, 0.0, 1e-6);
  EXPECT_NEAR(samples[0].vector.y, 0.0, 1e-6);
  EXPECT_NEAR(samples[0].vector.z, net_z > 0 ? 1.0 : -1.0, 1e-6);
  // the occluder itself looks down at a small receiver: it loses a sliver of its lower sky at most
  EXPECT_GT(samples[1].light, 0.99);
}

TEST_P(LightSolverTest, OccluderOffAxisShadesThePatchesCountedByAngle) {
  LightParameters p = parameters();
  p.transmittance = 0.25;
  // An occluder at polar angle 50 deg, azimuth 30 deg, angular radius 12 deg. Count by angle between the
  // patch centre and the occluder direction (a different test from the solvers' ray-sphere one).
  const double polar = 50 * pi / 180, azimuth = 30 * pi / 180, alpha = 12 * pi / 180, dist = 4.0;
  const glm::dvec3 u{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar)};
  const std::vector<LeafBall> balls{{{0, 0, 0}, 0.2}, {dist * u, dist * std::sin(alpha)}};
  const int V = p.sky_bands, H = p.sky_sectors;
  double total = 0, received = 0;
  glm::dvec3 flux(0.0);
  int shaded = 0;
  for (int v = 0; v < V; ++v)
    for (int h = 0; h < H; ++h) {
      const double th = (v + 0.5) * pi / V, ph = (h + 0.5) * 2 * pi / H;
      const glm::dvec3 n{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
      const double b0 = (v < V / 2 ? 1.0 : 1.0 / p.intensity_ratio) * band_solid_angle(v, V, H);
      const bool hit = std::acos(glm::dot(n, u)) <= alpha;
      shaded += hit;
      total += b0;
      received += hit ? 0.25 * b0 : b0;
      flux += n * (hit ? 0.25 * b0 : b0);
    }
  ASSERT_GT(shaded, 4);  // the scene really shades several patches
  const auto samples = solve(p, balls);
  EXPECT_NEAR(samples[0].light, received / total, 1e-6);
  // The light vector is the flux's direction: a unit vector, on the device in float. OpenCL lets a device's
  // division and length each be off by a few ulps (NVIDIA's OpenCL on an H100 gives a norm of 1 + 1.3e-7, one
  // float ulp above 1; PoCL 1 + 8e-9), so the norm is held to eight float epsilons. The direction is held
  // apart, and far tighter than a dot product could hold it (1 - cos 1e-6 is 5e-13): the sine of its angle to
  // the analytic flux under 1e-6, where both devices give 1.6e-7 (the float sums over the 512 patches).
  const glm::dvec3 vector = samples[0].vector;
  EXPECT_NEAR(glm::length(vector), 1.0, 8 * std::numeric_limits<float>::epsilon());
  EXPECT_LT(glm::length(glm::cross(glm::normalize(vector), glm::normalize(flux))), 1e-6);
  // light now comes from away from the occluder
  EXPECT_LT(samples[0].vector.x, 0.0);
}

TEST_P(LightSolverTest, RingOfOccludersLeavesTheLightVectorVertical) {
  LightParameters p = parameters();
  p.intensity_ratio = 0.8;  // stronger light from below, so the ring matters for the sign too
  std::vector<LeafBall> balls{{{0, 0, 0}, 0.1}};
  for (int k = 0; k < 8; ++k) {  // 8 balls, 45 deg apart: the 32 sectors map onto each other
    const double a = k * pi / 4;
    balls.push_back({{2 * std::cos(a), 2 * std::sin(a), 1.0}, 0.6});
  }
  const auto samples = solve(p, balls);
  EXPECT_LT(samples[0].light, 0.999);
  EXPECT_NEAR(samples[0].vector.x, 0.0, 1e-6);
  EXPECT_NEAR(samples[0].vector.y, 0.0, 1e-6);
  EXPECT_NEAR(std::abs(samples[0].vector.z), 1.0, 1e-6);
}

TEST_P(LightSolverTest, PeriodicPlotShadesAcrossItsEdgesLikeExplicitCopies) {
  LightParameters p = parameters();
  if (!p.periodic) GTEST_SKIP() << "periodic plots only";
  p.plot_x_min = p.plot_y_min = 0;
  p.plot_x_max = p.plot_y_max = 10;
  p.cutoff_m = 30;  // beyond the plot: near field holds every copy, the far field is empty
  p.far_field = true;
  // a receiver at the west edge and an occluder at the east edge: neighbours across the boundary
  const std::vector<LeafBall> stand{{{0.5, 5, 1}, 0.2}, {{9.5, 5.3, 1.1}, 0.5}};
  const auto periodic = solve(p, stand);
  // the same scene spelled out: the plot and its 8 neighbours, as plain (non-periodic) balls
  std::vector<LeafBall> copies{stand[0]};
  for (int sx = -1; sx <= 1; ++sx)
    for (int sy = -1; sy <= 1; ++sy)
      for (std::size_t k = 0; k < stand.size(); ++k)
        if (k != 0 || sx != 0 || sy != 0)
          copies.push_back({stand[k].centre + glm::dvec3(10.0 * sx, 10.0 * sy, 0), stand[k].radius});
  p.periodic = false;
  const auto spelled_out = solve(p, copies);
  EXPECT_LT(periodic[0].light, 0.97);  // the occluder 1 m west (across the edge) really shades
  EXPECT_NEAR(periodic[0].light, spelled_out[0].light, 1e-6);
  EXPECT_NEAR(glm::dot(periodic[0].vector, spelled_out[0].vector), 1.0, 1e-7);
  EXPECT_GT(periodic[0].vector.x, 0.0);  // light comes from the east, away from the shading neighbour
}

// The open-grown reference lights every tree of a stand alone in one call: the same answers as solving each
// group as a stand of its own, and no group shades another (two groups share one place here).
TEST_P(LightSolverTest, EachGroupAloneMatchesSolvingItByItself) {
  const auto p = parameters();
  const CelestialSphere sky(p);
  const auto first = testing::random_stand(40, 4.0, 0.2, 0.5, 3, sky, false);
  const auto second = testing::random_stand(30, 4.0, 0.2, 0.5, 4, sky, false);  // overlaps the first
  const std::vector<LeafBall> lone{{{2, 2, 2}, 0.3}};
  std::vector<LeafBall> balls = first;
  balls.insert(balls.end(), second.begin(), second.end());
  balls.insert(balls.end(), lone.begin(), lone.end());
  const std::vector<std::size_t> groups{0, first.size(), first.size(), balls.size() - 1, balls.size()};  // one empty
  auto solver = make_light_solver(*compute_, p);
  const auto together = solver->solve_each_alone(balls, groups);
  ASSERT_EQ(together.size(), balls.size());
  std::vector<LightSample> apart = solver->solve(first);
  const auto second_alone = solver->solve(second);
  const auto lone_alone = solver->solve(lone);
  apart.insert(apart.end(), second_alone.begin(), second_alone.end());
  apart.insert(apart.end(), lone_alone.begin(), lone_alone.end());
  double lowest = 1;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    EXPECT_EQ(together[k].light, apart[k].light) << "ball " << k;
    EXPECT_EQ(together[k].vector, apart[k].vector) << "ball " << k;
    lowest = std::min(lowest, together[k].light);
  }
  EXPECT_LT(lowest, 0.7);                     // the groups are dense enough to shade themselves
  EXPECT_NEAR(together.back().light, 1.0, 1e-6);  // the lone ball sits inside the other groups, unshaded
  EXPECT_THROW(solver->solve_each_alone(balls, std::vector<std::size_t>{0, 5}), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Backends, LightSolverTest,
                         ::testing::Combine(::testing::Values(Backend::reference, Backend::opencl),
                                            ::testing::Values(Mode::exact, Mode::culled), ::testing::Bool()),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param) == Backend::reference ? "Reference" : "OpenCL") +
                                  (std::get<1>(info.param) == Mode::exact ? "Exact" : "Culled") +
                                  (std::get<2>(info.param) ? "Periodic" : "Open");
                         });

// ---- OpenCL against the reference on random stands ----------------------------------------------------

struct EquivalenceCase {
  bool exact;
  bool periodic;
  bool far_field_bias_correction = false;  // culled only: both backends read the corrected far field
};

class LightEquivalenceTest : public ::testing::TestWithParam<EquivalenceCase> {};

double angle_degrees(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * 180.0 / pi;
}

TEST_P(LightEquivalenceTest, OpenCLMatchesReferenceOnRandomStands) {
  const auto device = compute::opencl_backend_for_test();
  if (!device) GTEST_SKIP() << "no OpenCL device";
  LightParameters p;
  p.exact = GetParam().exact;
  p.periodic = GetParam().periodic;
  p.far_field_bias_correction = GetParam().far_field_bias_correction;
  const double size = 6.0;
  p.plot_x_max = p.plot_y_max = size;
  p.cutoff_m = 2.0;          // a real split: many occluders near, many far
  p.far_field_cell_m = 1.0;
  p.transmittance = 0.6;
  const CelestialSphere sky(p);
  for (std::uint64_t seed : {1u, 2u}) {
    const auto balls = testing::random_stand(120, size, 0.2, 0.7, seed, sky, p.periodic);
    ReferenceLightSolver reference(p);
    const auto opencl = make_light_solver(*device, p);
    const auto expected = reference.solve(balls);
    const auto actual = opencl->solve(balls);
    ASSERT_EQ(actual.size(), balls.size());
    double lowest = 1;
    for (std::size_t k = 0; k < balls.size(); ++k) {
      lowest = std::min(lowest, expected[k].light);
      EXPECT_NEAR(actual[k].light, expected[k].light, 1e-4) << "ball " << k << " seed " << seed;
      EXPECT_LT(angle_degrees(actual[k].vector, expected[k].vector), 0.1) << "ball " << k << " seed " << seed;
    }
    EXPECT_LT(lowest, 0.5);  // the stand really is dense enough to shade
  }
}

// The culled solver of `device` against the reference on a random stand of `count` balls in a cube of `size`
// metres, at 1e-4 (the far field in float against double), where the stand shades somewhere below 0.8.
void expect_far_field_matches_reference(const compute::ComputeBackend& device, const LightParameters& p,
                                        std::size_t count, double size, std::uint64_t seed, const std::string& label) {
  const CelestialSphere sky(p);
  const auto balls = testing::random_stand(count, size, 0.2, 0.6, seed, sky, p.periodic);
  const auto expected = ReferenceLightSolver(p).solve(balls);
  const auto actual = make_light_solver(device, p)->solve(balls);
  ASSERT_EQ(actual.size(), balls.size()) << label;
  double lowest = 1;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    lowest = std::min(lowest, expected[k].light);
    EXPECT_NEAR(actual[k].light, expected[k].light, 1e-4) << label << ", ball " << k;
  }
  EXPECT_LT(lowest, 0.8) << label;  // there is shade to get right
}

// The culled kernel reads the far field eight patches at a time (cl/light.cl) and the sweep fills the table eight
// columns at a time (cl/far_field.cl), a chunk of 128 patches at a time (light/far_field_buffers.hpp): skies whose
// patch count is not a multiple of eight (2, 30 and 130 patches, the last a whole chunk and then one of 2 patches
// and six padding entries) and grids of any column count must match the reference too, open and periodic.
TEST(LightEightLanes, SkiesOfAnyPatchCountMatchTheReferenceInTheFarField) {
  const auto device = compute::opencl_backend_for_test();
  if (!device) GTEST_SKIP() << "no OpenCL device";
  for (const auto& [bands, sectors] : {std::pair{2, 1}, std::pair{6, 5}, std::pair{4, 4}, std::pair{10, 13}})
    for (const bool periodic : {false, true}) {
      LightParameters p;
      p.exact = false;
      p.periodic = periodic;
      p.sky_bands = bands;
      p.sky_sectors = sectors;
      p.plot_x_max = 5.5;  // 7 x 7 cells of 0.9 m and more: columns not a multiple of eight
      p.plot_y_max = 5.5;
      p.cutoff_m = 1.5;  // most of the shade from the far field
      p.far_field_cell_m = 0.9;
      p.transmittance = 0.6;
      expect_far_field_matches_reference(*device, p, 150, 5.5, 7,
                                         fmt::format("{} x {} {}", bands, sectors, periodic ? "periodic" : "open"));
    }
}

// The sweep looks up eight columns at once, with two loads of eight per corner row where one row holds all eight
// and their corners (cl/voxel_grid.clh, grid_sample_shifted8), and lane by lane elsewhere: rows of several runs
// of eight columns and rays slanted across many of them (the lowest band of an 8-band sky climbs one 0.4 m layer
// in ~4 m), open and periodic (where the slanted rays wrap around the plot's sides), must match the reference.
TEST(LightEightLanes, WideGridsWithLongSlantedRaysMatchTheReferenceInTheFarField) {
  const auto device = compute::opencl_backend_for_test();
  if (!device) GTEST_SKIP() << "no OpenCL device";
  for (const bool periodic : {false, true})
    for (const bool corrected : {false, true}) {
      LightParameters p;
      p.exact = false;
      p.periodic = periodic;
      p.far_field_bias_correction = corrected;
      p.sky_bands = 8;
      p.sky_sectors = 16;
      p.plot_x_max = p.plot_y_max = 12.0;  // 30 columns of 0.4 m a row, more on the open grid
      p.cutoff_m = 1.0;                    // most of the shade from the far field
      p.far_field_cell_m = 0.4;
      p.transmittance = 0.6;
      const std::string label = fmt::format("{}{}", periodic ? "periodic" : "open", corrected ? ", corrected" : "");
      expect_far_field_matches_reference(*device, p, 250, 12.0, 11, label);
    }
}

// The sweep reads the density with a margin around the grid's sides that holds what a lookup there gives
// (light/far_field_margin.hpp), and lane by lane where a lookup lands beyond it: an open grid whose outermost
// cells hold foliage (cells coarsened to fit the table's budget) gets no margin at all, and a start distance of
// more than the margin's cap puts the slanted rays' lookups beyond it, open and periodic. All must match the
// reference.
TEST(LightEightLanes, GridsWithoutAMarginAndLookupsBeyondItMatchTheReferenceInTheFarField) {
  const auto device = compute::opencl_backend_for_test();
  if (!device) GTEST_SKIP() << "no OpenCL device";
  LightParameters coarse;
  coarse.exact = false;
  coarse.sky_bands = 8;
  coarse.sky_sectors = 16;
  coarse.cutoff_m = 2.0;
  coarse.transmittance = 0.6;
  coarse.far_field_table_mb = 1;  // cells of ~1.8 m on a 16 m stand: foliage in the outermost cells
  {
    const CelestialSphere sky(coarse);
    const auto balls = testing::random_stand(400, 16.0, 0.2, 0.6, 6, sky, false);
    const FarField far(make_occluder_set(balls, PlotTorus::from(coarse), 0), coarse, sky, false);
    ASSERT_EQ(sweep_margin_cells(far, sky.patches()), 0);
  }
  expect_far_field_matches_reference(*device, coarse, 400, 16.0, 6, "open, outermost cells with foliage");
  for (const bool periodic : {false, true}) {
    LightParameters p;
    p.exact = false;
    p.periodic = periodic;
    p.sky_bands = 4;
    p.sky_sectors = 4;
    p.plot_x_max = p.plot_y_max = 6.0;
    p.cutoff_m = 10.0;  // start 10.1 m: the low band's lookups ~66 cells of 0.1 m out in x and y, the cap 64
    p.far_field_cell_m = 0.1;
    p.transmittance = 0.6;
    const CelestialSphere sky(p);
    const auto balls = testing::random_stand(150, 6.0, 0.2, 0.6, 8, sky, periodic);
    const FarField far(make_occluder_set(balls, PlotTorus::from(p), 0), p, sky, false);
    ASSERT_EQ(sweep_margin_cells(far, sky.patches()), sweep_margin_cap);
    for (const auto& patch : sky.patches())
      if (patch.band == 1 || patch.band == 2)  // the bands nearest the horizon
        ASSERT_GT(far.start_distance() * std::min(std::abs(patch.direction.x) / far.grid().cell.x,
                                                  std::abs(patch.direction.y) / far.grid().cell.y),
                  sweep_margin_cap);
    expect_far_field_matches_reference(*device, p, 150, 6.0, 8,
                                       periodic ? "periodic, beyond the cap" : "open, beyond the cap");
  }
}

// The exact and culled kernels against the reference's exact answer on `balls` (`culled` keeps every ball within
// its cut-off, so it must equal exact), and the open-grown kernel against the reference's on `groups`, all at 1e-5:
// one patch shaded or missed moves a light by ~(1 - t) / patch count, far above it. `label` names the case.
void expect_kernels_match_reference(const compute::ComputeBackend& device, const LightParameters& exact,
                                    const LightParameters& culled, const std::vector<LeafBall>& balls,
                                    const std::vector<std::size_t>& groups, const std::string& label) {
  const auto expected = ReferenceLightSolver(exact).solve(balls);
  for (const auto& p : {exact, culled}) {
    const auto actual = make_light_solver(device, p)->solve(balls);
    ASSERT_EQ(actual.size(), balls.size()) << label;
    for (std::size_t k = 0; k < balls.size(); ++k)
      EXPECT_NEAR(actual[k].light, expected[k].light, 1e-5)
          << label << (p.exact ? " exact" : " culled") << ", ball " << k;
  }
  const auto expected_alone = ReferenceLightSolver(exact).solve_each_alone(balls, groups);
  const auto alone = make_light_solver(device, exact)->solve_each_alone(balls, groups);
  ASSERT_EQ(alone.size(), balls.size()) << label;
  for (std::size_t k = 0; k < balls.size(); ++k)
    EXPECT_NEAR(alone[k].light, expected_alone[k].light, 1e-5) << label << " alone, ball " << k;
}

// The OpenCL kernels take a receiver's occluders eight at a time (cl/light.cl, OccluderBatch): a receiver with
// no occluder, a batch left part full, exactly full or full plus one must all match the reference, and so must a
// receiver sitting inside an occluder in any lane. Stands of 1 to 18 balls give every receiver count of occluders
// from 0 to 17, in the exact, culled (every ball within the cut-off) and open-grown (each group alone) kernels.
TEST(LightBatches, EveryOccluderCountFromNoneToTwoFullBatchesMatchesTheReference) {
  const auto device = compute::opencl_backend_for_test();
  if (!device) GTEST_SKIP() << "no OpenCL device";
  LightParameters exact;
  exact.exact = true;
  exact.transmittance = 0.6;
  LightParameters culled = exact;
  culled.exact = false;
  culled.cutoff_m = 100.0;  // every ball in the near field: culled must equal exact
  const CelestialSphere sky(exact);
  int receivers_inside = 0;
  for (std::size_t count = 1; count <= 18; ++count) {
    // 1.5 m box, radii up to 0.6 m: crowded, so some receivers sit inside another ball
    const auto balls = testing::random_stand(count, 1.5, 0.2, 0.6, 100 + count, sky, false);
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t j = 0; j < count; ++j)
        receivers_inside += i != j && glm::length(balls[i].centre - balls[j].centre) < balls[j].radius;
    const std::vector<std::size_t> groups{0, count / 2, count};  // two trees: a batch each, or none
    expect_kernels_match_reference(*device, exact, culled, balls, groups, std::to_string(count) + " balls");
  }
  EXPECT_GT(receivers_inside, 0);  // the lane that shades every patch was exercised
}

// The kernels test a ball's window of patches band by band, in runs of up to eight neighbouring patches
// (cl/light.cl, shade_band): a window across sector 0 (from either side) is two runs, one wider than eight sectors
// or around the zenith is several, and on a sky whose sector count is not a multiple of eight a run's last eight
// read into the next band. On a sky of 16 sectors or more a window of at most eight sectors is one run of eight a
// band without a mask (shade_narrow), placed back from the band's last sector, or two where it wraps past sector 0
// (on 16 sectors, the whole band). Balls placed in exactly those directions from a receiver, every ball also a
// receiver, must match the reference on skies of 16 x 32, 8 x 16, 6 x 7 and 4 x 9 patches, in the exact, culled and
// open-grown kernels.
TEST(LightPatchRuns, WindowsAcrossSectorZeroAroundTheZenithAndWideMatchTheReference) {
  const auto device = compute::opencl_backend_for_test();
  if (!device) GTEST_SKIP() << "no OpenCL device";
  std::vector<LeafBall> balls{{{0.0, 0.0, 0.0}, 0.05}};
  for (const double azimuth : {0.0, 0.03, -0.03, 0.5 * pi, pi, 2.0 * pi - 0.2})
    for (const double polar : {0.04, 0.7, 1.55, 2.4})
      for (const double sin_half_angle : {0.05, 0.35, 0.9}) {
        const double distance = 0.8 + 0.4 * polar;
        const glm::dvec3 direction{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                                   std::cos(polar)};
        balls.push_back({distance * direction * (1.0 + 0.7 * sin_half_angle), distance * sin_half_angle});
      }
  for (const auto& [bands, sectors] : {std::pair{16, 32}, std::pair{8, 16}, std::pair{6, 7}, std::pair{4, 9}}) {
    LightParameters exact;
    exact.exact = true;
    exact.sky_bands = bands;
    exact.sky_sectors = sectors;
    exact.transmittance = 0.6;
    LightParameters culled = exact;
    culled.exact = false;
    culled.far_field = false;
    culled.cutoff_m = 100.0;  // every ball in the near field: culled must equal exact
    const std::string sky = std::to_string(bands) + " x " + std::to_string(sectors);
    expect_kernels_match_reference(*device, exact, culled, balls, {0, balls.size()}, sky);  // one tree
    const std::uint32_t first_receiver = 0;
    EXPECT_LT(ReferenceLightSolver(exact).solve_for(balls, {&first_receiver, 1})[0].light, 0.8) << sky;  // shaded
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, LightEquivalenceTest,
                         ::testing::Values(EquivalenceCase{true, false}, EquivalenceCase{false, false},
                                           EquivalenceCase{true, true}, EquivalenceCase{false, true},
                                           EquivalenceCase{false, false, true}, EquivalenceCase{false, true, true}),
                         [](const auto& info) {
                           return std::string(info.param.exact ? "Exact" : "Culled") +
                                  (info.param.periodic ? "Periodic" : "Open") +
                                  (info.param.far_field_bias_correction ? "BiasCorrected" : "");
                         });

}  // namespace
}  // namespace heliostand
