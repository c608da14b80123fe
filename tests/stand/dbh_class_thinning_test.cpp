// Thinning by DBH class: the trees of the class leave, all or an evenly spread fraction; protected ones stay.
#include "stand/dbh_class_thinning.hpp"
#include "stand/thinning_candidates.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace heliostand {
namespace {

using ::testing::ElementsAre;

using testing::ten_trees;

ThinningRule dbh_class(double min_cm, double max_cm) {
  ThinningRule rule;
  rule.method = ThinningMethod::dbh_class;
  rule.dbh_class = {min_cm, max_cm};
  return rule;
}

TEST(DbhClassThinning, RemovesEveryTreeOfTheHalfOpenClass) {
  EXPECT_THAT(select_by_dbh_class(dbh_class(14, 20), ten_trees()), ElementsAre(2, 3, 4));  // 14, 16, 18: not 20
  EXPECT_TRUE(select_by_dbh_class(dbh_class(29, 40), ten_trees()).empty());
}

TEST(DbhClassThinning, AFractionIsSpreadEvenlyAcrossTheClass) {
  auto rule = dbh_class(10, 20);  // 10..18 cm: five trees
  rule.remove_fraction = 0.5;     // round(2.5) = 3, at class ranks 0, 2, 4
  EXPECT_THAT(select_by_dbh_class(rule, ten_trees()), ElementsAre(0, 2, 4));
}

TEST(DbhClassThinning, ProtectedTreesStayAndCountTowardTheFraction) {
  auto trees = ten_trees();
  trees[3].is_protected = true;
  EXPECT_THAT(select_by_dbh_class(dbh_class(14, 20), trees), ElementsAre(2, 4));
  auto rule = dbh_class(10, 20);
  rule.remove_fraction = 0.4;  // 2 of the 5 class stems, from the 4 unprotected (10, 12, 14, 18): ranks 1 and 3
  EXPECT_THAT(select_by_dbh_class(rule, trees), ElementsAre(1, 4));
}

}  // namespace
}  // namespace heliostand
