#pragma once
// Soil vertex values from a CSV file (docs/roots.md, "Soil"):
//
//   # comments and blank lines are ignored
//   i,j,k,moisture,nutrient
//   0,0,0,0.80,0.50
//
// i, j, k are vertex indices (0 .. cells along that axis); the value columns present (moisture and/or
// nutrient, any order) overwrite those vertices (value and capacity); vertices not listed keep the grid's current value, so a
// file can patch a uniform or layered start. Every problem in the file is reported at once as an
// InputError ("soil.csv:7: column 'moisture': expected a number >= 0, got \"wet\"").
#include <filesystem>
#include <iosfwd>
#include <string>

#include "roots/soil_grid.hpp"

namespace heliostand::roots {

void read_soil_csv(const std::filesystem::path& path, SoilGrid& soil);
// The same from an open stream; `file_name` is used in messages.
void read_soil_csv(std::istream& in, const std::string& file_name, SoilGrid& soil);

}  // namespace heliostand::roots
