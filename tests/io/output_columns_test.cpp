// The output tables' columns are declared once in code (io/stand_tables.hpp): the files follow the declaration,
// and docs/formats.md lists exactly the declared columns, one table row per column, with the declared units.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "io/csv_test_reader.hpp"
#include "io/stand_tables.hpp"
#include "read_text.hpp"

namespace heliostand {
namespace {

// "name [unit]" per column: one string per column keeps a failure message readable.
using ColumnLines = std::vector<std::string>;

ColumnLines declared(const std::vector<OutputColumn>& columns) {
  ColumnLines lines;
  for (const OutputColumn& column : columns) lines.push_back(column.name + " [" + column.unit + "]");
  return lines;
}

std::string trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(' ');
  if (first == std::string_view::npos) return {};
  return std::string(text.substr(first, text.find_last_not_of(' ') - first + 1));
}

std::vector<std::string> cells_of(std::string_view table_line) {
  std::vector<std::string> cells;
  std::size_t start = 1;  // after the leading '|'
  for (std::size_t bar = table_line.find('|', start); bar != std::string_view::npos;
       start = bar + 1, bar = table_line.find('|', start))
    cells.push_back(trimmed(table_line.substr(start, bar - start)));
  return cells;
}

// A column cell written `name` gives the bare name; anything else (two names in one row, a missing backtick)
// is kept as written, so it shows in the comparison instead of passing for a column.
std::string column_name(const std::string& cell) {
  const bool one_name = cell.size() > 2 && cell.front() == '`' && cell.back() == '`' &&
                        cell.find('`', 1) == cell.size() - 1;
  return one_name ? cell.substr(1, cell.size() - 2) : cell;
}

// The columns documented in the first markdown table after the heading line that starts with `heading`.
ColumnLines documented(std::string_view heading) {
  std::istringstream docs(testing::read_text(std::string(HELIOSTAND_SOURCE_DIR) + "/docs/formats.md"));
  std::string line;
  while (std::getline(docs, line) && line.rfind(heading, 0) != 0) {
  }
  ColumnLines lines;
  bool in_table = false;
  int rows = 0;
  while (std::getline(docs, line)) {
    if (line.empty() || line.front() != '|') {
      if (in_table) break;
      continue;
    }
    in_table = true;
    if (++rows <= 2) continue;  // the header row and the |---| row
    const auto cells = cells_of(line);
    if (cells.size() >= 2) lines.push_back(column_name(cells[0]) + " [" + cells[1] + "]");
  }
  return lines;
}

// Names each column missing on one side, then holds the order (the file's) too.
void expect_documented_exactly(const ColumnLines& in_docs, const ColumnLines& in_code) {
  for (const std::string& column : in_code)
    if (std::find(in_docs.begin(), in_docs.end(), column) == in_docs.end())
      ADD_FAILURE() << "declared in code, not in docs/formats.md: " << column;
  for (const std::string& column : in_docs)
    if (std::find(in_code.begin(), in_code.end(), column) == in_code.end())
      ADD_FAILURE() << "in docs/formats.md, not declared in code: " << column;
  EXPECT_EQ(in_docs, in_code) << "docs/formats.md lists the columns in the file's order";
}

void expect_meaningful_and_unique(const std::vector<OutputColumn>& columns) {
  std::set<std::string> names;
  for (const OutputColumn& column : columns) {
    EXPECT_TRUE(names.insert(column.name).second) << column.name << " declared twice";
    EXPECT_FALSE(column.unit.empty()) << column.name;
    EXPECT_FALSE(column.meaning.empty()) << column.name;
  }
}

TEST(OutputColumns, StandTableIsDocumentedColumnByColumnWithItsUnits) {
  expect_meaningful_and_unique(stand_table_columns());
  expect_documented_exactly(documented("### `stand_table.csv`"), declared(stand_table_columns()));
}

TEST(OutputColumns, TreesTableIsDocumentedColumnByColumnWithItsUnits) {
  expect_meaningful_and_unique(trees_columns());
  expect_documented_exactly(documented("### `trees.csv`"), declared(trees_columns()));
}

TEST(OutputColumns, EventsTableIsDocumentedColumnByColumnWithItsUnits) {
  expect_meaningful_and_unique(events_columns());
  expect_documented_exactly(documented("### `events.csv`"), declared(events_columns()));
}

// Each writer's header is its declaration, and a row has one field per declared column.
template <typename WriteRow>
void expect_table_follows(const std::vector<OutputColumn>& columns, void (*write_header)(CsvWriter&),
                          WriteRow write_row) {
  std::ostringstream out;
  CsvWriter csv(out);
  write_header(csv);
  write_row(csv);
  const auto records = testing::parse_csv(out.str());
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0], column_names(columns));
  EXPECT_EQ(records[1].size(), columns.size());
}

TEST(OutputColumns, EveryWriterFollowsItsDeclaration) {
  expect_table_follows(stand_table_columns(), write_stand_table_header,
                       [](CsvWriter& csv) { write_stand_table_row(csv, StandTableRow{}); });
  StandSnapshot one_tree;
  one_tree.trees.emplace_back();
  expect_table_follows(trees_columns(), write_trees_header,
                       [&](CsvWriter& csv) { write_tree_rows(csv, one_tree); });
  expect_table_follows(events_columns(), write_events_header,
                       [](CsvWriter& csv) { write_event_row(csv, TreeEvent{}); });
}

}  // namespace
}  // namespace heliostand
