#include "light/make_light_solver.hpp"

#include "light/reference_light_solver.hpp"
#ifdef HELIOSTAND_HAVE_OPENCL
#include "light/opencl_light_solver.hpp"
#endif

namespace heliostand {

std::unique_ptr<LightSolver> make_light_solver([[maybe_unused]] const compute::ComputeBackend& backend,
                                               const LightParameters& parameters) {
#ifdef HELIOSTAND_HAVE_OPENCL
  if (backend.is_opencl()) return std::make_unique<OpenCLLightSolver>(parameters, *backend.opencl());
#endif
  return std::make_unique<ReferenceLightSolver>(parameters);
}

}  // namespace heliostand
