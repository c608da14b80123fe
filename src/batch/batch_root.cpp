#include "batch/batch_root.hpp"

#include <fmt/format.h>

#include <fstream>
#include <iterator>

#include "io/output_folder.hpp"

namespace heliostand {
namespace fs = std::filesystem;

void check_inside_root(const fs::path& root, const fs::path& relative) {
  if (relative.is_absolute() || relative.empty()) {
    throw OutputFolderError(fmt::format("{}: not a path inside the output folder {}", relative.string(), root.string()));
  }
  fs::path walked = root;
  for (const fs::path& part : relative) {
    if (part == ".." || part == ".") {
      throw OutputFolderError(fmt::format("{}: '{}' would leave the output folder {}", relative.string(),
                                          part.string(), root.string()));
    }
    walked /= part;
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(walked, ec))) {
      throw OutputFolderError(fmt::format("{} is a symbolic link: refusing to write through it out of the output "
                                          "folder {}", walked.string(), root.string()));
    }
  }
}

bool run_finished(const fs::path& root, const BatchRun& run) {
  std::error_code ec;
  return fs::is_regular_file(fs::symlink_status(root / run.folder() / "run.json", ec));
}

namespace {

std::string read_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void take_root(const fs::path& root, bool force) {
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(root, ec))) {
    throw OutputFolderError(fmt::format("output folder {} is a symbolic link; give the folder it points to", root.string()));
  }
  if (make_output_folder(root)) {
    if (!fs::exists(root / batch_marker_name)) {
      throw OutputFolderError(fmt::format(
          "output folder {} is not empty and does not hold a heliostand batch (no {} file); choose another folder",
          root.string(), batch_marker_name));
    }
    if (force) empty_folder(root);
  }
  const fs::path marker = root / batch_marker_name;  // written whole and checked at its close, as a run's marker
  write_whole_file(marker, "This folder holds a heliostand batch; `heliostand batch --force` may delete its contents.\n",
                   marker);
}

void write_composed_scenario(const fs::path& root, const BatchRun& run) {
  const fs::path target = root / run.scenario_file();
  std::error_code ec;
  if (fs::exists(target, ec)) {
    if (read_file(target) == run.composed_scenario) return;
    throw OutputFolderError(fmt::format(
        "{} holds runs of another manifest ({} differs from what this manifest composes); choose another "
        "folder, or pass --force to delete that batch and start over",
        root.string(), target.string()));
  }
  fs::create_directories(target.parent_path());
  AtomicFile file(target);
  file.write(run.composed_scenario);
  file.commit();
}

}  // namespace

void prepare_batch_root(const fs::path& root, const std::vector<BatchRun>& runs, bool force) {
  take_root(root, force);
  for (const BatchRun& run : runs) {
    for (const fs::path& relative : {run.scenario_file(), run.folder(), run.log_file()}) check_inside_root(root, relative);
  }
  for (const BatchRun& run : runs) {
    write_composed_scenario(root, run);
    fs::create_directories(root / run.log_file().parent_path());
    fs::create_directories(root / run.folder().parent_path());
  }
  for (const char* table : {"summary.csv", "stand_tables.csv"}) check_inside_root(root, table);
}

}  // namespace heliostand
