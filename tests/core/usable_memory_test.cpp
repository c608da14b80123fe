// The memory this process may use (core/usable_memory.hpp): known on Linux, whatever limits it the least.
#include "core/usable_memory.hpp"

#include <gtest/gtest.h>

namespace heliostand {
namespace {

TEST(UsableMemory, IsKnownOnLinux) {
  const auto usable = usable_memory_bytes();
  ASSERT_TRUE(usable.has_value());
  EXPECT_GT(*usable, 64ull * 1024 * 1024);
}

}  // namespace
}  // namespace heliostand
