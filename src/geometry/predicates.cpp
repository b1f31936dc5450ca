#include "geometry/predicates.h"

#include <array>
#include <cstddef>

namespace camcov::geometry {

namespace {

// Error-free transformations (Shewchuk 1997, after Dekker and Knuth): each returns the rounded
// result and the rounding error, which together equal the exact value. They rely on the
// project-wide -ffp-contract=off: a fused multiply-add would break Dekker's product.
struct Pair {
  double hi;
  double lo;
};

Pair twoSum(double a, double b) {
  const double x = a + b;
  const double bVirtual = x - a;
  const double aVirtual = x - bVirtual;
  return {x, (a - aVirtual) + (b - bVirtual)};
}

Pair split(double a) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double c = kSplitter * a;
  const double hi = c - (c - a);
  return {hi, a - hi};
}

Pair twoProduct(double a, double b) {
  const double x = a * b;
  const Pair sa = split(a), sb = split(b);
  const double err = x - sa.hi * sb.hi - sa.lo * sb.hi - sa.hi * sb.lo;
  return {x, sa.lo * sb.lo - err};
}

}  // namespace

namespace detail {

int orientSignExact(Vec2 a, Vec2 b, Vec2 c) {
  // Edges that share a vertex ask this all the time, and the filter cannot certify a zero.
  if (a == c || b == c || a == b) return 0;
  // (a − c) × (b − c) expanded into products of input coordinates, each exact as a pair;
  // the c.x·c.y terms cancel. Grow-Expansion sums the twelve parts without error into a
  // non-overlapping expansion whose largest non-zero component carries the sign.
  const std::array<Pair, 6> products = {
      twoProduct(a.x, b.y),  twoProduct(-a.x, c.y), twoProduct(-c.x, b.y),
      twoProduct(-a.y, b.x), twoProduct(a.y, c.x),  twoProduct(c.y, b.x),
  };
  std::array<double, 12> expansion{};
  std::size_t size = 0;
  auto grow = [&](double value) {
    double carry = value;
    for (std::size_t i = 0; i < size; ++i) {
      const Pair s = twoSum(carry, expansion[i]);
      expansion[i] = s.lo;
      carry = s.hi;
    }
    expansion[size++] = carry;
  };
  for (const Pair& p : products) {
    grow(p.lo);
    grow(p.hi);
  }
  for (std::size_t i = size; i-- > 0;) {
    if (expansion[i] > 0.0) return 1;
    if (expansion[i] < 0.0) return -1;
  }
  return 0;
}

}  // namespace detail

int compareAngle(Vec2 o, Vec2 a, Vec2 b) {
  const int ha = angleHalf(a - o), hb = angleHalf(b - o);
  if (ha != hb) return ha < hb ? -1 : 1;
  // Within one half-plane the angular order is the orientation of (o, a, b).
  return -orientSign(o, a, b);
}

}  // namespace camcov::geometry
