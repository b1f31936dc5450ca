#pragma once
// splitmix64: a tiny seeded generator for benchmark inputs, the same numbers on every machine
// and easy to reproduce outside C++ (tests/bench/python_parity.py draws the same poses).
#include <cstdint>

namespace camcov::testing {

struct SplitMix64 {
  std::uint64_t state;
  // Uniform in [lo, hi): the top 53 bits of the next output.
  double uniform(double lo, double hi) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return lo + (hi - lo) * static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1p-53;
  }
};

}  // namespace camcov::testing
