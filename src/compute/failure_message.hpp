#pragma once
// What a user reads of a failure that stops a run (`error: ...`, exit 1). An OpenCL call that fails throws
// cl::Error, whose own text is the call's name alone ("clCreateBuffer"): the message adds the error's name and code,
// and for a device out of memory what to do about it. Out of host memory is said in words; any other failure is its
// own text. This header needs no OpenCL headers.
#include <exception>
#include <string>

namespace heliostand::compute {

std::string failure_message(const std::exception& failure);

}  // namespace heliostand::compute
