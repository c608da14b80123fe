#include "survey/csv_table.hpp"

#include <gtest/gtest.h>

namespace heliostand {
namespace {

TEST(CsvTable, SplitsRecordsAndKeepsTheirStartingLine) {
  const auto table = parse_csv("id,x\n1,2.5\n\n2,3\n", "f.csv");
  ASSERT_TRUE(table.problems.empty());
  ASSERT_EQ(table.records.size(), 3u);  // the blank line 3 is skipped
  EXPECT_EQ(table.records[1].line, 2);
  EXPECT_EQ(table.records[2].line, 4);
  EXPECT_EQ(table.records[2].fields, (std::vector<std::string>{"2", "3"}));
}

TEST(CsvTable, QuotedFieldsHoldCommasQuotesAndLineBreaks) {
  const auto table = parse_csv("a,b\r\n\"x, y\",\"say \"\"hi\"\"\"\r\n\"two\nlines\",z\r\nlast,1\r\n", "f.csv");
  ASSERT_TRUE(table.problems.empty());
  ASSERT_EQ(table.records.size(), 4u);
  EXPECT_EQ(table.records[1].fields, (std::vector<std::string>{"x, y", "say \"hi\""}));
  EXPECT_EQ(table.records[2].fields, (std::vector<std::string>{"two\nlines", "z"}));
  EXPECT_EQ(table.records[2].line, 3);
  EXPECT_EQ(table.records[3].line, 5);  // the quoted line break counts as a line
}

TEST(CsvTable, EmptyFieldsAndByteOrderMark) {
  const auto table = parse_csv("\xEF\xBB\xBF" "a,b,c\n,,\n", "f.csv");
  ASSERT_EQ(table.records.size(), 2u);
  EXPECT_EQ(table.records[0].fields[0], "a");
  EXPECT_EQ(table.records[1].fields, (std::vector<std::string>{"", "", ""}));
}

TEST(CsvTable, ReportsEveryQuotingError) {
  const auto table = parse_csv("a,b\nab\"c,1\n\"x\"y,2\nok,3\n\"open,4\n", "f.csv");
  ASSERT_EQ(table.problems.size(), 3u);
  EXPECT_EQ(table.problems[0].format(), "f.csv:2: a quote inside an unquoted field (quote the whole field and double the inner quotes)");
  EXPECT_EQ(table.problems[1].format(), "f.csv:3: unexpected text after a closing quote");
  EXPECT_EQ(table.problems[2].format(), "f.csv:5: unterminated quoted field (a quote opened here is never closed)");
  // The good record between them survives.
  ASSERT_EQ(table.records.size(), 2u);
  EXPECT_EQ(table.records[1].line, 4);
}

}  // namespace
}  // namespace heliostand
