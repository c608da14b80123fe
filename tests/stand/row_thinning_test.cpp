// Row thinning: every k-th planted row from the first one named leaves; protected trees and trees of unknown row stay.
#include "stand/row_thinning.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace heliostand {
namespace {

using ::testing::ElementsAre;

// Eight rows (0-based 0..7) of two trees; tree 2r and 2r+1 stand in row r.
std::vector<ThinningCandidate> eight_rows() {
  std::vector<ThinningCandidate> trees;
  for (int i = 0; i < 16; ++i) {
    ThinningCandidate tree{"t" + std::to_string(i), 20.0, false};
    tree.planting_row = i / 2;
    trees.push_back(tree);
  }
  return trees;
}

ThinningRule every(int interval, int first_row) {
  ThinningRule rule;
  rule.method = ThinningMethod::rows;
  rule.rows.interval = interval;
  rule.rows.first_row = first_row;
  return rule;
}

TEST(RowThinning, EveryKthRowFromTheFirstNamed) {
  // Every third row from row 2 (1-based): rows 2, 5, 8, i.e. 0-based 1, 4, 7.
  EXPECT_THAT(select_by_rows(every(3, 2), eight_rows()), ElementsAre(2, 3, 8, 9, 14, 15));
  // Every second row from row 1: rows 1, 3, 5, 7.
  EXPECT_THAT(select_by_rows(every(2, 1), eight_rows()), ElementsAre(0, 1, 4, 5, 8, 9, 12, 13));
}

TEST(RowThinning, ProtectedTreesAndTreesOfUnknownRowStay) {
  auto trees = eight_rows();
  trees[2].is_protected = true;
  trees[8].planting_row = -1;
  EXPECT_THAT(select_by_rows(every(3, 2), trees), ElementsAre(3, 9, 14, 15));
}

}  // namespace
}  // namespace heliostand
