#pragma once
// The three CSV tables of a run (columns, units and meaning: docs/formats.md):
//   stand_table.csv  per simulated year, the whole stand and each species: metrics per hectare, removals, deaths,
//                    production
//   trees.csv        one row per tree per output year
//   events.csv       one row per tree removed (thinning) or dead (mortality), every simulated year
// Each table's columns are declared once, in file order, by its *_columns() list: the header is that list's
// names, each row writes one field per column in the same order, and docs/formats.md lists the same columns
// with the same units (tests/io/output_columns_test.cpp).
#include <vector>

#include "io/csv_writer.hpp"
#include "io/output_column.hpp"
#include "records/stand_snapshot.hpp"
#include "records/stand_table_ledger.hpp"
#include "records/tree_event.hpp"

namespace heliostand {

const std::vector<OutputColumn>& stand_table_columns();
const std::vector<OutputColumn>& trees_columns();
const std::vector<OutputColumn>& events_columns();

void write_stand_table_header(CsvWriter& csv);
void write_stand_table_row(CsvWriter& csv, const StandTableRow& row);

void write_trees_header(CsvWriter& csv);
void write_tree_rows(CsvWriter& csv, const StandSnapshot& snapshot);

void write_events_header(CsvWriter& csv);
void write_event_row(CsvWriter& csv, const TreeEvent& event);

}  // namespace heliostand
