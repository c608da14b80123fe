#pragma once
// Everything a run writes, behind one object the stand manager drives:
//   StandOutput out({folder, force, plot_area_m2});      // takes the folder (refuses a non-empty one)
//   each simulated year:  out.record_events(events);      // its removals and deaths: events.csv rows
//                         out.write_stand_rows(inventory); // stand_table.csv: the whole stand, then each species
//   each output year:     out.write_year(snapshot);       // VTK year + stand.pvd, trees.csv rows
//   at the end:           out.finish(manifest);           // tables renamed into place, run.json last
// Tables are streamed to hidden temporaries (".trees.csv.tmp") and renamed at finish(). If the run
// throws, the destructor still renames them (their rows are complete up to the last written year), but
// no run.json is written: its absence marks the run as unfinished.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <fstream>
#include <memory>
#include <span>
#include <vector>

#include "core/checkpoint_access.hpp"
#include "io/csv_writer.hpp"
#include "io/output_folder.hpp"
#include "io/run_manifest.hpp"
#include "io/vtk_time_series_writer.hpp"
#include "records/stand_snapshot.hpp"
#include "records/stand_table_ledger.hpp"
#include "records/tree_event.hpp"
#include "records/year_recorder.hpp"
#include "scenario/output_detail.hpp"
#include "scenario/vtk_compression.hpp"

namespace heliostand {

struct StandOutputOptions {
  std::filesystem::path folder;
  bool force = false;        // replace an earlier heliostand run in `folder`
  double plot_area_m2 = 0;   // for the per-hectare values of stand_table.csv
  bool write_vtk = true;     // false: tables only (batch forecasts)
  OutputDetail detail = OutputDetail::full;  // the VTK blocks (scenario/output_detail.hpp)
  VtkCompression compression = default_vtk_compression;  // the VTK pieces' (scenario/vtk_compression.hpp)
  // Take over the folder of an interrupted run (OutputFolder's resume); the tables are reopened by a checkpoint
  // (io/checkpoint_state.hpp), which cuts them back to the rows it counts, instead of being started afresh.
  bool resume = false;
};

class StandOutput final : public YearRecorder {
 public:
  static constexpr const char* stand_table_file = "stand_table.csv";
  static constexpr const char* trees_file = "trees.csv";
  static constexpr const char* events_file = "events.csv";
  static constexpr const char* manifest_file = "run.json";
  using TableLengths = std::array<std::uint64_t, 3>;  // bytes of stand_table, trees, events

  explicit StandOutput(const StandOutputOptions& options);
  ~StandOutput();
  StandOutput(const StandOutput&) = delete;
  StandOutput& operator=(const StandOutput&) = delete;

  void record_events(std::span<const TreeEvent> events) override;
  // The year's stand_table.csv rows, its flows from the events recorded since the previous call.
  void write_stand_rows(const StandInventory& inventory) override;
  void write_year(const StandSnapshot& snapshot) override;
  bool draws_trunks() const override { return vtk_ != nullptr; }
  // Fills manifest.output_files, renames the tables into place and writes run.json last.
  void finish(RunManifest manifest);

  OutputFolder& folder() { return folder_; }
  VtkTimeSeriesWriter* vtk() { return vtk_.get(); }   // to add blocks; null when VTK output is off

 private:
  friend struct checkpoint::Access;
  struct Table {
    AtomicFile file;
    std::ofstream stream;
    CsvWriter csv;
    // `resume_at`: reopen the temporary an interrupted run left, cut back to that many bytes, and append.
    explicit Table(const std::filesystem::path& final_path, std::optional<std::uint64_t> resume_at = std::nullopt);
    void flush();  // throws "cannot write FINAL_PATH: REASON" if the rows could not be written
  };

  void resume_tables(const TableLengths& lengths);

  void close_tables();

  double plot_area_m2_;  // declared before folder_: a bad area is refused before the folder is touched
  OutputFolder folder_;
  std::unique_ptr<VtkTimeSeriesWriter> vtk_;
  std::unique_ptr<Table> stand_table_, trees_, events_;
  StandTableLedger ledger_;
  std::vector<TreeEvent> events_of_year_;
  bool finished_ = false;
};

}  // namespace heliostand
