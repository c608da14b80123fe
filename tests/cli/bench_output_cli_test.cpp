// The JSON of `heliostand bench light` and `bench stand` goes to stdout and, with -o, to a file. A file that cannot
// be written is an error that names it, with a non-zero exit, and then nothing is reported: no JSON on stdout (which
// a script would take for a result) and no file, whole or half-written. The file is tried before the benchmark runs,
// so that a long run's JSON is not lost to a mistyped folder.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>

#include "cli/cli_runner.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

const std::string quiet_reference_bench = quick_reference_light_bench + " -q";

}  // namespace

TEST(BenchOutputCli, AnUnwritableFileIsAnErrorAndNothingIsReported) {
  const fs::path folder = scratch_folder("bench-output-unwritable");
  fs::remove_all(folder);
  fs::create_directories(folder);
  const fs::path json = folder / "no-such-folder" / "light.json";
  const CliResult refused = run_cli(quiet_reference_bench + " -o " + json.string());
  EXPECT_NE(refused.status, 0) << refused.output;
  EXPECT_NE(refused.output.find("cannot write " + json.string() + ": No such file or directory"), std::string::npos)
      << refused.output;
  EXPECT_EQ(refused.output.find("\"benchmark\""), std::string::npos) << "no JSON on stdout: " << refused.output;
  EXPECT_FALSE(fs::exists(json.parent_path()));
}

// The file is tried before the benchmark runs: a mistyped folder must not be found out after a long run, whose JSON
// would then be lost. The light benchmark's progress lines (not -q) show that no canopy was lit; the stand
// benchmark's kept tables folder, that no stand was grown.
TEST(BenchOutputCli, AnUnwritableFileIsRefusedBeforeTheBenchmarkRuns) {
  const fs::path folder = scratch_folder("bench-output-unwritable-first");
  fs::create_directories(folder);
  const fs::path json = folder / "no-such-folder" / "out.json";
  const std::string cannot_write = "cannot write " + json.string() + ": No such file or directory";

  const CliResult light = run_cli(quick_reference_light_bench + " -o " + json.string());
  EXPECT_EQ(light.status, 2) << light.output;
  EXPECT_NE(light.output.find(cannot_write), std::string::npos) << light.output;
  EXPECT_EQ(light.output.find("bench light: 300 balls"), std::string::npos) << "no canopy lit: " << light.output;

  const fs::path tables = folder / "tables";
  const std::string stand_flags = " --years 1 --device reference -q --tables " + tables.string();
  const CliResult stand = run_cli("bench stand " + tiny_bench_stand.string() + stand_flags + " -o " + json.string());
  EXPECT_EQ(stand.status, 2) << stand.output;
  EXPECT_NE(stand.output.find(cannot_write), std::string::npos) << stand.output;
  EXPECT_FALSE(fs::exists(tables)) << "no stand grown";
  EXPECT_TRUE(fs::is_empty(folder)) << "nothing left behind";
}

// A folder given where the file belongs (`-o out/`) is refused up front, by name, and left as it was.
TEST(BenchOutputCli, AFolderGivenForTheFileIsRefused) {
  const fs::path folder = scratch_folder("bench-output-folder");
  fs::create_directories(folder);
  const CliResult refused = run_cli(quick_reference_light_bench + " -o " + folder.string());
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("cannot write " + folder.string() + ": it is a folder"), std::string::npos)
      << refused.output;
  EXPECT_EQ(refused.output.find("bench light: 300 balls"), std::string::npos) << "no canopy lit: " << refused.output;
  EXPECT_TRUE(fs::is_directory(folder));
  EXPECT_TRUE(fs::is_empty(folder)) << "nothing written into it";
  EXPECT_FALSE(fs::exists(folder.parent_path() / ("." + folder.filename().string() + ".tmp"))) << "no temporary";
}

TEST(BenchOutputCli, AWritableFileHoldsTheJsonPrintedAndNoTemporaryIsLeft) {
  const fs::path folder = scratch_folder("bench-output-writable");
  fs::remove_all(folder);
  fs::create_directories(folder);
  const fs::path json = folder / "light.json";
  const CliResult written = run_cli(quiet_reference_bench + " -o " + json.string());
  ASSERT_EQ(written.status, 0) << written.output;
  const std::string file = read_text(json);
  EXPECT_NE(file.find("\"benchmark\": \"light\""), std::string::npos) << file;
  EXPECT_NE(written.output.find(file), std::string::npos) << "stdout carries the same JSON";
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1) << "only light.json";
}

// -q leaves only warnings and errors on stderr: the progress lines (one as each solver starts and ends) are info.
TEST(BenchOutputCli, QuietLeavesOnlyTheJson) {
  const CliResult chatty = run_cli(quick_reference_light_bench);
  ASSERT_EQ(chatty.status, 0) << chatty.output;
  EXPECT_NE(chatty.output.find("bench light: 300 balls"), std::string::npos)
      << "the progress lines shown: " << chatty.output;
  const CliResult quiet = run_cli(quiet_reference_bench);
  ASSERT_EQ(quiet.status, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("bench light:"), std::string::npos) << quiet.output;
  EXPECT_EQ(quiet.output.front(), '{') << "stdout holds the JSON alone: " << quiet.output;
}

// -o may name a file that is not a regular one (a FIFO, /dev/stdout, /dev/null): the JSON goes into it, and it stays
// what it was. A rename into place replaced the node itself: run as root, `-o /dev/full` left a JSON file there.
TEST(BenchOutputCli, AFifoGivenForTheFileGetsTheJsonAndStaysAFifo) {
  const fs::path folder = scratch_folder("bench-output-fifo");
  fs::remove_all(folder);
  fs::create_directories(folder);
  const fs::path fifo = folder / "light.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);  // so that the benchmark's write need not wait
  ASSERT_GE(reader, 0) << std::strerror(errno);
  const CliResult written = run_cli(quiet_reference_bench + " -o " + fifo.string());
  std::string json;
  char bytes[4096];
  for (ssize_t read = 0; (read = ::read(reader, bytes, sizeof bytes)) > 0;) json.append(bytes, bytes + read);
  ::close(reader);
  ASSERT_EQ(written.status, 0) << written.output;
  EXPECT_NE(json.find("\"benchmark\": \"light\""), std::string::npos) << json;
  EXPECT_NE(written.output.find(json), std::string::npos) << "stdout carries the same JSON";
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1) << "nothing beside it";
}

}  // namespace heliostand::testing
