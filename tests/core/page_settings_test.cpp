// The allocator's settings a benchmark records: the kernel's transparent-huge-page mode is the bracketed word of
// /sys/kernel/mm/transparent_hugepage/enabled, and nothing is made up where the file says none.
#include "core/page_settings.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace heliostand {
namespace {

std::optional<std::string> chosen(const std::string& text) {
  std::istringstream enabled(text);
  return chosen_transparent_huge_pages(enabled);
}

TEST(PageSettings, TheBracketedModeIsTheKernels) {
  EXPECT_EQ(chosen("always [madvise] never\n"), "madvise");
  EXPECT_EQ(chosen("[always] madvise never\n"), "always");
  EXPECT_EQ(chosen("always madvise [never]\n"), "never");
}

TEST(PageSettings, NoBracketedWordIsNoMode) {
  EXPECT_EQ(chosen(""), std::nullopt);
  EXPECT_EQ(chosen("always madvise never\n"), std::nullopt);
  EXPECT_EQ(chosen("[] always\n"), std::nullopt);
}

TEST(PageSettings, UnsetIsNullInTheJson) {
  const nlohmann::json json = page_settings_json(PageSettings{});
  EXPECT_TRUE(json.at("glibc_tunables").is_null());
  EXPECT_TRUE(json.at("transparent_huge_pages").is_null());
  const nlohmann::json set = page_settings_json(PageSettings{"glibc.malloc.hugetlb=1", "madvise"});
  EXPECT_EQ(set.at("glibc_tunables"), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(set.at("transparent_huge_pages"), "madvise");
}

}  // namespace
}  // namespace heliostand
