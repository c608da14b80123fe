#include "core/parallel_for.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace heliostand {
namespace {

// Restores the hardware's count after each test, whatever it chose.
struct ParallelFor : ::testing::Test {
  ~ParallelFor() override { set_worker_threads(0); }
};

TEST_F(ParallelFor, VisitsEveryIndexOnceOnAnyNumberOfThreads) {
  for (unsigned threads : {1u, 2u, 5u}) {
    set_worker_threads(threads);
    EXPECT_EQ(worker_threads(), threads);
    std::vector<std::atomic<int>> visits(1000);
    parallel_for(visits.size(), [&](std::size_t i) { ++visits[i]; });
    for (std::size_t i = 0; i < visits.size(); ++i) ASSERT_EQ(visits[i].load(), 1) << i << " on " << threads;
  }
}

TEST_F(ParallelFor, BlocksCoverEveryIndexOnceWithTheLastBlockShort) {
  for (unsigned threads : {1u, 2u, 5u}) {
    set_worker_threads(threads);
    for (std::size_t block : {1u, 7u, 64u, 5000u}) {
      std::vector<std::atomic<int>> visits(1000);
      parallel_for_blocks(visits.size(), block, [&](std::size_t first, std::size_t last) {
        ASSERT_LT(first, last);
        ASSERT_LE(last - first, block);
        for (std::size_t i = first; i < last; ++i) ++visits[i];
      });
      for (std::size_t i = 0; i < visits.size(); ++i)
        ASSERT_EQ(visits[i].load(), 1) << i << " in blocks of " << block << " on " << threads;
    }
  }
  parallel_for_blocks(0, 8, [](std::size_t, std::size_t) { FAIL() << "a block of nothing"; });
}

TEST_F(ParallelFor, ZeroMeansTheHardwaresCount) {
  set_worker_threads(0);
  EXPECT_EQ(worker_threads(), std::max(1u, std::thread::hardware_concurrency()));
}

TEST_F(ParallelFor, AFailureInOneIterationReachesTheCaller) {
  set_worker_threads(3);
  EXPECT_THROW(parallel_for(100, [](std::size_t i) { if (i == 42) throw std::runtime_error("tree 42"); }),
               std::runtime_error);
}

}  // namespace
}  // namespace heliostand
