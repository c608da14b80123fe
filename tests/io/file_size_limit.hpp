#pragma once
// While one of these lives, no file of this process can grow past `bytes` (RLIMIT_FSIZE; by default one byte, so
// none can grow, as on a full disk): a write past the limit fails with EFBIG, the SIGXFSZ it would also raise
// ignored. Both are restored after.
#include <sys/resource.h>

#include <csignal>

namespace heliostand::testing {

class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes = 1) : old_handler_(std::signal(SIGXFSZ, SIG_IGN)) {
    ::getrlimit(RLIMIT_FSIZE, &old_limit_);
    rlimit limit = old_limit_;
    limit.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &old_limit_);
    std::signal(SIGXFSZ, old_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit old_limit_{};
  void (*old_handler_)(int);
};

}  // namespace heliostand::testing
