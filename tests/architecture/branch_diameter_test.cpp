#include "architecture/branch_diameter.hpp"

#include <gtest/gtest.h>

namespace heliostand {
namespace {

TEST(BranchDiameter, Eq11InCentimetres) {
  // 1 m from the tip = 100 cm: 0.0595 × 100^0.717 = 0.0595 × 27.164393 = 1.61628 cm
  EXPECT_NEAR(branch_diameter_cm(SpeciesParameters{}, 1.0), 1.61628, 1e-4);
  EXPECT_EQ(branch_diameter_cm(SpeciesParameters{}, 0.0), 0.0);
}

}  // namespace
}  // namespace heliostand
