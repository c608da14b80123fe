#pragma once
// Which stems stand near which: a 2-D k-d tree (FLANN KDTreeSingleIndex, deterministic) over stem positions, for
// competition indices (stand/hegyi_index.hpp), crop-tree release and finding planting rows.
//
// Plot edges. A simulated plot is a piece of a larger stand, and a tree near its edge has neighbours outside it
// that are not simulated. Two treatments (docs/model.md "Neighbourhoods and the Hegyi index"):
//   periodic  the plot is one tile of an endless stand of copies of itself; a distance is taken to the nearest
//             copy of the other stem (the minimum-image rule), so every stem sees a full neighbourhood;
//   buffered  only simulated stems count: the plot is taken to sit in a buffer of stand that is not modelled,
//             and a stem within the search radius of the edge sees fewer neighbours than it has.
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "geometry/plot_bounds.hpp"

namespace heliostand {

struct StandEdges {
  bool periodic = false;
  PlotBounds domain;  // the repeating tile when periodic (its width and depth are the periods)
};

struct Neighbour {
  std::size_t stem = 0;  // index into the positions the neighbourhood was built from
  double distance_m = 0;
};

class Neighbourhood {
 public:
  Neighbourhood(std::span<const glm::dvec2> positions, StandEdges edges);
  ~Neighbourhood();
  Neighbourhood(const Neighbourhood&) = delete;
  Neighbourhood& operator=(const Neighbourhood&) = delete;

  std::size_t size() const { return positions_.size(); }
  const StandEdges& edges() const { return edges_; }

  // Every other stem closer than `radius_m` to stem `stem`, each once (at its nearest copy when periodic), by
  // stem index.
  std::vector<Neighbour> within(std::size_t stem, double radius_m) const;
  // The closest other stem; none when the stem stands alone.
  std::optional<Neighbour> nearest(std::size_t stem) const;
  // Distance between two stems under the edge treatment.
  double distance(std::size_t a, std::size_t b) const;

 private:
  struct Index;
  std::vector<glm::dvec2> positions_;
  StandEdges edges_;
  std::vector<double> coordinates_;      // row-major points x 2: the stems and, when periodic, their 8 copies;
                                         // owned here because FLANN keeps a pointer
  std::vector<std::size_t> stem_of_point_;
  std::unique_ptr<Index> index_;
};

}  // namespace heliostand
