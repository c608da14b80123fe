#include "io/vtk_time_series_writer.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <vtkXMLMultiBlockDataWriter.h>

#include "io/vtk_write_check.hpp"

namespace heliostand {
namespace fs = std::filesystem;

VtkTimeSeriesWriter::VtkTimeSeriesWriter(OutputFolder& folder, std::vector<StandBlock> blocks,
                                         VtkCompression compression)
    : folder_(folder), blocks_(std::move(blocks)), compression_(compression), sizes_csv_("stand_age,block,bytes\n") {}

fs::path VtkTimeSeriesWriter::year_file(int stand_age) {
  return fs::path(year_folder) / fmt::format("stand_age_{:04d}.vtm", stand_age);
}

namespace {

// VTK 9.1 leaves empty blocks out of the .vtm, and writes no .vtm at all when every block is empty
// (e.g. the year after the last tree was cut). The time step must still exist, so write an empty
// multiblock that carries the year.
std::string empty_year_vtm(const StandSnapshot& snapshot) {
  return fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt32\">\n"
      "  <vtkMultiBlockDataSet>\n  </vtkMultiBlockDataSet>\n"
      "  <FieldData>\n"
      "    <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n"
      "    <DataArray type=\"Float64\" Name=\"year_index\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n"
      "  </FieldData>\n"
      "</VTKFile>\n",
      snapshot.stand_age, snapshot.year_index);
}

// Moves `from` onto `to`, replacing whatever was there (a rewrite of the same year).
void replace_with(const fs::path& from, const fs::path& to) {
  if (fs::is_directory(to)) fs::remove_all(to);
  fs::rename(from, to);
}

// VTK's XML writers compress each piece's appended data in blocks with the chosen compressor; zlib at VTK's default
// level, as every series before run.vtk_compression was written.
void set_compressor(vtkXMLWriterBase& writer, VtkCompression compression) {
  switch (compression) {
    case VtkCompression::lz4: writer.SetCompressorTypeToLZ4(); return;
    case VtkCompression::zlib: writer.SetCompressorTypeToZLib(); return;
    case VtkCompression::none: writer.SetCompressorTypeToNone(); return;
  }
}

double megabytes(std::uintmax_t bytes) { return static_cast<double>(bytes) / 1e6; }

}  // namespace

std::vector<std::pair<std::string, std::uintmax_t>> block_file_sizes(const fs::path& vtm) {
  std::ifstream in(vtm);
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  // VTK writes each block as <DataSet index="0" name="branches" file="stand_age_0025/stand_age_0025_0.vtp">.
  static const std::regex data_set(R"re(<DataSet[^>]*\sname="([^"]*)"[^>]*\sfile="([^"]*)")re");
  std::vector<std::pair<std::string, std::uintmax_t>> sizes;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), data_set); it != std::sregex_iterator(); ++it) {
    const fs::path piece = vtm.parent_path() / (*it)[2].str();
    std::error_code error;
    const std::uintmax_t bytes = fs::file_size(piece, error);
    sizes.emplace_back((*it)[1].str(), error ? 0 : bytes);
  }
  return sizes;
}

void VtkTimeSeriesWriter::record_sizes(int stand_age, const fs::path& vtm) {
  std::uintmax_t total = fs::file_size(vtm);
  std::string per_block;
  for (const auto& [block, bytes] : block_file_sizes(vtm)) {
    total += bytes;
    per_block += fmt::format("{}{} {:.2f}", per_block.empty() ? "" : ", ", block, megabytes(bytes));
    sizes_csv_ += fmt::format("{},{},{}\n", stand_age, block, bytes);
  }
  spdlog::info("VTK stand age {}: {:.2f} MB ({} MB)", stand_age, megabytes(total), per_block);
  folder_.write_file(sizes_file, sizes_csv_);
}

fs::path VtkTimeSeriesWriter::write_year(const StandSnapshot& snapshot) {
  const fs::path relative_vtm = year_file(snapshot.stand_age);
  const fs::path final_vtm = folder_.path_of(relative_vtm);
  const fs::path final_pieces = fs::path(final_vtm).replace_extension();  // the writer's piece folder
  fs::create_directories(final_vtm.parent_path());

  // The writer names the piece folder after the .vtm and references pieces by that name, so the
  // whole year is written into a temporary folder under its final names, then moved into place:
  // pieces first, the .vtm last, so a reader never finds a .vtm whose pieces are missing.
  AtomicFile staging(final_pieces);  // temporary: stand/.stand_age_0025.tmp/ (removed if we throw)
  fs::remove_all(staging.temporary_path());
  fs::create_directories(staging.temporary_path());
  const fs::path staged_vtm = staging.temporary_path() / final_vtm.filename();

  auto writer = vtkSmartPointer<vtkXMLMultiBlockDataWriter>::New();
  writer->SetFileName(staged_vtm.string().c_str());
  writer->SetInputData(build_stand_multiblock(snapshot, blocks_));
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  set_compressor(*writer, compression_);
  write_checked(*writer, final_vtm);

  if (!fs::exists(staged_vtm)) write_whole_file(staged_vtm, empty_year_vtm(snapshot), final_vtm);

  const fs::path staged_pieces = staging.temporary_path() / final_pieces.filename();
  if (fs::exists(staged_pieces)) replace_with(staged_pieces, final_pieces);
  fs::rename(staged_vtm, final_vtm);
  fs::remove_all(staging.temporary_path());

  folder_.record_output(relative_vtm);
  if (fs::exists(final_pieces)) {
    std::vector<fs::path> pieces;
    for (const fs::directory_entry& piece : fs::directory_iterator(final_pieces)) pieces.push_back(piece.path());
    std::sort(pieces.begin(), pieces.end());  // directory order is arbitrary; run.json should not be
    for (const fs::path& piece : pieces) folder_.record_output(fs::relative(piece, folder_.root()));
  }

  record_sizes(snapshot.stand_age, final_vtm);
  collection_.add(snapshot.stand_age, relative_vtm.generic_string());
  folder_.write_file(collection_file, collection_.to_xml());
  return relative_vtm;
}

}  // namespace heliostand
