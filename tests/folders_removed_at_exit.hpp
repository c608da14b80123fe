#pragma once
// Scratch folders a test program makes for itself (outside the build tree), deleted with what they hold when the
// process exits normally: GoogleTest returns from main and libFuzzer ends a timed run with exit(0), both of which run
// the destructors of statics. A process that crashes leaves them for the post-mortem.
#include <algorithm>
#include <filesystem>
#include <mutex>
#include <system_error>
#include <vector>

namespace heliostand::testing {

class FoldersRemovedAtExit {
 public:
  FoldersRemovedAtExit() = default;
  FoldersRemovedAtExit(const FoldersRemovedAtExit&) = delete;
  FoldersRemovedAtExit& operator=(const FoldersRemovedAtExit&) = delete;
  ~FoldersRemovedAtExit() {
    std::error_code ignored;  // best effort at exit: never throw from a destructor
    for (const std::filesystem::path& folder : folders_) std::filesystem::remove_all(folder, ignored);
  }

  void add(const std::filesystem::path& folder) {
    const std::lock_guard lock(mutex_);
    if (std::find(folders_.begin(), folders_.end(), folder) == folders_.end()) folders_.push_back(folder);
  }

 private:
  std::mutex mutex_;
  std::vector<std::filesystem::path> folders_;
};

// The one list of the process.
inline FoldersRemovedAtExit& folders_removed_at_exit() {
  static FoldersRemovedAtExit folders;
  return folders;
}

}  // namespace heliostand::testing
