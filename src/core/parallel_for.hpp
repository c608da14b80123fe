#pragma once
// A minimal parallel loop for independent per-tree work (a tree's crown growth, its light response, its roots'
// buds). Every tree draws from its own random stream and writes only its own state, so the result is the same
// for any number of threads; `set_worker_threads(1)` runs the loop in order on the calling thread.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace heliostand {

// The threads parallel_for uses: what `set_worker_threads` chose, else the hardware's (at least 1).
unsigned worker_threads();
// 0 goes back to the hardware's count. Process-wide: `heliostand grow --threads N` and the tests that prove the
// answers do not depend on it.
void set_worker_threads(unsigned threads);

// Runs `work` on `workers` threads at once, the calling thread one of them, and returns when every one has returned.
// `work` takes its share itself (each caller here draws indices from one atomic counter until none are left), so
// fewer threads do the same work: where the process may start no more threads (its limit of processes, or of address
// space for their stacks, e.g. `--threads 100000`), the ones started share it, instead of the std::thread objects
// left unjoined ending the program (std::terminate).
template <typename Work>
void run_on_threads(std::size_t workers, Work work) {
  std::vector<std::jthread> helpers;
  for (std::size_t w = 1; w < workers; ++w) {
    try {
      helpers.emplace_back(work);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones running, and this one, share the work
    }
  }
  work();
}  // the helpers join here

// parallel_for on at most `threads` threads of the caller's choosing (a solver's own count, not `--threads`), with
// the same guarantees: every index once, the threads that could start sharing the work, a failure rethrown here.
template <typename Body>
void parallel_for_on(std::size_t threads, std::size_t count, Body body) {
  const std::size_t workers = std::min(count, threads);
  if (workers <= 1) {
    for (std::size_t i = 0; i < count; ++i) body(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  run_on_threads(workers, [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        body(i);
      } catch (...) {
        std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
    }
  });
  if (failure) std::rethrow_exception(failure);
}

// body(i) for every i in [0, count), on worker_threads() threads.
template <typename Body>
void parallel_for(std::size_t count, Body body) {
  parallel_for_on(worker_threads(), count, body);
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
