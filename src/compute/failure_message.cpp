#include "compute/failure_message.hpp"

#include <new>

#include <fmt/format.h>

#ifdef HELIOSTAND_HAVE_OPENCL
#include <CL/opencl.hpp>
#endif

namespace heliostand::compute {
namespace {

#ifdef HELIOSTAND_HAVE_OPENCL
// The OpenCL errors a run can meet once its kernels are built (a build failure has its own message: the build log).
const char* opencl_error_name(cl_int code) {
  switch (code) {
    case CL_DEVICE_NOT_AVAILABLE: return "CL_DEVICE_NOT_AVAILABLE";
    case CL_MEM_OBJECT_ALLOCATION_FAILURE: return "CL_MEM_OBJECT_ALLOCATION_FAILURE";
    case CL_OUT_OF_RESOURCES: return "CL_OUT_OF_RESOURCES";
    case CL_OUT_OF_HOST_MEMORY: return "CL_OUT_OF_HOST_MEMORY";
    case CL_INVALID_BUFFER_SIZE: return "CL_INVALID_BUFFER_SIZE";
    case CL_INVALID_WORK_GROUP_SIZE: return "CL_INVALID_WORK_GROUP_SIZE";
    case CL_INVALID_COMMAND_QUEUE: return "CL_INVALID_COMMAND_QUEUE";
    default: return "an OpenCL error";
  }
}

// A buffer the device could not allocate (CL_OUT_OF_RESOURCES is left out: on some GPUs it also reports a kernel
// that failed).
bool out_of_device_memory(cl_int code) {
  return code == CL_MEM_OBJECT_ALLOCATION_FAILURE || code == CL_INVALID_BUFFER_SIZE;
}

std::string opencl_failure_message(const cl::Error& failure) {
  std::string message = fmt::format("the OpenCL call {} failed: {} ({})", failure.what(),
                                    opencl_error_name(failure.err()), failure.err());
  if (out_of_device_memory(failure.err()))
    message += ", the device lacks the memory for it: lower light.far_field_table_mb (the far field's largest "
               "buffers), grow the stand in parts, or choose another device (--device, `heliostand devices`)";
  return message;
}
#endif

}  // namespace

std::string failure_message(const std::exception& failure) {
#ifdef HELIOSTAND_HAVE_OPENCL
  if (const auto* opencl = dynamic_cast<const cl::Error*>(&failure)) return opencl_failure_message(*opencl);
#endif
  if (dynamic_cast<const std::bad_alloc*>(&failure) != nullptr)
    return fmt::format("out of memory ({}): the run needs more than this machine lets it use", failure.what());
  return failure.what();
}

}  // namespace heliostand::compute
