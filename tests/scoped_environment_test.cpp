// ScopedEnvironment puts back what was there: a value the caller gave, or nothing.
#include "scoped_environment.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace heliostand::testing {
namespace {

constexpr const char* variable = "HELIOSTAND_SCOPED_ENVIRONMENT_TEST";

std::optional<std::string> current() {
  const char* value = std::getenv(variable);
  return value ? std::optional<std::string>(value) : std::nullopt;
}

TEST(ScopedEnvironment, SetsForTheScopeAndUnsetsWhatWasNotThere) {
  ::unsetenv(variable);
  {
    const ScopedEnvironment set(variable, "inside");
    EXPECT_EQ(current(), "inside");
  }
  EXPECT_EQ(current(), std::nullopt);
}

TEST(ScopedEnvironment, PutsBackTheValueItReplaced) {
  ::setenv(variable, "given by the caller", 1);
  {
    const ScopedEnvironment set(variable, "inside");
    EXPECT_EQ(current(), "inside");
  }
  EXPECT_EQ(current(), "given by the caller");
  {
    const ScopedEnvironment unset(variable, std::nullopt);
    EXPECT_EQ(current(), std::nullopt);
  }
  EXPECT_EQ(current(), "given by the caller");
  ::unsetenv(variable);
}

TEST(ScopedEnvironment, NestedScopesUnwindInOrder) {
  ::setenv(variable, "outermost", 1);
  {
    const ScopedEnvironment outer(variable, "outer");
    {
      const ScopedEnvironment inner(variable, std::nullopt);
      EXPECT_EQ(current(), std::nullopt);
    }
    EXPECT_EQ(current(), "outer");
  }
  EXPECT_EQ(current(), "outermost");
  ::unsetenv(variable);
}

}  // namespace
}  // namespace heliostand::testing
