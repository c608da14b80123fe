#include "io/stand_output.hpp"

#include <cerrno>
#include <optional>

#include <fmt/format.h>

#include "io/stand_tables.hpp"

namespace heliostand {

StandOutput::Table::Table(const std::filesystem::path& final_path, std::optional<std::uint64_t> resume_at)
    : file(final_path), csv(stream) {
  if (resume_at) {
    // A run that stopped on an error (not killed) renamed its tables into place, without run.json: take them back.
    if (!std::filesystem::exists(file.temporary_path()) && std::filesystem::exists(file.final_path()))
      std::filesystem::rename(file.final_path(), file.temporary_path());
    std::filesystem::resize_file(file.temporary_path(), *resume_at);  // resume_tables() checked the length
  }
  errno = 0;
  stream.open(file.temporary_path(), resume_at ? std::ios::app : std::ios::trunc);
  if (!stream) throw cannot_write(file.final_path(), errno);
}

void StandOutput::Table::flush() {
  // Each year's rows are pushed to the file as soon as they are written, and a failure (a full disk, a file size
  // limit) stops the run that year, with the system's reason, instead of decades later at the rename.
  errno = 0;
  stream.flush();
  if (!stream) throw cannot_write(file.final_path(), errno);
}

namespace {

constexpr double kSquareMetresPerHectare = 10000.0;

double checked_plot_area(double plot_area_m2) {
  if (!(plot_area_m2 > 0)) throw std::invalid_argument("stand output: plot area must be > 0 m²");
  return plot_area_m2;
}

}  // namespace

StandOutput::StandOutput(const StandOutputOptions& options)
    : plot_area_m2_(checked_plot_area(options.plot_area_m2)),
      folder_(options.folder, options.force, options.resume),
      ledger_(plot_area_m2_ / kSquareMetresPerHectare) {
  if (options.write_vtk)
    vtk_ = std::make_unique<VtkTimeSeriesWriter>(folder_, stand_blocks(options.detail), options.compression);
  if (options.resume) {
    // What the killed run was writing when it died (a VTK year, a checkpoint) is not part of any checkpoint.
    folder_.remove_stray_temporaries({temporary_sibling(folder_.path_of(stand_table_file)),
                                      temporary_sibling(folder_.path_of(trees_file)),
                                      temporary_sibling(folder_.path_of(events_file))});
    return;  // the tables are reopened by resume_tables()
  }
  stand_table_ = std::make_unique<Table>(folder_.path_of(stand_table_file));
  trees_ = std::make_unique<Table>(folder_.path_of(trees_file));
  events_ = std::make_unique<Table>(folder_.path_of(events_file));
  write_stand_table_header(stand_table_->csv);
  write_trees_header(trees_->csv);
  write_events_header(events_->csv);
}

void StandOutput::resume_tables(const TableLengths& lengths) {
  // Every table is checked before any is cut back: a checkpoint that does not fit leaves the folder as it was.
  const std::array<const char*, 3> names{stand_table_file, trees_file, events_file};
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto temporary = temporary_sibling(folder_.path_of(names[k]));
    const auto held = std::filesystem::exists(temporary) ? temporary : folder_.path_of(names[k]);
    std::error_code error;
    const auto written = std::filesystem::file_size(held, error);
    if (error || written < lengths[k])
      throw OutputFolderError(fmt::format("cannot resume {}: the checkpoint counts {} bytes of it, the folder holds {}",
                                          held.string(), lengths[k], error ? std::string("none") : std::to_string(written)));
  }
  stand_table_ = std::make_unique<Table>(folder_.path_of(stand_table_file), lengths[0]);
  trees_ = std::make_unique<Table>(folder_.path_of(trees_file), lengths[1]);
  events_ = std::make_unique<Table>(folder_.path_of(events_file), lengths[2]);
}

StandOutput::~StandOutput() {
  if (finished_ || !stand_table_) return;
  try {
    close_tables();
  } catch (...) {
    // Already unwinding from a failed run: the temporaries are cleaned up by AtomicFile.
  }
}

void StandOutput::record_events(std::span<const TreeEvent> events) {
  for (const TreeEvent& event : events) write_event_row(events_->csv, event);
  events_->flush();
  events_of_year_.insert(events_of_year_.end(), events.begin(), events.end());
}

void StandOutput::write_stand_rows(const StandInventory& inventory) {
  for (const StandTableRow& row : ledger_.rows_of_year(inventory, events_of_year_))
    write_stand_table_row(stand_table_->csv, row);
  events_of_year_.clear();
  stand_table_->flush();
}

void StandOutput::write_year(const StandSnapshot& snapshot) {
  write_tree_rows(trees_->csv, snapshot);
  trees_->flush();
  if (vtk_) vtk_->write_year(snapshot);
}

void StandOutput::close_tables() {
  // Every table that closes whole is renamed into place, even after another failed: a run stopped by a failed
  // table keeps the others' rows. The failed one is left to its AtomicFile, which deletes it.
  std::optional<OutputFolderError> first_failure;
  for (Table* table : {stand_table_.get(), trees_.get(), events_.get()}) {
    if (table->file.committed()) continue;
    errno = 0;
    table->stream.close();
    if (!table->stream) {
      if (!first_failure) first_failure = cannot_write(table->file.final_path(), errno);
      continue;
    }
    table->file.commit();
    folder_.record_output(table->file.final_path().filename());
  }
  if (first_failure) throw *first_failure;
}

void StandOutput::finish(RunManifest manifest) {
  close_tables();
  manifest.output_files = folder_.output_files();
  manifest.output_files.push_back(manifest_file);
  folder_.write_file(manifest_file, to_json(manifest));
  finished_ = true;
}

}  // namespace heliostand
