#include "io/output_folder.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include <unistd.h>

#include <fmt/format.h>

namespace heliostand {
namespace fs = std::filesystem;

fs::path temporary_sibling(const fs::path& final_path) {
  std::string name = final_path.filename().string();
  name.insert(0, 1, '.');  // (not "." + name: GCC 12 warns falsely on that concatenation, -Wrestrict)
  name += ".tmp";
  return final_path.parent_path() / name;
}

OutputFolderError cannot_write(const fs::path& final_path, int reason) {
  return OutputFolderError(fmt::format("cannot write {}: {}", final_path.string(),
                                       reason != 0 ? std::strerror(reason) : "the write stopped short"));
}

namespace {

bool is_special_file(fs::file_status status) {
  return fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status);
}

// The file that a rename into place should replace: the one a symbolic link names (the link kept), else the name.
fs::path file_to_replace(const fs::path& final_path) {
  std::error_code error;
  if (!fs::is_symlink(fs::symlink_status(final_path, error))) return final_path;
  fs::path target = fs::canonical(final_path, error);
  return error ? final_path : target;  // a dangling link is replaced itself
}

}  // namespace

AtomicFile::AtomicFile(fs::path final_path) : final_(std::move(final_path)) {
  std::error_code error;
  if (is_special_file(fs::status(final_, error))) return;  // written in place: no destination to rename over
  destination_ = file_to_replace(final_);
  temporary_ = temporary_sibling(destination_);
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : final_(std::move(other.final_)),
      destination_(std::move(other.destination_)),
      temporary_(std::move(other.temporary_)),
      committed_(other.committed_) {
  other.committed_ = true;  // the moved-from object owns no temporary any more
}

AtomicFile::~AtomicFile() {
  if (committed_ || written_in_place()) return;
  std::error_code ignored;  // best effort while unwinding: never throw from a destructor
  fs::remove_all(temporary_, ignored);
}

void write_whole_file(const fs::path& path, std::string_view contents, const fs::path& final_path) {
  // errno is read only where the stream failed, and cleared first: a failure that sets none (a short write the
  // library noticed itself) must not be reported with the reason of some earlier, unrelated call ("Success").
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  out.close();
  if (!out) throw cannot_write(final_path, errno);
}

void AtomicFile::write(std::string_view contents) const {
  // A folder where the file belongs would only fail at commit(), as a rename naming the hidden temporary.
  std::error_code ignored;
  if (fs::is_directory(final_, ignored))
    throw OutputFolderError(fmt::format("cannot write {}: it is a folder, not a file", final_.string()));
  write_whole_file(written_in_place() ? final_ : temporary_, contents, final_);
}

void AtomicFile::try_writing() const {
  if (!written_in_place()) return write("");
  if (::access(final_.c_str(), W_OK) != 0) throw cannot_write(final_, errno);
}

void AtomicFile::commit() {
  if (committed_) return;
  std::error_code error;
  if (!written_in_place()) fs::rename(temporary_, destination_, error);
  if (error) {
    throw OutputFolderError(
        fmt::format("cannot rename {} to {}: {}", temporary_.string(), destination_.string(), error.message()));
  }
  committed_ = true;
}

bool make_output_folder(const fs::path& folder) {
  std::error_code error;
  if (!fs::exists(folder, error)) {
    fs::create_directories(folder, error);
    if (error) {
      throw OutputFolderError(fmt::format("cannot create output folder {}: {}", folder.string(), error.message()));
    }
    return false;
  }
  if (!fs::is_directory(folder)) {
    throw OutputFolderError(fmt::format("output folder {} exists and is not a folder", folder.string()));
  }
  return fs::directory_iterator(folder) != fs::directory_iterator();
}

void empty_folder(const fs::path& folder) {
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) fs::remove_all(entry.path());
}

OutputFolder::OutputFolder(fs::path root, bool force, bool resume) : root_(std::move(root)) {
  if (resume) {
    take_over_for_resume();
    return;
  }
  if (make_output_folder(root_)) {
    if (!force) {
      throw OutputFolderError(fmt::format(
          "output folder {} already exists and is not empty; choose another folder, or pass --force "
          "to replace an earlier heliostand run in it",
          root_.string()));
    }
    if (!fs::exists(root_ / marker_name)) {
      throw OutputFolderError(fmt::format(
          "output folder {} is not empty and does not hold an earlier heliostand run (no {} file); "
          "refusing to delete its contents even with --force",
          root_.string(), marker_name));
    }
    empty_folder(root_);
  }
  // Written whole and checked at its close: a buffered stream checked only after `<<` misses a full disk.
  const fs::path marker = root_ / marker_name;
  write_whole_file(marker, "This folder holds the output of a heliostand run; `--force` may delete its contents.\n",
                   marker);
}

void OutputFolder::take_over_for_resume() {
  if (!fs::is_directory(root_))
    throw OutputFolderError(fmt::format("cannot resume: output folder {} does not exist", root_.string()));
  if (!fs::exists(root_ / marker_name))
    throw OutputFolderError(fmt::format("cannot resume: output folder {} does not hold a heliostand run (no {} file)",
                                        root_.string(), marker_name));
  if (fs::exists(root_ / "run.json"))
    throw OutputFolderError(fmt::format("cannot resume: the run in {} has finished (it has its run.json); pass "
                                        "--force instead of --resume to grow it again",
                                        root_.string()));
}

void OutputFolder::remove_stray_temporaries(const std::vector<fs::path>& keep) {
  std::vector<fs::path> stray;
  for (auto entry = fs::recursive_directory_iterator(root_); entry != fs::recursive_directory_iterator(); ++entry) {
    const std::string name = entry->path().filename().string();
    const bool temporary = name.size() > 5 && name.front() == '.' && name.ends_with(".tmp");
    if (!temporary || std::find(keep.begin(), keep.end(), entry->path()) != keep.end()) continue;
    stray.push_back(entry->path());
    if (entry->is_directory()) entry.disable_recursion_pending();
  }
  for (const fs::path& path : stray) fs::remove_all(path);
}

void OutputFolder::write_file(const fs::path& relative, std::string_view contents) {
  const fs::path target = path_of(relative);
  fs::create_directories(target.parent_path());
  AtomicFile file(target);
  file.write(contents);
  file.commit();
  record_output(relative);
}

void OutputFolder::record_output(const fs::path& relative) {
  const std::string name = relative.generic_string();
  if (std::find(outputs_.begin(), outputs_.end(), name) == outputs_.end()) outputs_.push_back(name);
}

}  // namespace heliostand
