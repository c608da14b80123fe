#pragma once
// Candidates for the thinning rules' tests.
#include <string>
#include <vector>

#include "stand/thinning.hpp"

namespace heliostand::testing {

// Ten trees "t0" .. "t9", tree k of DBH 10 + 2k cm (10, 12, ..., 28 cm), none protected.
inline std::vector<ThinningCandidate> ten_trees() {
  std::vector<ThinningCandidate> trees;
  for (int i = 0; i < 10; ++i) trees.push_back({"t" + std::to_string(i), 10.0 + 2.0 * i, false});
  return trees;
}

}  // namespace heliostand::testing
