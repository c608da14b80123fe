#include "roots/make_root_field_solver.hpp"

#include "roots/reference_root_field_solver.hpp"
#ifdef HELIOSTAND_HAVE_OPENCL
#include "roots/opencl_root_field.hpp"
#endif

namespace heliostand::roots {

std::unique_ptr<RootFieldSolver> make_root_field_solver([[maybe_unused]] const compute::ComputeBackend& backend) {
#ifdef HELIOSTAND_HAVE_OPENCL
  if (backend.is_opencl()) return std::make_unique<OpenCLRootFieldSolver>(*backend.opencl());
#endif
  return std::make_unique<ReferenceRootFieldSolver>();
}

}  // namespace heliostand::roots
