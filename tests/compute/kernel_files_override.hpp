#pragma once
// HELIOSTAND_KERNEL_DIR pointing, for one scope, at a folder of this process's own holding the given kernel files:
// every kernel built meanwhile reads them in place of the embedded copies of the same names (the other files stay
// the embedded ones). The folder is removed and the variable put back as it was when the scope ends.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "scoped_environment.hpp"

namespace heliostand::testing {

class KernelFilesOverride {
 public:
  // `label` names the folder (several overrides in one process); `files`: (file name in cl/, its text).
  KernelFilesOverride(const std::string& label, const std::vector<std::pair<std::string, std::string>>& files)
      : dir_(make_dir(label)), kernel_dir_("HELIOSTAND_KERNEL_DIR", dir_.string()) {
    for (const auto& [name, text] : files) std::ofstream(dir_ / name) << text;
  }
  ~KernelFilesOverride() { std::filesystem::remove_all(dir_); }
  KernelFilesOverride(const KernelFilesOverride&) = delete;
  KernelFilesOverride& operator=(const KernelFilesOverride&) = delete;

 private:
  static std::filesystem::path make_dir(const std::string& label) {
    auto dir = std::filesystem::temp_directory_path() / ("heliostand_" + label + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
  }

  std::filesystem::path dir_;
  ScopedEnvironment kernel_dir_;  // after dir_: made from it
};

}  // namespace heliostand::testing
