#pragma once
// The plain C++ root-contact field: candidate segments from a FLANN k-d tree over segment midpoints
// (radius search with R + the longest half segment, so no segment whose nearest point is inside the
// sphere is missed), then the exact nearest-point test. Double precision; the oracle for OpenCL.
// The k-d tree is built once a year (begin_year) and serves every query of that year; a query's apices share the
// worker threads (core/parallel_for.hpp), each summed as on one thread.
#include <memory>

#include "roots/root_field_solver.hpp"

namespace heliostand::roots {

class ReferenceRootFieldSolver final : public RootFieldSolver {
 public:
  ReferenceRootFieldSolver();
  ~ReferenceRootFieldSolver() override;
  std::string name() const override { return "reference"; }
  void begin_year(const RootFieldYear& year) override;
  std::vector<RootFieldSample> query(std::span<const RootTipQuery> tips, std::span<const glm::dvec3> probes,
                                     int probes_per_tip) override;
  void end_year() override;

 private:
  struct Index;
  static constexpr std::size_t apices_per_block = 64;  // an apex alone is too little work to hand to a thread
  RootFieldSample with_contacts(const RootTipQuery& tip, RootFieldSample sample) const;
  RootFieldYear year_;
  std::unique_ptr<Index> index_;  // none while the year has no segments
};

// The pieces both backends share in meaning (the kernel restates them in OpenCL C).
glm::dvec3 nearest_point_on_segment(const glm::dvec3& point, const RootSegmentLine& segment);
glm::dvec3 moisture_pull(const glm::dvec3& apex, double perception_radius_m, std::span<const glm::dvec3> probes,
                         const SoilGrid& soil);

}  // namespace heliostand::roots
