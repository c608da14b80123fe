#pragma once
// Deterministic random streams. Every tree, year and organ draws from its own stream, derived from the
// run's seed and a few integer tags, so that results do not depend on thread count, solver backend,
// output settings or the order in which trees are visited.
#include <cstdint>
#include <initializer_list>

namespace heliostand {

class RandomStream {
 public:
  // A stream identified by the run seed and any number of tags (tree id, year, organ kind, ...).
  RandomStream(std::uint64_t seed, std::initializer_list<std::uint64_t> tags = {});

  std::uint64_t next_u64();
  double uniform();                        // [0, 1)
  double uniform(double low, double high); // [low, high)
  double symmetric();                      // [-1, 1), the seed-000 "random" in D = D0 + 0.3*random
  double normal(double mean, double sd);   // Box–Muller, so the sequence is ours, not the library's
  bool chance(double probability);         // true with the given probability (clamped to [0, 1])
  int below(int n);                        // integer in [0, n)

 private:
  std::uint64_t state_;
};

// SplitMix64 finaliser: a well-mixed 64-bit hash, used to combine seed and tags.
std::uint64_t mix64(std::uint64_t x);

}  // namespace heliostand
