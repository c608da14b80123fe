#pragma once
// What became of a tree, as written to trees.csv (text) and to the VTK `trees` block (integer code).
#include <string_view>

namespace heliostand {

// The integer values are part of the output format (docs/formats.md): never renumber them.
enum class TreeStatus : int {
  alive = 0,    // standing and living
  dead = 1,     // died (mortality) and still standing in the stand
  removed = 2,  // taken out by thinning in this output year
};

constexpr std::string_view to_string(TreeStatus status) {
  switch (status) {
    case TreeStatus::alive: return "alive";
    case TreeStatus::dead: return "dead";
    case TreeStatus::removed: return "removed";
  }
  return "unknown";
}

constexpr int status_code(TreeStatus status) { return static_cast<int>(status); }

}  // namespace heliostand
