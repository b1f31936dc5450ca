#pragma once
// The one random-number source of a run (SPEC section 3: no global RNG state shared between
// runs). std::mt19937_64's sequence is fixed by the C++ standard and the conversions below
// are ours, so a seed gives the same numbers with any standard library.
#include <cstdint>
#include <random>

namespace camcov {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  std::uint64_t bits() { return engine_(); }
  // Uniform in [0, 1): the top 53 bits as a double.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform in {0, ..., n - 1} for 0 < n < 2^53 (bias below n·2^-53).
  std::uint64_t index(std::uint64_t n) {
    const auto i = static_cast<std::uint64_t>(uniform() * static_cast<double>(n));
    return i < n ? i : n - 1;
  }
  // A seed for a child generator, so sub-components get independent streams.
  std::uint64_t fork() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace camcov
