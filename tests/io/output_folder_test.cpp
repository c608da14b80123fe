#include "io/output_folder.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <future>
#include <sstream>

#include "io/file_size_limit.hpp"
#include "io/temp_folder.hpp"
#include "read_text.hpp"

namespace heliostand {
namespace {
namespace fs = std::filesystem;

using testing::read_text;

TEST(OutputFolder, CreatesAMissingFolderWithParents) {
  testing::TempFolder tmp("output_folder_create");
  const fs::path root = tmp.path() / "a" / "b";
  OutputFolder folder(root, false);
  EXPECT_TRUE(fs::is_directory(root));
  EXPECT_TRUE(fs::exists(root / OutputFolder::marker_name));
}

TEST(OutputFolder, AcceptsAnExistingEmptyFolder) {
  testing::TempFolder tmp("output_folder_empty");
  EXPECT_NO_THROW(OutputFolder(tmp.path(), false));
}

TEST(OutputFolder, RefusesANonEmptyFolderWithoutForceAndSaysWhy) {
  testing::TempFolder tmp("output_folder_refuse");
  std::ofstream(tmp.path() / "notes.txt") << "keep me";
  try {
    OutputFolder folder(tmp.path(), false);
    FAIL() << "a non-empty folder was accepted";
  } catch (const OutputFolderError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(tmp.path().string()), std::string::npos) << message;
    EXPECT_NE(message.find("not empty"), std::string::npos) << message;
    EXPECT_NE(message.find("--force"), std::string::npos) << message;
  }
  EXPECT_EQ(read_text(tmp.path() / "notes.txt"), "keep me");
}

TEST(OutputFolder, ForceReplacesAnEarlierRun) {
  testing::TempFolder tmp("output_folder_force");
  {
    OutputFolder first(tmp.path(), false);
    first.write_file("stand_table.csv", "old\n");
  }
  OutputFolder second(tmp.path(), true);
  EXPECT_FALSE(fs::exists(tmp.path() / "stand_table.csv"));
  EXPECT_TRUE(fs::exists(tmp.path() / OutputFolder::marker_name));
}

TEST(OutputFolder, ForceStillRefusesAFolderThatIsNotAnEarlierRun) {
  testing::TempFolder tmp("output_folder_foreign");
  std::ofstream(tmp.path() / "thesis.tex") << "precious";
  EXPECT_THROW(OutputFolder(tmp.path(), true), OutputFolderError);
  EXPECT_EQ(read_text(tmp.path() / "thesis.tex"), "precious");
}

TEST(OutputFolder, RefusesAFileInPlaceOfTheFolder) {
  testing::TempFolder tmp("output_folder_file");
  std::ofstream(tmp.path() / "out") << "x";
  EXPECT_THROW(OutputFolder(tmp.path() / "out", true), OutputFolderError);
}

TEST(OutputFolder, AMarkerThatCannotBeWrittenIsAnErrorNamingItAndTheReason) {
  // The marker is the folder's first file: on a full disk the run must stop there with the system's reason, not
  // start with a marker whose write failed unseen in a stream's buffer.
  testing::TempFolder tmp("output_folder_full_disk");
  const fs::path marker = tmp.path() / OutputFolder::marker_name;
  try {
    testing::FileSizeLimit full_disk;
    OutputFolder folder(tmp.path(), false);
    FAIL() << "a marker that could not be written was accepted";
  } catch (const OutputFolderError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + marker.string() + ": " + std::strerror(EFBIG));
  }
}

TEST(OutputFolder, WriteFileLeavesOnlyTheFinalFileAndRecordsIt) {
  testing::TempFolder tmp("output_folder_write");
  OutputFolder folder(tmp.path() / "run", false);
  folder.write_file("sub/table.csv", "a,b\n");
  folder.write_file("sub/table.csv", "a,b\n1,2\n");  // a rewrite replaces the file
  EXPECT_EQ(read_text(tmp.path() / "run" / "sub" / "table.csv"), "a,b\n1,2\n");
  EXPECT_EQ(folder.output_files(), std::vector<std::string>{"sub/table.csv"});
  for (const auto& entry : fs::recursive_directory_iterator(tmp.path())) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

TEST(AtomicFile, TemporaryIsAHiddenSiblingAndVanishesIfNeverCommitted) {
  testing::TempFolder tmp("atomic_file");
  const fs::path target = tmp.path() / "run.json";
  fs::path temporary;
  try {
    AtomicFile file(target);
    temporary = file.temporary_path();
    EXPECT_EQ(temporary, tmp.path() / ".run.json.tmp");
    std::ofstream(temporary) << "{";
    throw std::runtime_error("simulated failure while writing");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_FALSE(fs::exists(target));
}

TEST(AtomicFile, CommitRenamesOverAnOlderFile) {
  testing::TempFolder tmp("atomic_commit");
  const fs::path target = tmp.path() / "stand.pvd";
  std::ofstream(target) << "old";
  AtomicFile file(target);
  std::ofstream(file.temporary_path()) << "new";
  file.commit();
  EXPECT_EQ(read_text(target), "new");
  EXPECT_FALSE(fs::exists(file.temporary_path()));
}

TEST(AtomicFile, AFileThatCannotBeWrittenIsAnErrorNamingItAndTheReason) {
  testing::TempFolder tmp("atomic_unwritable");
  const fs::path target = tmp.path() / "no such folder" / "light.json";
  AtomicFile file(target);
  errno = 0;  // no stale reason to borrow: the one in the message must come from the failed write itself
  try {
    file.write("{}");
    FAIL() << "expected an error";
  } catch (const OutputFolderError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + target.string() + ": " + std::strerror(ENOENT));
  }
  EXPECT_FALSE(fs::exists(file.temporary_path()));
  EXPECT_FALSE(fs::exists(target));
}

// A folder where the file belongs is refused by name before anything is written, instead of failing at commit() as
// a rename of the hidden temporary; the folder is left as it was.
TEST(AtomicFile, AFolderWhereTheFileBelongsIsRefusedBeforeAnythingIsWritten) {
  testing::TempFolder tmp("atomic_folder");
  const fs::path target = tmp.path() / "light.json";
  fs::create_directories(target);
  AtomicFile file(target);
  try {
    file.write("{}");
    FAIL() << "expected an error";
  } catch (const OutputFolderError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + target.string() + ": it is a folder, not a file");
  }
  EXPECT_FALSE(fs::exists(file.temporary_path()));
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_TRUE(fs::is_empty(target));
}

// A symbolic link given for the file is followed: the file it names gets the new contents, and the link stays a link
// (a rename onto the link's own name would replace the link and leave its file as it was).
TEST(AtomicFile, ALinkIsFollowedAndKept) {
  testing::TempFolder tmp("atomic_link");
  const fs::path real = tmp.path() / "real.json";
  const fs::path link = tmp.path() / "link.json";
  std::ofstream(real) << "old";
  fs::create_symlink(real.filename(), link);
  AtomicFile file(link);
  file.write("new");
  file.commit();
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_text(real), "new");
  EXPECT_EQ(std::distance(fs::directory_iterator(tmp.path()), fs::directory_iterator()), 2) << "no temporary left";
}

// A file that is not a regular one is written in place: renaming over it would replace the node itself, which root
// may do to /dev/null. A FIFO stands for every such file here (no test may touch /dev): its reader is opened first,
// without waiting, so that the write does not wait either and the bytes can be read back.
TEST(AtomicFile, AFifoIsWrittenInPlaceAndStaysAFifo) {
  testing::TempFolder tmp("atomic_fifo");
  const fs::path fifo = tmp.path() / "light.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0) << std::strerror(errno);
  AtomicFile file(fifo);
  EXPECT_TRUE(file.written_in_place());
  file.write("{}\n");
  file.commit();
  char bytes[16] = {};
  const ssize_t read = ::read(reader, bytes, sizeof bytes);
  ::close(reader);
  EXPECT_EQ(std::string(bytes, read > 0 ? static_cast<std::size_t>(read) : 0), "{}\n");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_EQ(std::distance(fs::directory_iterator(tmp.path()), fs::directory_iterator()), 1) << "no temporary left";
}

// Trying a FIFO before the work must not open it: the open would wait for a reader, and the close end the reader's
// input before the contents came. Should it open it after all, the test lets it go by opening the reader itself.
TEST(AtomicFile, TryingAFifoDoesNotOpenIt) {
  testing::TempFolder tmp("atomic_fifo_try");
  const fs::path fifo = tmp.path() / "stand.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  const AtomicFile file(fifo);
  auto tried = std::async(std::launch::async, [&file] { file.try_writing(); });
  if (tried.wait_for(std::chrono::seconds(10)) != std::future_status::ready) {
    const int reader = ::open(fifo.c_str(), O_RDONLY);  // the waiting writer's open returns now
    tried.wait();
    ::close(reader);
    FAIL() << "try_writing() opened the FIFO and waited for a reader";
  }
  tried.get();  // rethrows what it threw
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
}

}  // namespace
}  // namespace heliostand
