#include "scenario/vtk_compression.hpp"

namespace heliostand {

std::string_view name_of(VtkCompression compression) {
  switch (compression) {
    case VtkCompression::lz4: return "lz4";
    case VtkCompression::zlib: return "zlib";
    case VtkCompression::none: return "none";
  }
  return "lz4";
}

std::optional<VtkCompression> parse_vtk_compression(std::string_view text) {
  for (VtkCompression compression : {VtkCompression::lz4, VtkCompression::zlib, VtkCompression::none})
    if (text == name_of(compression)) return compression;
  return std::nullopt;
}

}  // namespace heliostand
