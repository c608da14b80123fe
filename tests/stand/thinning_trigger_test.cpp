// When thinnings fire: at a fixed age (repeating every k years), or on a stand condition that stays spent or re-arms
// after a minimum interval.
#include "stand/thinning_trigger.hpp"

#include <gtest/gtest.h>

namespace heliostand {
namespace {

const StandMeasures any_stand{30.0, 15.0};
using Measure = StandCondition::Measure;

TEST(ThinningTrigger, FixedAgeFiresOnceOrEveryKYearsFromIt) {
  const ThinningTrigger once{40, std::nullopt, std::nullopt};
  EXPECT_FALSE(why_thinning_fires(once, 39, std::nullopt, any_stand));
  EXPECT_EQ(why_thinning_fires(once, 40, std::nullopt, any_stand), "stand age 40");
  EXPECT_FALSE(why_thinning_fires(once, 45, 40, any_stand));
  const ThinningTrigger every_five{40, std::nullopt, 5};
  EXPECT_FALSE(why_thinning_fires(every_five, 35, std::nullopt, any_stand));
  EXPECT_FALSE(why_thinning_fires(every_five, 43, 40, any_stand));
  EXPECT_EQ(why_thinning_fires(every_five, 45, 40, any_stand), "stand age 45 (every 5 years from 40)");
  EXPECT_TRUE(why_thinning_fires(every_five, 50, 45, any_stand));
}

TEST(ThinningTrigger, BasalAreaMustExceedTheThreshold) {
  const ThinningTrigger when{0, StandCondition{Measure::basal_area_m2_per_ha, 40.0}, std::nullopt};
  EXPECT_FALSE(why_thinning_fires(when, 50, std::nullopt, {40.0, 20.0}));  // equal is not above
  EXPECT_EQ(why_thinning_fires(when, 50, std::nullopt, {41.234, 20.0}), "basal area 41.23 > 40 m²/ha");
  // Spent once fired, however dense the stand grows again.
  EXPECT_FALSE(why_thinning_fires(when, 60, 50, {55.0, 20.0}));
}

TEST(ThinningTrigger, TopHeightFiresWhenReached) {
  const ThinningTrigger when{0, StandCondition{Measure::top_height_m, 18.0}, std::nullopt};
  EXPECT_FALSE(why_thinning_fires(when, 50, std::nullopt, {30.0, 17.99}));
  EXPECT_EQ(why_thinning_fires(when, 50, std::nullopt, {30.0, 18.0}), "top height 18.00 m >= 18 m");
}

TEST(ThinningTrigger, ARepeatingConditionReArmsAfterItsInterval) {
  const ThinningTrigger when{0, StandCondition{Measure::basal_area_m2_per_ha, 40.0}, 5};
  const StandMeasures dense{45.0, 20.0}, open{35.0, 20.0};
  EXPECT_FALSE(why_thinning_fires(when, 54, 50, dense));  // four years after: not yet
  EXPECT_FALSE(why_thinning_fires(when, 55, 50, open));   // re-armed, but the stand is below the threshold
  EXPECT_TRUE(why_thinning_fires(when, 55, 50, dense));
  EXPECT_TRUE(why_thinning_fires(when, 58, 50, dense));   // any later year the condition holds
}

}  // namespace
}  // namespace heliostand
