#pragma once
// Wall-clock seconds from `start` to now, on the steady clock: the solvers' parts, the run's stages and wall time,
// the progress line's and the batch's estimates.
#include <chrono>

namespace heliostand {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace heliostand
