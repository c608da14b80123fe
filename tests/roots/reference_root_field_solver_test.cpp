// The reference root-contact field (the oracle) answers a query's apices on the worker threads. Each apex's
// contacts and moisture pull must be what one thread computes, bit for bit, on any number of threads.
#include "roots/reference_root_field_solver.hpp"

#include <gtest/gtest.h>

#include "core/parallel_for.hpp"
#include "grown_root_stand.hpp"

namespace heliostand::roots {
namespace {

class ReferenceRootFieldThreads : public ::testing::Test {
 protected:
  ~ReferenceRootFieldThreads() override { set_worker_threads(0); }
};

TEST_F(ReferenceRootFieldThreads, TheSameFieldOnAnyNumberOfThreads) {
  test_stands::GrownStand stand = test_stands::grown_stand(8, 3);
  const test_stands::ApexQueries queries = test_stands::apices_at_every_segment_end(stand, 3);
  ASSERT_GT(queries.tips.size(), 8 * 64u) << "several blocks of apices";
  const RootFieldInput input = queries.input(stand.soil);
  set_worker_threads(1);
  ReferenceRootFieldSolver solver;
  const std::vector<RootFieldSample> in_order = solver.solve(input);
  int with_contacts = 0;
  for (const RootFieldSample& sample : in_order) with_contacts += sample.contacts > 0 ? 1 : 0;
  ASSERT_GT(with_contacts, int(in_order.size()) / 2) << "apices that feel their neighbours";
  for (unsigned threads : {2u, 3u, 8u}) {
    set_worker_threads(threads);
    const std::vector<RootFieldSample> samples = solver.solve(input);
    ASSERT_EQ(samples.size(), in_order.size());
    int differing = 0;
    for (std::size_t t = 0; t < samples.size(); ++t)
      differing += samples[t].contacts != in_order[t].contacts ||
                   samples[t].contact_avoidance != in_order[t].contact_avoidance ||
                   samples[t].moisture_pull != in_order[t].moisture_pull;
    EXPECT_EQ(differing, 0) << threads << " threads";
  }
}

}  // namespace
}  // namespace heliostand::roots
