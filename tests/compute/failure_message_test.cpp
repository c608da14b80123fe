// What a user reads of a failure that stops a run (compute/failure_message.hpp). An OpenCL call said only its own
// name ("error: clCreateBuffer", a far-field table larger than the machine's memory); now the error's name, its code
// and, for a device out of memory, what to lower.
#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <string>

#include "compute/failure_message.hpp"

#ifdef HELIOSTAND_HAVE_OPENCL
#include <CL/opencl.hpp>
#endif

namespace heliostand::compute {
namespace {

TEST(FailureMessage, AnyOtherFailureIsItsOwnText) {
  EXPECT_EQ(failure_message(std::runtime_error("cannot write trees.csv: No space left on device")),
            "cannot write trees.csv: No space left on device");
}

TEST(FailureMessage, OutOfHostMemoryIsSaidInWords) {
  EXPECT_EQ(failure_message(std::bad_alloc()),
            "out of memory (std::bad_alloc): the run needs more than this machine lets it use");
}

#ifdef HELIOSTAND_HAVE_OPENCL
TEST(FailureMessage, AnOpenCLCallOutOfDeviceMemorySaysWhatToLower) {
  const std::string allocation = failure_message(cl::Error(CL_MEM_OBJECT_ALLOCATION_FAILURE, "clCreateBuffer"));
  EXPECT_EQ(allocation.rfind("the OpenCL call clCreateBuffer failed: CL_MEM_OBJECT_ALLOCATION_FAILURE (-4), the "
                             "device lacks the memory for it: lower light.far_field_table_mb",
                             0),
            0u)
      << allocation;
  const std::string size = failure_message(cl::Error(CL_INVALID_BUFFER_SIZE, "clCreateBuffer"));
  EXPECT_NE(size.find("CL_INVALID_BUFFER_SIZE (-61), the device lacks the memory"), std::string::npos) << size;
}

TEST(FailureMessage, AnyOtherOpenCLFailureNamesTheCallAndTheCode) {
  EXPECT_EQ(failure_message(cl::Error(CL_OUT_OF_RESOURCES, "clEnqueueReadBuffer")),
            "the OpenCL call clEnqueueReadBuffer failed: CL_OUT_OF_RESOURCES (-5)");
  EXPECT_EQ(failure_message(cl::Error(-9999, "clFinish")), "the OpenCL call clFinish failed: an OpenCL error (-9999)");
}
#endif

}  // namespace
}  // namespace heliostand::compute
