// The batch manifest reader (every problem with its line and key, nothing run), the scenario layers' merge rule,
// and the output root's refusals: nothing written outside it, nothing of another folder overwritten.
#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "batch/batch_manifest.hpp"
#include "batch/batch_root.hpp"
#include "batch/batch_run.hpp"
#include "core/input_error.hpp"
#include "io/file_size_limit.hpp"
#include "io/output_folder.hpp"
#include "io/temp_folder.hpp"

namespace heliostand {
namespace {
namespace fs = std::filesystem;
using testing::TempFolder;

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

std::vector<std::string> manifest_problems(const fs::path& manifest) {
  try {
    load_batch_manifest(manifest);
  } catch (const InputError& error) {
    std::vector<std::string> lines;
    for (const auto& problem : error.problems()) lines.push_back(problem.format(error.field_kind()));
    return lines;
  }
  return {};
}

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
  for (const auto& line : lines)
    if (line.find(text) != std::string::npos) return true;
  return false;
}

TEST(BatchManifest, ReportsEveryProblemWithItsLineAndKey) {
  TempFolder folder("batch-manifest");
  write(folder.path() / "stand.toml", "[stand]\n");
  const fs::path manifest = folder.path() / "batch.toml";
  write(manifest,
        "seeds = [1, 1, -2]\n"            // line 1: a repeat and a negative seed
        "colour = 'green'\n"              // line 2: unknown key
        "[[stand]]\n"
        "name = '../escape'\n"            // line 4: not a folder name
        "scenario = 'stand.toml'\n"
        "[[stand]]\n"
        "name = 'b'\n"
        "scenario = 'missing.toml'\n"     // line 8: no such file
        "[[scenario]]\n"
        "name = 'b'\n"
        "override = 3\n");                // line 11: not a table
  const auto lines = manifest_problems(manifest);
  const std::string file = manifest.string();
  EXPECT_TRUE(mentions(lines, file + ":1: key 'seeds': seed 1 is given twice")) << ::testing::PrintToString(lines);
  EXPECT_TRUE(mentions(lines, file + ":1: key 'seeds': expected integers >= 0"));
  EXPECT_TRUE(mentions(lines, file + ":2: key 'colour': unknown key"));
  EXPECT_TRUE(mentions(lines, file + ":4: key 'stand[1].name': '../escape' cannot name a folder"));
  EXPECT_TRUE(mentions(lines, file + ":8: key 'stand[2].scenario': no such file"));
  EXPECT_TRUE(mentions(lines, file + ":11: key 'scenario[1].override': expected a table"));
  EXPECT_EQ(lines.size(), 6u) << ::testing::PrintToString(lines);
}

TEST(BatchManifest, NotTomlIsRefusedWithItsLine) {
  TempFolder folder("batch-manifest");
  write(folder.path() / "batch.toml", "seeds = [1]\n[[stand]\n");
  const auto lines = manifest_problems(folder.path() / "batch.toml");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("batch.toml:2: not valid TOML"), std::string::npos) << lines[0];
}

TEST(ScenarioLayers, TablesMergeKeyByKeyAndEverythingElseIsReplaced) {
  auto base = toml::parse("[run]\nyears = 5\nseed = 7\n[[thinning]]\nage = 23\n[light]\nsky_bands = 8\n");
  merge_scenario_layer(base, toml::parse("thinning = []\n[run]\nyears = 1\n"));
  EXPECT_EQ(base["run"]["years"].value<int>(), 1);
  EXPECT_EQ(base["run"]["seed"].value<int>(), 7);         // kept: the layer's [run] merges key by key
  EXPECT_EQ(base["thinning"].as_array()->size(), 0u);     // replaced: an array is a value
  EXPECT_EQ(base["light"]["sky_bands"].value<int>(), 8);  // untouched
}

TEST(ScenarioLayers, RelativePathsFollowTheLayerThatSetsThem) {
  TempFolder folder("batch-manifest");
  write(folder.path() / "stands/a/scenario.toml", "[stand]\nsurvey = 'survey.csv'\n[soil]\nfile = 'soil.csv'\n");
  write(folder.path() / "regimes/wet.toml", "[soil]\nfile = 'wet.csv'\n");
  write(folder.path() / "batch.toml",
        "seeds = [1]\n[[stand]]\nname = 'a'\nscenario = 'stands/a/scenario.toml'\n"
        "[[scenario]]\nname = 'wet'\nfile = 'regimes/wet.toml'\n");
  const BatchManifest manifest = load_batch_manifest(folder.path() / "batch.toml");
  const toml::table composed = compose_scenario(manifest, manifest.stands[0], manifest.scenarios[0]);
  const fs::path root = fs::absolute(folder.path()).lexically_normal();
  EXPECT_EQ(composed["stand"]["survey"].value<std::string>(), (root / "stands/a/survey.csv").string());
  EXPECT_EQ(composed["soil"]["file"].value<std::string>(), (root / "regimes/wet.csv").string());
}

TEST(BatchRoot, NoWrittenPathLeavesTheRoot) {
  TempFolder folder("batch-root");
  const fs::path root = folder.path() / "root";
  fs::create_directories(root);
  EXPECT_THROW(check_inside_root(root, "../outside.csv"), OutputFolderError);
  EXPECT_THROW(check_inside_root(root, "runs/../../outside"), OutputFolderError);
  EXPECT_THROW(check_inside_root(root, "/etc/passwd"), OutputFolderError);
  fs::create_directories(folder.path() / "elsewhere");
  fs::create_directory_symlink(folder.path() / "elsewhere", root / "runs");
  EXPECT_THROW(check_inside_root(root, "runs/a/as-is/seed-1"), OutputFolderError);
  EXPECT_NO_THROW(check_inside_root(root, "logs/a/as-is/seed-1.log"));
}

TEST(BatchRoot, AFolderThatIsNotABatchIsNeverTouched) {
  TempFolder folder("batch-root");
  write(folder.path() / "root/notes.txt", "mine\n");
  const std::vector<BatchRun> runs{{"a", "as-is", 1, "[run]\n"}};
  EXPECT_THROW(prepare_batch_root(folder.path() / "root", runs, true), OutputFolderError);
  EXPECT_TRUE(fs::exists(folder.path() / "root/notes.txt"));
  EXPECT_FALSE(fs::exists(folder.path() / "root/inputs"));
}

TEST(BatchRoot, AFileOrALinkInPlaceOfTheRootIsRefusedAndLeftAlone) {
  TempFolder folder("batch-root");
  write(folder.path() / "root", "mine\n");
  try {
    prepare_batch_root(folder.path() / "root", {}, true);
    FAIL() << "a file in place of the root was accepted";
  } catch (const OutputFolderError& e) {
    EXPECT_EQ(std::string(e.what()),
              "output folder " + (folder.path() / "root").string() + " exists and is not a folder");
  }
  EXPECT_TRUE(fs::is_regular_file(folder.path() / "root"));
  fs::create_directories(folder.path() / "elsewhere");
  fs::create_directory_symlink(folder.path() / "elsewhere", folder.path() / "link");
  EXPECT_THROW(prepare_batch_root(folder.path() / "link", {}, true), OutputFolderError);
  EXPECT_TRUE(fs::is_empty(folder.path() / "elsewhere"));
}

TEST(BatchRoot, ABatchOfAnotherManifestIsRefusedUnlessForced) {
  TempFolder folder("batch-root");
  const fs::path root = folder.path() / "root";
  prepare_batch_root(root, {{"a", "as-is", 1, "[run]\nyears = 1\n"}}, false);
  EXPECT_THROW(prepare_batch_root(root, {{"a", "as-is", 1, "[run]\nyears = 2\n"}}, false), OutputFolderError);
  EXPECT_NO_THROW(prepare_batch_root(root, {{"a", "as-is", 1, "[run]\nyears = 1\n"}}, false));  // the same: taken again
  EXPECT_NO_THROW(prepare_batch_root(root, {{"a", "as-is", 1, "[run]\nyears = 2\n"}}, true));
}

TEST(BatchRoot, AMarkerThatCannotBeWrittenIsAnErrorNamingItAndTheReason) {
  TempFolder folder("batch-root");
  const fs::path root = folder.path() / "root";
  try {
    testing::FileSizeLimit full_disk;
    prepare_batch_root(root, {}, false);
    FAIL() << "a batch marker that could not be written was accepted";
  } catch (const OutputFolderError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot write " + (root / batch_marker_name).string() + ": " + std::strerror(EFBIG));
  }
}

}  // namespace
}  // namespace heliostand
