#pragma once
// The plain C++ root-contact field: candidate segments from a FLANN k-d tree over segment midpoints
// (radius search with R + the longest half segment, so no segment whose nearest point is inside the
// sphere is missed), then the exact nearest-point test. Double precision; the oracle for OpenCL.
#include "roots/root_field_solver.hpp"

namespace heliostand::roots {

class ReferenceRootFieldSolver final : public RootFieldSolver {
 public:
  std::string name() const override { return "reference"; }
  std::vector<RootFieldSample> solve(const RootFieldInput& input) override;
};

// The pieces both backends share in meaning (the kernel restates them in OpenCL C).
glm::dvec3 nearest_point_on_segment(const glm::dvec3& point, const RootSegmentLine& segment);
glm::dvec3 moisture_pull(const glm::dvec3& apex, double perception_radius_m, std::span<const glm::dvec3> probes,
                         const SoilGrid& soil);

}  // namespace heliostand::roots
