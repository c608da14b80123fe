#include "core/parallel_for.hpp"

#include <algorithm>

namespace heliostand {

namespace {
std::atomic<unsigned> chosen_threads{0};  // 0: the hardware's
}

unsigned worker_threads() {
  const unsigned chosen = chosen_threads.load();
  return chosen > 0 ? chosen : std::max(1u, std::thread::hardware_concurrency());
}

void set_worker_threads(unsigned threads) { chosen_threads.store(threads); }

}  // namespace heliostand
