#include "io/output_folder.hpp"

#include <algorithm>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

namespace heliostand {
namespace fs = std::filesystem;

fs::path temporary_sibling(const fs::path& final_path) {
  std::string name = final_path.filename().string();
  name.insert(0, 1, '.');  // (not "." + name: GCC 12 warns falsely on that concatenation, -Wrestrict)
  name += ".tmp";
  return final_path.parent_path() / name;
}

AtomicFile::AtomicFile(fs::path final_path)
    : final_(std::move(final_path)), temporary_(temporary_sibling(final_)) {}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : final_(std::move(other.final_)), temporary_(std::move(other.temporary_)), committed_(other.committed_) {
  other.committed_ = true;  // the moved-from object owns no temporary any more
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  std::error_code ignored;  // best effort while unwinding: never throw from a destructor
  fs::remove_all(temporary_, ignored);
}

void AtomicFile::commit() {
  if (committed_) return;
  std::error_code error;
  fs::rename(temporary_, final_, error);
  if (error) {
    throw OutputFolderError(
        fmt::format("cannot rename {} to {}: {}", temporary_.string(), final_.string(), error.message()));
  }
  committed_ = true;
}

namespace {

bool is_empty_folder(const fs::path& folder) { return fs::directory_iterator(folder) == fs::directory_iterator(); }

void clear_folder(const fs::path& folder) {
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) fs::remove_all(entry.path());
}

}  // namespace

OutputFolder::OutputFolder(fs::path root, bool force) : root_(std::move(root)) {
  std::error_code error;
  if (fs::exists(root_, error)) {
    if (!fs::is_directory(root_)) {
      throw OutputFolderError(fmt::format("output folder {} exists and is not a folder", root_.string()));
    }
    if (!is_empty_folder(root_)) {
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
      clear_folder(root_);
    }
  } else {
    fs::create_directories(root_, error);
    if (error) {
      throw OutputFolderError(fmt::format("cannot create output folder {}: {}", root_.string(), error.message()));
    }
  }
  std::ofstream marker(root_ / marker_name);
  marker << "This folder holds the output of a heliostand run; `--force` may delete its contents.\n";
  if (!marker) throw OutputFolderError(fmt::format("cannot write into output folder {}", root_.string()));
}

void OutputFolder::write_file(const fs::path& relative, std::string_view contents) {
  const fs::path target = path_of(relative);
  fs::create_directories(target.parent_path());
  AtomicFile file(target);
  {
    std::ofstream out(file.temporary_path(), std::ios::binary | std::ios::trunc);
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.close();
    if (!out) throw OutputFolderError(fmt::format("cannot write {}", file.temporary_path().string()));
  }
  file.commit();
  record_output(relative);
}

void OutputFolder::record_output(const fs::path& relative) {
  const std::string name = relative.generic_string();
  if (std::find(outputs_.begin(), outputs_.end(), name) == outputs_.end()) outputs_.push_back(name);
}

}  // namespace heliostand
