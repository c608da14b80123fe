#pragma once
// A tree leaving the living stand: taken out by thinning or killed by mortality. One row of events.csv;
// the removals and deaths also feed the removed_* and dead_* columns of stand_table.csv.
#include <string>
#include <string_view>

namespace heliostand {

enum class TreeEventKind { removed, died };

constexpr std::string_view to_string(TreeEventKind kind) {
  return kind == TreeEventKind::removed ? "removed" : "died";
}

// The cause code of every removal: a scheduled thinning is the only way trees are taken out. Deaths carry
// their cause's code (stand/mortality.hpp: light, suppression, background).
inline constexpr std::string_view thinning_cause = "thinning";

struct TreeEvent {
  int stand_age = 0;         // years: stand age in the year the event happened
  int tree_id = 0;
  std::string label;         // survey id of the tree
  std::string species;       // the tree's species (its [species.NAME] in the scenario)
  TreeEventKind kind = TreeEventKind::removed;
  // Why, twice: `cause` is a fixed code to group by (thinning_cause or a death cause), `reason` the words of
  // whoever decided it (a thinning's scenario `reason`, e.g. "first thinning"; a death repeats its code).
  std::string cause;
  std::string reason;
  double dbh_cm = 0;         // at the moment of the event
  double height_m = 0;
  double volume_m3 = 0;      // stem volume
};

}  // namespace heliostand
