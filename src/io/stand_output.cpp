#include "io/stand_output.hpp"

#include <fmt/format.h>

#include "io/stand_tables.hpp"

namespace heliostand {

StandOutput::Table::Table(const std::filesystem::path& final_path)
    : file(final_path), stream(file.temporary_path(), std::ios::trunc), csv(stream) {
  if (!stream) throw OutputFolderError(fmt::format("cannot write {}", file.temporary_path().string()));
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
      folder_(options.folder, options.force),
      ledger_(plot_area_m2_ / kSquareMetresPerHectare) {
  if (options.write_vtk) vtk_ = std::make_unique<VtkTimeSeriesWriter>(folder_, stand_blocks(options.detail));
  stand_table_ = std::make_unique<Table>(folder_.path_of(stand_table_file));
  trees_ = std::make_unique<Table>(folder_.path_of(trees_file));
  events_ = std::make_unique<Table>(folder_.path_of(events_file));
  write_stand_table_header(stand_table_->csv);
  write_trees_header(trees_->csv);
  write_events_header(events_->csv);
}

StandOutput::~StandOutput() {
  if (finished_) return;
  try {
    close_tables();
  } catch (...) {
    // Already unwinding from a failed run: the temporaries are cleaned up by AtomicFile.
  }
}

void StandOutput::record_events(std::span<const TreeEvent> events) {
  for (const TreeEvent& event : events) write_event_row(events_->csv, event);
  events_->stream.flush();
  events_of_year_.insert(events_of_year_.end(), events.begin(), events.end());
}

void StandOutput::write_stand_rows(const StandInventory& inventory) {
  for (const StandTableRow& row : ledger_.rows_of_year(inventory, events_of_year_))
    write_stand_table_row(stand_table_->csv, row);
  events_of_year_.clear();
  stand_table_->stream.flush();
}

void StandOutput::write_year(const StandSnapshot& snapshot) {
  write_tree_rows(trees_->csv, snapshot);
  trees_->stream.flush();
  if (vtk_) vtk_->write_year(snapshot);
}

void StandOutput::close_tables() {
  for (Table* table : {stand_table_.get(), trees_.get(), events_.get()}) {
    if (table->file.committed()) continue;
    table->stream.close();
    if (!table->stream) throw OutputFolderError(fmt::format("cannot write {}", table->file.temporary_path().string()));
    table->file.commit();
    folder_.record_output(table->file.final_path().filename());
  }
}

void StandOutput::finish(RunManifest manifest) {
  close_tables();
  manifest.output_files = folder_.output_files();
  manifest.output_files.push_back(manifest_file);
  folder_.write_file(manifest_file, to_json(manifest));
  finished_ = true;
}

}  // namespace heliostand
