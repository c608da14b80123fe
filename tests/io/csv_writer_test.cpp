#include "io/csv_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "io/csv_test_reader.hpp"
#include "io/stand_tables.hpp"

namespace heliostand {
namespace {

TEST(CsvField, PlainTextIsWrittenAsIs) {
  EXPECT_EQ(csv_field("A-17"), "A-17");
  EXPECT_EQ(csv_field(""), "");
  EXPECT_EQ(csv_field("two words"), "two words");
}

TEST(CsvField, SeparatorsQuotesLineBreaksAndOuterSpacesAreQuoted) {
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("line\nbreak"), "\"line\nbreak\"");
  EXPECT_EQ(csv_field("cr\r"), "\"cr\r\"");
  EXPECT_EQ(csv_field(" padded"), "\" padded\"");
  EXPECT_EQ(csv_field("padded "), "\"padded \"");
}

TEST(CsvNumber, FixedDecimalsRoundedNoNegativeZeroNaNEmpty) {
  EXPECT_EQ(csv_number(1.0, 3), "1.000");
  EXPECT_EQ(csv_number(2.34567, 2), "2.35");
  EXPECT_EQ(csv_number(-12.5, 1), "-12.5");
  EXPECT_EQ(csv_number(123456.0, 0), "123456");
  EXPECT_EQ(csv_number(-0.0001, 3), "0.000");
  EXPECT_EQ(csv_number(-0.0, 2), "0.00");
  EXPECT_EQ(csv_number(std::numeric_limits<double>::quiet_NaN(), 2), "");
}

TEST(CsvWriter, RowsJoinFieldsWithCommasAndEndWithNewline) {
  std::ostringstream out;
  CsvWriter csv(out);
  csv.header({"id", "label", "dbh_cm"});
  csv.integer(7).text("X,1").number(12.345, 1).end_row();
  csv.integer(-3).text("").number(std::numeric_limits<double>::quiet_NaN(), 1).end_row();
  EXPECT_EQ(out.str(), "id,label,dbh_cm\n7,\"X,1\",12.3\n-3,,\n");
}

TEST(CsvWriter, ARowWithMoreOrFewerFieldsThanItsHeaderIsRefused) {
  std::ostringstream out;
  CsvWriter csv(out);
  csv.header({"id", "dbh_cm"});
  csv.integer(1).number(12.0, 1).end_row();
  EXPECT_THROW(csv.integer(2).end_row(), std::logic_error);
  CsvWriter again(out);
  again.header({"id", "dbh_cm"});
  EXPECT_THROW(again.integer(3).number(1.0, 1).number(2.0, 1).end_row(), std::logic_error);
}

TEST(CsvWriter, AwkwardTextSurvivesARoundTrip) {
  const std::vector<std::string> fields = {"plain", "com,ma", "quo\"te", "new\nline", " lead", "", "\"\""};
  std::ostringstream out;
  CsvWriter csv(out);
  for (const std::string& f : fields) csv.text(f);
  csv.end_row();
  csv.text("second").end_row();
  const auto records = testing::parse_csv(out.str());
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0], fields);
  EXPECT_EQ(records[1], std::vector<std::string>{"second"});
}

TEST(StandTables, HeadersHaveTheDocumentedColumns) {
  std::ostringstream out;
  CsvWriter csv(out);
  write_stand_table_header(csv);
  write_trees_header(csv);
  write_events_header(csv);
  const auto records = testing::parse_csv(out.str());
  ASSERT_EQ(records.size(), 3u);
  EXPECT_EQ(records[0], (std::vector<std::string>{
                            "stand_age", "year_index", "species", "stems_per_ha", "basal_area_m2_per_ha", "qmd_cm",
                            "mean_height_m", "hg_m", "top_height_m", "volume_m3_per_ha", "removed_stems_per_ha",
                            "removed_basal_area_m2_per_ha", "removed_volume_m3_per_ha", "dead_stems_per_ha",
                            "dead_basal_area_m2_per_ha", "dead_volume_m3_per_ha", "dead_light_stems_per_ha",
                            "dead_light_basal_area_m2_per_ha", "dead_light_volume_m3_per_ha",
                            "dead_suppression_stems_per_ha", "dead_suppression_basal_area_m2_per_ha",
                            "dead_suppression_volume_m3_per_ha", "dead_background_stems_per_ha",
                            "dead_background_basal_area_m2_per_ha", "dead_background_volume_m3_per_ha",
                            "total_production_m3_per_ha", "cai_m3_per_ha", "mai_m3_per_ha"}));
  EXPECT_EQ(records[1], (std::vector<std::string>{"stand_age", "tree_id", "label", "x_m", "y_m", "status",
                                                  "habitat_tree", "hollows", "age",
                                                  "height_m", "dbh_cm", "crown_base_m", "crown_radius_m",
                                                  "volume_m3", "leaf_balls", "mean_light", "light_budget",
                                                  "relative_light", "dbh_increment_cm", "root_length_m",
                                                  "root_max_depth_m", "root_uptake", "hegyi_index"}));
  EXPECT_EQ(records[2], (std::vector<std::string>{"stand_age", "tree_id", "label", "species", "event", "cause",
                                                  "reason", "dbh_cm", "height_m", "volume_m3"}));
}

TEST(StandTables, TreeRowEndsWithItsHegyiIndex) {
  StandSnapshot snapshot;
  snapshot.trees.resize(2);
  snapshot.trees[0].hegyi_index = 1.23456;  // 1/m, four decimals
  snapshot.trees[1].status = TreeStatus::removed;  // gone: no index (NaN), an empty field
  std::ostringstream out;
  CsvWriter csv(out);
  write_trees_header(csv);
  write_tree_rows(csv, snapshot);
  const auto records = testing::parse_csv(out.str());
  ASSERT_EQ(records.size(), 3u);
  ASSERT_EQ(records[0].back(), "hegyi_index");
  EXPECT_EQ(records[1].back(), "1.2346");
  EXPECT_EQ(records[2].back(), "");
  EXPECT_EQ(records[1].size(), records[0].size());
}

TEST(StandTables, EventRowCarriesSpeciesKindCauseCodeReasonLabelAndQuotedTexts) {
  std::ostringstream out;
  CsvWriter csv(out);
  write_event_row(csv, {45, 12, "P3,12", "todomatsu", TreeEventKind::removed, "thinning", "first thinning, from below",
                        23.456, 18.2, 0.41234});
  write_event_row(csv, {46, 13, "P3-13", "karamatsu", TreeEventKind::died, "suppression", "suppression", 8.0, 9.0,
                        0.02});
  EXPECT_EQ(out.str(),
            "45,12,\"P3,12\",todomatsu,removed,thinning,\"first thinning, from below\",23.46,18.200,0.4123\n"
            "46,13,P3-13,karamatsu,died,suppression,suppression,8.00,9.000,0.0200\n");
}

}  // namespace
}  // namespace heliostand
