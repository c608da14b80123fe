#pragma once
// The survey's `hollow` column: the hollows of one tree in one cell, as a forester records a cavity —
// its height and the direction it faces, optionally the entrance size:
//
//   HEIGHT_M/AZIMUTH_DEG[/WIDTH_M/WOUND_HEIGHT_M]   several separated by ';', e.g. "1.4/135;3.2/300/0.08/0.15"
//
// An empty cell means no hollow. Sizes not given keep the HollowSpec defaults; with a width W given, the callus
// roll follows it: r = W/8 within [0.01, 0.015] m, I = W/4 − r within [0, 0.01] m (docs/formats.md).
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "hollow/hollow_spec.hpp"

namespace heliostand {

// The hollows in the cell, or the reason the cell cannot be read.
std::variant<std::vector<hollow::HollowSpec>, std::string> parse_hollow_cell(std::string_view cell);

}  // namespace heliostand
