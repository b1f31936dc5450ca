#pragma once
// A sum of lengths that does not depend on the order of its terms: each term is rounded once
// to a multiple of 2^-64 (m) and the multiples are added as 128-bit integers, exactly. So a
// sum kept up to date by adding and taking away terms (the reward's incremental terms) is the
// sum made afresh from the same terms, to the bit, in any order and on any number of threads.
// The rounding, at most 5.4e-20 per term, is far below a double's precision for any length a
// scene has.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace camcov::reward {

class FixedPointSum {
 public:
  __extension__ using Units = __int128;  // of 2^-64; a GCC and Clang extension

  // The term x >= 0 in units; a term at or beyond 2^40 (or NaN) is refused, so that any sum
  // of fewer than 2^23 terms stays in range.
  static Units units(double x) {
    if (!(x >= 0.0 && x < 0x1p40)) {
      throw std::invalid_argument("FixedPointSum: term out of range: " + std::to_string(x));
    }
    // trunc(x · 2^64), as its whole part (below 2^40) and its fraction's 64 bits: both parts
    // are exact in a double and convert without the slow 128-bit conversion.
    const double whole = std::floor(x);
    return (static_cast<Units>(static_cast<std::uint64_t>(whole)) << 64) |
           static_cast<std::uint64_t>((x - whole) * 0x1p64);
  }

  void add(Units u) { total_ += u; }
  void subtract(Units u) { total_ -= u; }
  double value() const { return static_cast<double>(total_) * 0x1p-64; }

 private:
  Units total_ = 0;
};

}  // namespace camcov::reward
