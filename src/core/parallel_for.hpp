#pragma once
// A minimal parallel loop for independent per-tree work (a tree's crown growth, its light response, its roots'
// buds). Every tree draws from its own random stream and writes only its own state, so the result is the same
// for any number of threads; `set_worker_threads(1)` runs the loop in order on the calling thread.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace heliostand {

// The threads parallel_for uses: what `set_worker_threads` chose, else the hardware's (at least 1).
unsigned worker_threads();
// 0 goes back to the hardware's count. Process-wide: `heliostand grow --threads N` and the tests that prove the
// answers do not depend on it.
void set_worker_threads(unsigned threads);

template <typename Body>
void parallel_for(std::size_t count, Body body) {
  const std::size_t workers = std::min<std::size_t>(count, worker_threads());
  if (workers <= 1) {
    for (std::size_t i = 0; i < count; ++i) body(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  std::vector<std::thread> threads;
  for (std::size_t w = 0; w < workers; ++w)
    threads.emplace_back([&] {
      for (std::size_t i = next++; i < count; i = next++) {
        try {
          body(i);
        } catch (...) {
          std::lock_guard lock(failure_mutex);
          if (!failure) failure = std::current_exception();
        }
      }
    });
  for (auto& thread : threads) thread.join();
  if (failure) std::rethrow_exception(failure);
}

// parallel_for over [0, count) in blocks of `block` consecutive indices, body(first, last) per block: for loops
// whose single iteration is too little work to hand to a thread (converting one root segment, one apex).
template <typename Body>
void parallel_for_blocks(std::size_t count, std::size_t block, Body body) {
  block = std::max<std::size_t>(block, 1);
  parallel_for((count + block - 1) / block,
               [&](std::size_t b) { body(b * block, std::min(count, (b + 1) * block)); });
}

}  // namespace heliostand
