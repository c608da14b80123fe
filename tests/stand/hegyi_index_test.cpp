// Hegyi's competition index over a stem neighbourhood: by hand for three trees, across a plot edge with periodic and
// buffered edges, and against the plain O(n²) sum on a random stand.
#include "stand/hegyi_index.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "rng/random_stream.hpp"

namespace heliostand {
namespace {

const StandEdges buffered{};
StandEdges periodic(PlotBounds plot) { return {true, plot}; }

// A 20 cm subject tree at the origin, a 30 cm neighbour 3 m east, a 10 cm neighbour 4 m north; the two neighbours are
// 5 m apart.
TEST(HegyiIndex, ThreeTreesByHand) {
  const std::vector<glm::dvec2> positions{{0, 0}, {3, 0}, {0, 4}};
  const std::vector<double> dbh{20, 30, 10};
  const Neighbourhood stems(positions, buffered);
  const auto index = hegyi_indices(stems, dbh, 6.0);
  ASSERT_EQ(index.size(), 3u);
  EXPECT_NEAR(index[0], (30.0 / 20) / 3 + (10.0 / 20) / 4, 1e-12);  // 0.5 + 0.125
  EXPECT_NEAR(index[1], (20.0 / 30) / 3 + (10.0 / 30) / 5, 1e-12);
  EXPECT_NEAR(index[2], (20.0 / 10) / 4 + (30.0 / 10) / 5, 1e-12);
  // A radius of 4.5 m leaves out the 5 m pair and keeps the rest; the bound is strict (dist < R).
  const auto near = hegyi_indices(stems, dbh, 4.5);
  EXPECT_NEAR(near[1], (20.0 / 30) / 3, 1e-12);
  EXPECT_NEAR(near[2], (20.0 / 10) / 4, 1e-12);
  EXPECT_NEAR(hegyi_indices(stems, dbh, 4.0)[0], 0.5, 1e-12);
}

TEST(HegyiIndex, StemWithoutDbhHasNoIndexAndAddsNothing) {
  const std::vector<glm::dvec2> positions{{0, 0}, {2, 0}};
  const Neighbourhood stems(positions, buffered);
  const auto index = hegyi_indices(stems, std::vector<double>{20, 0}, 6.0);
  EXPECT_EQ(index[0], 0.0);
  EXPECT_TRUE(std::isnan(index[1]));
}

// On a 10 m x 10 m plot, a tree 1 m from the west edge and one 1 m from the east edge are 8 m apart inside the plot
// but 2 m apart across the edge: periodic edges count each other, buffered edges do not.
TEST(HegyiIndex, PeriodicEdgesSeeAcrossThePlotEdgeAndBufferedOnesDoNot) {
  const PlotBounds plot{0, 0, 10, 10};
  const std::vector<glm::dvec2> positions{{1, 5}, {9, 5}};
  const std::vector<double> dbh{20, 20};
  const Neighbourhood wrapped(positions, periodic(plot)), open(positions, buffered);
  EXPECT_NEAR(wrapped.distance(0, 1), 2.0, 1e-12);
  EXPECT_NEAR(open.distance(0, 1), 8.0, 1e-12);
  EXPECT_NEAR(hegyi_indices(wrapped, dbh, 6.0)[0], 1.0 / 2.0, 1e-12);
  EXPECT_EQ(hegyi_indices(open, dbh, 6.0)[0], 0.0);
  // A radius over half the plot reaches the other stem twice (2 m one way, 8 m the other): it counts once.
  const auto neighbours = wrapped.within(0, 9.0);
  ASSERT_EQ(neighbours.size(), 1u);
  EXPECT_NEAR(neighbours[0].distance_m, 2.0, 1e-12);
}

TEST(Neighbourhood, NearestNeighbourAcrossAPeriodicEdge) {
  const PlotBounds plot{0, 0, 10, 10};
  const std::vector<glm::dvec2> positions{{0.5, 5}, {4, 5}, {9.5, 5}};
  const Neighbourhood wrapped(positions, periodic(plot)), open(positions, buffered);
  EXPECT_EQ(wrapped.nearest(0)->stem, 2u);  // 1 m across the west edge
  EXPECT_NEAR(wrapped.nearest(0)->distance_m, 1.0, 1e-12);
  EXPECT_EQ(open.nearest(0)->stem, 1u);  // 3.5 m inside the plot
}

// The plain sum over every pair, distances to the nearest copy when periodic.
std::vector<double> brute_force(const std::vector<glm::dvec2>& p, const std::vector<double>& dbh, double radius,
                                const StandEdges& edges) {
  std::vector<double> index(p.size(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (i == j) continue;
      double dx = p[j].x - p[i].x, dy = p[j].y - p[i].y;
      if (edges.periodic) {
        dx -= edges.domain.width_m() * std::round(dx / edges.domain.width_m());
        dy -= edges.domain.depth_m() * std::round(dy / edges.domain.depth_m());
      }
      const double distance = std::hypot(dx, dy);
      if (distance < radius) index[i] += dbh[j] / dbh[i] / std::max(distance, 0.1);
    }
  return index;
}

TEST(HegyiIndex, AgreesWithTheBruteForceSumOnARandomStand) {
  const PlotBounds plot{10, -5, 50, 25};  // 40 m x 30 m, off the origin
  RandomStream random(2024);
  std::vector<glm::dvec2> positions;
  std::vector<double> dbh;
  for (int i = 0; i < 300; ++i) {
    positions.push_back({random.uniform(plot.x_min, plot.x_max), random.uniform(plot.y_min, plot.y_max)});
    dbh.push_back(random.uniform(5.0, 40.0));
  }
  for (const StandEdges& edges : {buffered, periodic(plot)}) {
    const Neighbourhood stems(positions, edges);
    const auto fast = hegyi_indices(stems, dbh, 6.0);
    const auto slow = brute_force(positions, dbh, 6.0, edges);
    int with_neighbours = 0;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      EXPECT_NEAR(fast[i], slow[i], 1e-9 * std::max(1.0, slow[i])) << "tree " << i << " periodic " << edges.periodic;
      with_neighbours += slow[i] > 0;
    }
    EXPECT_GT(with_neighbours, 250);  // the test compares real sums, not zeros
  }
}

}  // namespace
}  // namespace heliostand
