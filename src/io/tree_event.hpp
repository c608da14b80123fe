#pragma once
// A tree leaving the living stand: taken out by thinning or killed by mortality. One row of events.csv;
// the removals also feed the removed_* columns of stand_table.csv.
#include <string>
#include <string_view>

namespace heliostand {

enum class TreeEventKind { removed, died };

constexpr std::string_view to_string(TreeEventKind kind) {
  return kind == TreeEventKind::removed ? "removed" : "died";
}

struct TreeEvent {
  int stand_age = 0;         // years: stand age in the year the event happened
  int tree_id = 0;
  std::string label;         // survey id of the tree
  TreeEventKind kind = TreeEventKind::removed;
  std::string reason;        // e.g. "thinning:low", "suppression", "windthrow" (free text, documented by its producer)
  double dbh_cm = 0;         // at the moment of the event
  double height_m = 0;
  double volume_m3 = 0;      // stem volume
};

}  // namespace heliostand
