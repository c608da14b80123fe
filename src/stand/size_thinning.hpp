#pragma once
// Thinning by size (methods from_below, from_above, neutral) to a target: a density (stems/ha), a basal area
// (m²/ha), or a fraction of the living stems or basal area.
//   from_below  removes unprotected trees smallest DBH first until the target is met;
//   from_above  largest first;
//   neutral     evenly across the DBH distribution so that it keeps its shape: of the m unprotected trees ranked
//               by DBH (smallest first, ties in survey order), removing n takes the ranks ⌊(i + ½)·m/n⌋,
//               i = 0 … n−1 — one tree from the middle of each of n equal slices of the ranking. A basal-area
//               target takes the smallest n whose trees bring the stand down to it.
// Stem targets count every living tree (protected ones too): a stems/ha target keeps floor(target × area) trees,
// a fraction f removes round(f × living stems). A basal-area fraction g leaves at most (1 − g) of the living basal
// area. Protected trees are never removed; a target that needs them removes what it can.
#include <cstddef>
#include <vector>

#include "stand/thinning.hpp"

namespace heliostand {

std::vector<std::size_t> select_by_size(const ThinningRule& rule, const std::vector<ThinningCandidate>& living,
                                        double plot_area_ha);

// The ranks (0-based, ascending) a neutral thinning takes when it removes `count` of `out_of` ranked trees.
std::vector<std::size_t> neutral_ranks(std::size_t count, std::size_t out_of);

}  // namespace heliostand
