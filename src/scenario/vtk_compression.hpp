#pragma once
// How the yearly VTK pieces are compressed (scenario key `run.vtk_compression`, docs/formats.md "Compression"):
//   lz4   fast: the example's output stage in a third of zlib's time, its files about 1.5 times zlib's
//   zlib  the smallest files (VTK's default level, as every series before this key), for archives and slow disks
//   none  raw binary, as quick to write as lz4, about three times zlib's files
// VTK's readers (LZ4 since VTK 8.0) and so ParaView read all three; each piece names its compressor in its header.
#include <string_view>

#include "core/named_choice.hpp"

namespace heliostand {

enum class VtkCompression { lz4, zlib, none };

// Compression was most of the example's output stage and a third of its run with zlib (docs/performance.md,
// "The VTK series compressed with LZ4").
inline constexpr VtkCompression default_vtk_compression = VtkCompression::lz4;

inline constexpr NamedChoices<VtkCompression, 3> vtk_compression_names{
    {{VtkCompression::lz4, "lz4"}, {VtkCompression::zlib, "zlib"}, {VtkCompression::none, "none"}}};

constexpr std::string_view name_of(VtkCompression compression) { return name_in(vtk_compression_names, compression); }

}  // namespace heliostand
