#include "rng/random_stream.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace heliostand {

std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

RandomStream::RandomStream(std::uint64_t seed, std::initializer_list<std::uint64_t> tags)
    : state_(mix64(seed)) {
  for (std::uint64_t tag : tags) state_ = mix64(state_ ^ mix64(tag + 0x632be59bd9b4e019ULL));
}

// SplitMix64 generator: tiny state, passes BigCrush, and the stream is fully ours (portable).
std::uint64_t RandomStream::next_u64() {
  state_ += 0x9e3779b97f4a7c15ULL;
  std::uint64_t z = state_;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double RandomStream::uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

double RandomStream::uniform(double low, double high) { return low + (high - low) * uniform(); }

double RandomStream::symmetric() { return uniform(-1.0, 1.0); }

double RandomStream::normal(double mean, double sd) {
  const double u1 = 1.0 - uniform();  // (0, 1]
  const double u2 = uniform();
  return mean + sd * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

bool RandomStream::chance(double probability) { return uniform() < std::clamp(probability, 0.0, 1.0); }

int RandomStream::below(int n) { return n <= 0 ? 0 : static_cast<int>(uniform() * n); }

}  // namespace heliostand
