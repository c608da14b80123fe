#pragma once
// A hollow a surveyed tree carries (habitat tree), and where the user gave it, so that a hollow the
// trunk cannot hold is reported at its own line and field (survey column 'hollow' or scenario key
// 'hollow[2]'). The geometry itself is hollow::HollowSpec (docs/hollows.md).
#include <string>

#include "hollow/hollow_spec.hpp"

namespace heliostand {

struct TreeHollow {
  hollow::HollowSpec spec;
  bool seed_given = false;  // otherwise derived from the run seed, the tree and the hollow's index
  std::string file;         // where it was written
  int line = 0;
  std::string field;        // survey column as written in the header, or scenario key path "hollow[2]"
  std::string field_kind;   // "column" or "key"
};

}  // namespace heliostand
