#include "batch/batch_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "io/csv_writer.hpp"
#include "io/output_folder.hpp"

namespace heliostand {
namespace fs = std::filesystem;

namespace {

struct StandTable {
  std::string header;
  std::vector<std::string> rows;
};

StandTable read_stand_table(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(fmt::format("cannot read {}", file.string()));
  StandTable table;
  std::getline(in, table.header);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) table.rows.push_back(line);
  }
  return table;
}

// year_index is the table's second column, an integer (docs/formats.md), so the text before the second comma.
long year_index(const std::string& row) {
  const std::size_t first = row.find(',');
  return first == std::string::npos ? -1 : std::strtol(row.c_str() + first + 1, nullptr, 10);
}

std::string run_keys(const RunResult& result) {
  return fmt::format("{},{},{},{}", csv_field(result.run->id()), csv_field(result.run->stand),
                     csv_field(result.run->scenario), result.run->seed);
}

std::string status_fields(const RunResult& result) {
  return fmt::format("{},{},{}", result.exit_status == 0 ? "ok" : "failed", result.exit_status,
                     csv_field(result.error));
}

void write_atomically(const fs::path& file, const std::string& contents) {
  AtomicFile atomic(file);
  atomic.write(contents);
  atomic.commit();
}

}  // namespace

void write_batch_summary(const fs::path& root, const std::vector<RunResult>& results) {
  std::string stand_header;  // the stand table's header, from the first finished run (every run writes the same)
  std::vector<StandTable> tables(results.size());
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (results[i].exit_status != 0) continue;
    tables[i] = read_stand_table(root / results[i].run->folder() / "stand_table.csv");
    if (stand_header.empty()) stand_header = tables[i].header;
  }
  const std::string stand_columns = stand_header.empty() ? "" : "," + stand_header;
  // A failed run's row leaves every stand column empty: as many commas as the header has columns.
  const std::string empty_stand(stand_header.empty() ? 0 : std::count(stand_header.begin(), stand_header.end(), ',') + 1,
                                ',');

  std::string summary = "run,stand,scenario,seed,status,exit_status,error" + stand_columns + "\n";
  std::string yearly = "run,stand,scenario,seed" + stand_columns + "\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const RunResult& result = results[i];
    const std::string keys = run_keys(result);
    if (result.exit_status != 0) {
      summary += keys + "," + status_fields(result) + empty_stand + "\n";
      continue;
    }
    long last_year = -1;
    for (const std::string& row : tables[i].rows) last_year = std::max(last_year, year_index(row));
    for (const std::string& row : tables[i].rows) {
      yearly += keys + "," + row + "\n";
      if (year_index(row) == last_year) summary += keys + "," + status_fields(result) + "," + row + "\n";
    }
  }
  write_atomically(root / "stand_tables.csv", yearly);
  write_atomically(root / "summary.csv", summary);
}

}  // namespace heliostand
