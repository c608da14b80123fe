#pragma once
// The root-contact field (seed 003): for every growing root apex, what its root cap perceives inside
// its perception sphere —
//   contact avoidance  Vt = −Σ unit(direction from the apex to each other root segment in the sphere)
//   moisture pull      Vw =  Σ unit(probe_k) · moisture(apex + R · probe_k)   over the K probes
// computed for the roots of ALL trees at once. Two implementations (the OpenMM pattern, as for light):
// ReferenceRootFieldSolver, plain C++ and the oracle, and OpenCLRootFieldSolver (float on the device);
// make_root_field_solver() (roots/make_root_field_solver.hpp) picks the one of the run's compute backend.
// The probe directions are inputs, drawn on the host, so both backends see the same probes.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "roots/soil_grid.hpp"

namespace heliostand::roots {

struct RootSegmentLine {
  glm::dvec3 start{0.0};
  glm::dvec3 end{0.0};
};

struct RootTipQuery {
  glm::dvec3 position{0.0};            // the apex (end of the segment it grows from)
  double perception_radius_m = 0.2;    // R
  int excluded[2] = {-1, -1};          // segment indices it does not feel: its own segment and its parent
};

// The segments of one year's field seen as ONE indexed list without copying them: the trees' own segment lists
// (or any lists of start/end pairs) one after another. Segment i of the list is entry i − first(part) of its part.
// The lists must outlive every query of the year (they do: the trees change only after all queries).
class SegmentList {
 public:
  SegmentList() = default;
  SegmentList(std::span<const RootSegmentLine> lines) { append(lines); }  // NOLINT: a span of lines is a list

  // Any list whose elements have `glm::dvec3 start, end` (RootSegmentLine, RootSegment).
  template <class Segment>
  void append(std::span<const Segment> part) {
    parts_.push_back({part.empty() ? nullptr : reinterpret_cast<const std::byte*>(&part.front().start),
                      part.empty() ? nullptr : reinterpret_cast<const std::byte*>(&part.front().end), sizeof(Segment),
                      size_, part.size()});
    size_ += part.size();
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t part_count() const { return parts_.size(); }
  std::size_t first_of_part(std::size_t part) const { return parts_.at(part).first; }
  RootSegmentLine operator[](std::size_t i) const;
  // Half the length of the longest segment (0 for none): how far past a query's reach a segment's midpoint may lie
  // while its nearest point lies within it.
  double longest_half_m() const;
  // Visits every segment in order, (index, start, end), without the per-index part search of operator[].
  template <class Visit>
  void for_each(Visit&& visit) const {
    for (std::size_t part = 0; part < parts_.size(); ++part) for_each_of_part(part, visit);
  }
  // The same for one part's segments only (the parts are disjoint: one thread per part visits every segment once).
  template <class Visit>
  void for_each_of_part(std::size_t part, Visit&& visit) const {
    const Part& p = parts_[part];
    for (std::size_t j = 0; j < p.count; ++j) visit(p.first + j, at(p.start, p.stride, j), at(p.end, p.stride, j));
  }

 private:
  struct Part {
    const std::byte* start;  // the first element's `start`
    const std::byte* end;    // the first element's `end`
    std::size_t stride;      // bytes from one element to the next
    std::size_t first;       // index of the part's first segment in the whole list
    std::size_t count;
  };
  static const glm::dvec3& at(const std::byte* first, std::size_t stride, std::size_t j) {
    return *reinterpret_cast<const glm::dvec3*>(first + j * stride);
  }
  std::vector<Part> parts_;
  std::size_t size_ = 0;
};

// What every query of one year feels: the roots as they stood at the start of the year, and the soil.
struct RootFieldYear {
  SegmentList segments;                     // every living root segment of the stand
  const SoilGrid* soil = nullptr;           // none: the moisture pull is zero
  // The widest perception radius of the year's queries. It sizes the OpenCL solver's grid cells (so it must be the
  // same, and it is, whether the year's tips come in one query or in many); a wider query is still answered exactly.
  double widest_perception_radius_m = 0.0;
};

// One call's worth of everything at once (tests, benchmarks): solve() = begin_year() + one query().
struct RootFieldInput {
  std::span<const RootSegmentLine> segments;  // every living root segment of the stand
  std::span<const RootTipQuery> tips;
  std::span<const glm::dvec3> probes;         // probes_per_tip offsets per tip, in units of R (|p| <= 1)
  int probes_per_tip = 0;
  const SoilGrid* soil = nullptr;             // none: the moisture pull is zero
};

struct RootFieldSample {
  glm::dvec3 contact_avoidance{0.0};  // Vt before normalisation
  int contacts = 0;                   // segments felt (distance to their nearest point < R)
  glm::dvec3 moisture_pull{0.0};      // Vw before normalisation
};

// Segments nearer than this to the apex give no direction and are not counted (cl/roots.cl gets this value as
// the build option TOUCHING_DISTANCE).
inline constexpr double touching_distance_m = 1e-5;

class RootFieldSolver {
 public:
  virtual ~RootFieldSolver() = default;
  virtual std::string name() const = 0;  // "reference" or "opencl:<device>"
  // Once a year: indexes the segments (and, on a device, uploads them and the soil's moisture) for all the
  // year's queries. Nothing of the segments is copied beyond what the index needs (docs/performance.md).
  virtual void begin_year(const RootFieldYear& year) = 0;
  // One sample per tip, in the order given, against the year begun last; `probes` holds probes_per_tip offsets
  // per tip. Any number of queries per year: a tip's answer does not depend on which other tips share its query.
  virtual std::vector<RootFieldSample> query(std::span<const RootTipQuery> tips, std::span<const glm::dvec3> probes,
                                             int probes_per_tip) = 0;
  // After the year's last query: the year is over (a query before the next begin_year() is an error). The reference
  // frees its index; the OpenCL solver keeps its device buffers, room for the next year's field written anew (a
  // buffer made anew each year is as many fresh pages: docs/performance.md "The root-contact field's buffers kept
  // from one year to the next, where fresh pages are dear").
  virtual void end_year() = 0;
  // Everything at once: begin_year() with the widest R of the tips, one query, end_year().
  std::vector<RootFieldSample> solve(const RootFieldInput& input);
};

}  // namespace heliostand::roots
