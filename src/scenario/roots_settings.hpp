#pragma once
// Scenario settings of the roots, the shared soil and the crown–root coupling (tables [roots],
// [roots.SPECIES], [roots.SPECIES.TYPE], [soil], [coupling], [[root_pruning]]; docs/formats.md).
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "coupling/coupling_parameters.hpp"
#include "roots/root_parameters.hpp"
#include "roots/soil_grid.hpp"

namespace heliostand {

// How one soil field (moisture or nutrient) starts: uniform, a linear gradient, or layers by depth.
struct SoilFieldSetting {
  enum class Kind { uniform, gradient, layers };
  Kind kind = Kind::uniform;
  double value = 1.0;                 // uniform
  int axis = 0;                       // gradient: 0 x, 1 y, 2 z
  double at_min = 1.0, at_max = 1.0;  // gradient: values on the grid's min and max faces
  std::vector<double> bottoms_m;      // layers: bottom depth of each layer (m below the surface)
  std::vector<double> values;         // layers: value of each layer
};

struct SoilSettings {
  double spacing_m = 0.5;             // voxel edge
  double depth_m = 3.0;               // grid depth below the surface (z = 0); horizontally the plot
  SoilFieldSetting moisture;          // default uniform 1.0
  SoilFieldSetting nutrient;          // default uniform 1.0 (seed 003: 0.5 poor, 1.0 rich)
  std::optional<std::filesystem::path> file;  // CSV patch of vertex values (absolute), applied after the fields
  roots::SoilRecharge recharge;
};

// Root pruning (seed 003 Fig. 14, bonsai): every non-main root of the given paths whose end lies at least
// min_depth_m deep (and min_distance_m from the collar) is cut, with what it carries.
struct RootPruningEvent {
  int line = 0;
  std::optional<int> stand_age;       // once, at the end of this stand age's root growth ...
  bool every_year = false;            // ... or every simulated year
  std::vector<int> sectors;           // paths 0..7 (empty = all paths)
  double min_depth_m = 0.0;
  double min_distance_m = 0.0;
  std::vector<std::string> tree_labels;  // survey ids (empty = every tree)
};

struct RootsSettings {
  bool enabled = true;
  std::map<std::string, roots::RootParameters> by_species;  // species without an entry: tap_rooted_conifer()
  SoilSettings soil;
  CouplingParameters coupling;
  std::vector<RootPruningEvent> pruning;

  roots::RootParameters parameters_of(const std::string& species) const {
    auto it = by_species.find(species);
    return it == by_species.end() ? roots::tap_rooted_conifer() : it->second;
  }
};

}  // namespace heliostand
