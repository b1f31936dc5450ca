#pragma once
// Exact orientation and polar-angle predicates.
//
// The paper says every comparison of the visibility sweep must be made "within an
// ε-boundary" (section IV-B, after Algorithm 1). We make the combinatorial decisions exact
// instead: the sweep's event order and its active-edge order are computed from the same
// exact predicate on input coordinates, so they can never contradict each other, whatever
// the degeneracy (collinear vertices, a camera on a supporting line, a vertex on a ray).
// Tolerances remain only where geometry is constructed (see docs/visibility.md).
//
// Exactness holds for finite coordinates whose products neither overflow nor underflow
// (|coordinate differences| between about 1e-140 and 1e140): any scene in metres.
#include <cmath>

#include "geometry/vec2.h"

namespace camcov::geometry {

namespace detail {
// Sign of orient(a, b, c) in exact expansion arithmetic; the slow path of orientSign().
int orientSignExact(Vec2 a, Vec2 b, Vec2 c);
// Shewchuk's ccwerrboundA = (3 + 16u)u with u = 2^-53: if |det| exceeds this times the sum of
// the two products' magnitudes, the floating-point sign of det is the true sign.
inline constexpr double kOrientErrorBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
}  // namespace detail

struct Orientation {
  double det;  // orient(a, b, c) rounded: (a − c) × (b − c)
  int sign;    // its exact sign
};

// orient(a, b, c) = cross(b − a, c − a), rounded, with its exact sign: +1 for a left turn
// a → b → c, −1 for a right turn, 0 exactly when the three points are collinear. Shewchuk's
// adaptive filter (stage A), then an exact fallback that almost never runs on
// non-degenerate input.
inline Orientation orientation(Vec2 a, Vec2 b, Vec2 c) {
  const double left = (a.x - c.x) * (b.y - c.y);
  const double right = (a.y - c.y) * (b.x - c.x);
  const double det = left - right;
  const double bound = detail::kOrientErrorBound * (std::abs(left) + std::abs(right));
  if (det > bound) return {det, 1};
  if (-det > bound) return {det, -1};
  return {det, detail::orientSignExact(a, b, c)};
}

inline int orientSign(Vec2 a, Vec2 b, Vec2 c) {
  return orientation(a, b, c).sign;
}

// Which half of the polar angle range [0, 2π) the direction d lies in, decided exactly:
// 0 for [0, π) (d.y > 0, or d.y == 0 and d.x > 0), 1 for [π, 2π). d must not be zero.
inline int angleHalf(Vec2 d) {
  return (d.y > 0.0 || (d.y == 0.0 && d.x > 0.0)) ? 0 : 1;
}

// Exact comparison of the polar angles in [0, 2π) (the +x axis is 0) of a − o and b − o:
// −1 if a comes first counter-clockwise, +1 if b does, 0 if both lie on the same ray.
// Neither a nor b may equal o.
int compareAngle(Vec2 o, Vec2 a, Vec2 b);

// A pseudo-angle: a strictly increasing function of the polar angle of d over [0, 2π) onto
// [0, 4), without trigonometry (the +x axis maps to 0, +y to 1, −x to 2, −y to 3). Computed
// from d = q − o rounded once per coordinate, the result is within kPseudoAngleError of the
// pseudo-angle of the exact direction, so two keys farther apart than 2·kPseudoAngleError
// order their directions correctly; closer keys need compareAngle().
inline double pseudoAngle(Vec2 d) {
  if (d.y >= 0.0) return d.x >= 0.0 ? d.y / (d.x + d.y) : 1.0 - d.x / (d.y - d.x);
  return d.x < 0.0 ? 2.0 - d.y / (-d.x - d.y) : 3.0 + d.x / (d.x - d.y);
}
// Error analysis: each rounded coordinate carries relative error u = 2^-53, the quotient in
// [0, 1] then at most 5u absolute, and adding the integer part at most 4u more. 16u leaves
// a factor of 1.7 to spare.
inline constexpr double kPseudoAngleError = 16.0 * 0x1p-53;

}  // namespace camcov::geometry
