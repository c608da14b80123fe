#pragma once
// Writes the stand as a ParaView time series: one multiblock file per output year
// (stand/stand_age_0025.vtm + its piece folder stand/stand_age_0025/) and the index stand.pvd,
// rewritten after every year so a run that stops early can still be opened. The bytes each block took in each
// year are logged and kept in vtk_sizes.csv (stand_age,block,bytes), rewritten with stand.pvd.
#include <filesystem>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/output_folder.hpp"
#include "io/pvd_collection.hpp"
#include "io/vtk_stand_blocks.hpp"
#include "records/stand_snapshot.hpp"
#include "scenario/vtk_compression.hpp"

namespace heliostand {

class VtkTimeSeriesWriter {
 public:
  static constexpr const char* collection_file = "stand.pvd";
  static constexpr const char* year_folder = "stand";
  static constexpr const char* sizes_file = "vtk_sizes.csv";

  explicit VtkTimeSeriesWriter(OutputFolder& folder, std::vector<StandBlock> blocks = default_stand_blocks(),
                               VtkCompression compression = default_vtk_compression);

  // Adds a block to every year written from now on (e.g. roots, soil).
  void add_block(StandBlock block) { blocks_.push_back(std::move(block)); }

  // Writes the year's multiblock and rewrites stand.pvd. Returns the .vtm path relative to the folder.
  std::filesystem::path write_year(const StandSnapshot& snapshot);

  // "stand/stand_age_0025.vtm" for stand age 25.
  static std::filesystem::path year_file(int stand_age);

 private:
  void record_sizes(int stand_age, const std::filesystem::path& vtm);
  friend struct checkpoint::Access;

  OutputFolder& folder_;
  std::vector<StandBlock> blocks_;
  VtkCompression compression_;
  PvdCollection collection_;
  std::string sizes_csv_;  // vtk_sizes.csv so far
};

// The bytes of each block's piece file of a written year, in the .vtm's order: {block name, bytes}.
std::vector<std::pair<std::string, std::uintmax_t>> block_file_sizes(const std::filesystem::path& vtm);

}  // namespace heliostand
