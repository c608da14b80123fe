// read_toml_file: the one reader of the TOML files a user hands in (scenario, batch manifest, seed-000 experiment).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scenario/toml_file.hpp"
#include "survey/survey_test_files.hpp"

namespace heliostand {
namespace {

using testing::input_problems;
using ::testing::ElementsAre;
using ::testing::StartsWith;

TEST(TomlFile, ReadsATableWhole) {
  const auto file = testing::write_test_file("good.toml", "[run]\nyears = 3\n");
  const toml::table table = read_toml_file(file, "good.toml", "scenario");
  EXPECT_EQ(table["run"]["years"].value<int>(), 3);
}

TEST(TomlFile, AFileThatCannotBeReadIsRefusedWithItsRoleAndTheReason) {
  EXPECT_THAT(input_problems([] { read_toml_file("/nonexistent/heliostand/m.toml", "m.toml", "batch manifest"); }),
              ElementsAre("m.toml: cannot read the batch manifest: No such file or directory"));
  const auto folder = testing::test_file_folder();
  std::filesystem::create_directories(folder);
  EXPECT_THAT(input_problems([&] { read_toml_file(folder, "dir", "scenario"); }),
              ElementsAre("dir: cannot read the scenario: it is a directory"));
}

TEST(TomlFile, TextThatIsNotTomlIsRefusedWithItsLine) {
  const auto file = testing::write_test_file("bad.toml", "[run]\nyears = [\n");
  const auto problems = input_problems([&] { read_toml_file(file, "bad.toml", "scenario"); });
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_THAT(problems[0], StartsWith("bad.toml:2: not valid TOML: "));
}

}  // namespace
}  // namespace heliostand
