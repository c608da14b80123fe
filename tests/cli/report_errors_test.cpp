// Every command's last catch (cli/report_errors.cpp): a failure while running is said in words (compute/
// failure_message.hpp) with exit status 1. Before, an OpenCL call out of device memory printed "error: clCreateBuffer".
#include <gtest/gtest.h>

#include <new>
#include <string>

#include "cli/commands.hpp"

#ifdef HELIOSTAND_HAVE_OPENCL
#include <CL/opencl.hpp>
#endif

namespace heliostand::cli {
namespace {

// What report_errors prints to stderr for `failure`, and its exit status.
template <class Failure>
std::pair<int, std::string> reported(const Failure& failure) {
  ::testing::internal::CaptureStderr();
  const int status = report_errors([&]() -> int { throw failure; });
  return {status, ::testing::internal::GetCapturedStderr()};
}

TEST(ReportErrors, OutOfHostMemoryIsSaidInWordsWithExitOne) {
  const auto [status, said] = reported(std::bad_alloc());
  EXPECT_EQ(status, 1);
  EXPECT_EQ(said, "error: out of memory (std::bad_alloc): the run needs more than this machine lets it use\n");
}

#ifdef HELIOSTAND_HAVE_OPENCL
TEST(ReportErrors, AnOpenCLCallThatFailedIsNamedWithItsErrorAndExitOne) {
  const auto [status, said] = reported(cl::Error(CL_MEM_OBJECT_ALLOCATION_FAILURE, "clCreateBuffer"));
  EXPECT_EQ(status, 1);
  EXPECT_EQ(said.rfind("error: the OpenCL call clCreateBuffer failed: CL_MEM_OBJECT_ALLOCATION_FAILURE (-4), the "
                       "device lacks the memory for it",
                       0),
            0u)
      << said;
}
#endif

}  // namespace
}  // namespace heliostand::cli
