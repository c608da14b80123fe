// The stage clock's two measures: wall time (run.json) and the process's CPU time (`bench stand`), whose ratio says
// how many cores a stage kept busy. A stage that waits uses wall time and no CPU; a stage that computes uses CPU.
// No speed is asserted: the work below is measured by the clock it runs under, not against a deadline.
#include <gtest/gtest.h>

#include <chrono>
#include <ctime>
#include <thread>

#include "stand/stage_clock.hpp"

namespace heliostand {
namespace {

double thread_cpu_seconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// Computes until this thread has used `seconds` of CPU (however long that takes on a loaded machine).
void burn_cpu(double seconds) {
  const double until = thread_cpu_seconds() + seconds;
  volatile double sink = 1.0;
  while (thread_cpu_seconds() < until) sink = sink * 1.0000001 + 1e-9;
}

TEST(StageClock, AWaitingStageTakesWallTimeAndNoCpu) {
  StageClock clock;
  clock.time("waiting", [] { std::this_thread::sleep_for(std::chrono::milliseconds(100)); return 0; });
  EXPECT_GE(clock.seconds("waiting"), 0.1);
  EXPECT_LT(clock.cpu_seconds("waiting"), 0.05) << "asleep, the process used next to no CPU";
}

TEST(StageClock, AComputingStageTakesCpuTime) {
  StageClock clock;
  clock.time("computing", [] { burn_cpu(0.1); return 0; });
  EXPECT_GE(clock.cpu_seconds("computing"), 0.1);
  EXPECT_GE(clock.seconds("computing"), 0.09) << "one thread's CPU second takes at least a wall second";
}

// Each stage adds up over its calls, apart from the others, in the order the stages first ran; the CPU seconds of
// every thread of the process count, as a stage's worker threads' do.
TEST(StageClock, StagesAddUpApartAndCountEveryThread) {
  StageClock clock;
  for (int call = 0; call < 2; ++call) {
    clock.time("two threads", [] {
      std::thread other([] { burn_cpu(0.05); });
      burn_cpu(0.05);
      other.join();
      return 0;
    });
    clock.time("asleep", [] { std::this_thread::sleep_for(std::chrono::milliseconds(20)); return 0; });
  }
  ASSERT_EQ(clock.cpu_stages().size(), 2u);
  EXPECT_EQ(clock.cpu_stages()[0].first, "two threads");
  EXPECT_EQ(clock.cpu_stages()[1].first, "asleep");
  EXPECT_GE(clock.cpu_seconds("two threads"), 0.2) << "two calls, two threads, 0.05 s of CPU each";
  EXPECT_LT(clock.cpu_seconds("asleep"), 0.03);
  EXPECT_GE(clock.seconds("asleep"), 0.04);
  EXPECT_EQ(clock.cpu_seconds("never run"), 0.0);
}

}  // namespace
}  // namespace heliostand
