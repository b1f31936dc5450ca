// The exact predicates the sweep relies on (src/geometry/predicates.h), checked against exact
// rational arithmetic on random and deliberately near-degenerate inputs.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_int.hpp>
#include <cmath>
#include <numbers>

#include "geometry/predicates.h"
#include "random_scenes.h"

namespace camcov::geometry {
namespace {

using Rational = boost::multiprecision::cpp_rational;

Rational exact(double v) {
  return Rational(v);
}  // every double is a rational, exactly

int exactOrient(Vec2 a, Vec2 b, Vec2 c) {
  const Rational det = (exact(b.x) - exact(a.x)) * (exact(c.y) - exact(a.y)) -
                       (exact(b.y) - exact(a.y)) * (exact(c.x) - exact(a.x));
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

// The pseudo-angle of the exact direction q − p.
Rational exactPseudoAngle(Vec2 p, Vec2 q) {
  const Rational x = exact(q.x) - exact(p.x), y = exact(q.y) - exact(p.y);
  if (y >= 0 && x >= 0) return Rational(y / (x + y));
  if (y >= 0) return Rational(1 - x / (y - x));
  if (x < 0) return Rational(2 - y / (-x - y));
  return Rational(3 + x / (x - y));
}

TEST(Predicates, RationalConversionIsExact) {
  // The double nearest 0.1 is 3602879701896397 / 2^55, not 1/10.
  EXPECT_EQ(exact(0.1), Rational(3602879701896397) / Rational(36028797018963968));
}

TEST(Predicates, OrientSignIsExactOnNearlyCollinearPoints) {
  visibility::testing::Random random(1);
  int degenerate = 0;
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::pow(10.0, random.integer(-3, 6));
    const Vec2 a{random.uniform(-1, 1) * scale, random.uniform(-1, 1) * scale};
    const Vec2 b{random.uniform(-1, 1) * scale, random.uniform(-1, 1) * scale};
    // c on the line through a and b as far as rounding allows, then nudged by a few ulps.
    Vec2 c = lerp(a, b, random.uniform(-2, 3));
    for (int k = random.integer(0, 3); k > 0; --k) {
      c.x = std::nextafter(c.x, random.chance(0.5) ? INFINITY : -INFINITY);
    }
    if (random.chance(0.2)) c = lerp(a, b, random.integer(-2, 3));  // often exactly collinear
    const int want = exactOrient(a, b, c);
    degenerate += want == 0;
    ASSERT_EQ(orientSign(a, b, c), want) << i;
    ASSERT_EQ(orientSign(b, c, a), want) << i;  // cyclic symmetry
    ASSERT_EQ(orientSign(b, a, c), -want) << i;
  }
  EXPECT_GT(degenerate, 100);  // the exact fallback did decide ties
}

TEST(Predicates, CompareAngleOrdersDirectionsCounterClockwiseFromPlusX) {
  const Vec2 o{1, 1};
  EXPECT_EQ(compareAngle(o, {2, 1}, {1, 2}), -1);        // 0 before π/2
  EXPECT_EQ(compareAngle(o, {0, 1}, {1, 0}), -1);        // π before 3π/2
  EXPECT_EQ(compareAngle(o, {1, 0}, {2, 0.99}), -1);     // 3π/2 before just under 2π
  EXPECT_EQ(compareAngle(o, {2, 1.01}, {2, 0.99}), -1);  // just over 0 before just under 2π
  EXPECT_EQ(compareAngle(o, {3, 1}, {2, 1}), 0);         // same ray
  EXPECT_EQ(compareAngle(o, {2, 1}, {0, 1}), -1);        // opposite rays: 0 before π
  visibility::testing::Random random(2);
  for (int i = 0; i < 20000; ++i) {
    const Vec2 a =
        o + unitVector(random.uniform(0, 2 * std::numbers::pi)) * random.uniform(0.1, 10);
    const Vec2 b =
        o + unitVector(random.uniform(0, 2 * std::numbers::pi)) * random.uniform(0.1, 10);
    auto angle = [o](Vec2 v) {
      const double t = std::atan2(v.y - o.y, v.x - o.x);
      return t < 0 ? t + 2 * std::numbers::pi : t;
    };
    if (std::abs(angle(a) - angle(b)) > 1e-9) {
      ASSERT_EQ(compareAngle(o, a, b), angle(a) < angle(b) ? -1 : 1);
    }
    ASSERT_EQ(compareAngle(o, a, b), -compareAngle(o, b, a));
  }
}

TEST(Predicates, PseudoAngleStaysWithinItsErrorBound) {
  visibility::testing::Random random(3);
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::pow(10.0, random.integer(-6, 6));
    const Vec2 p{random.uniform(-50, 50), random.uniform(-50, 50)};
    Vec2 q = p + Vec2{random.uniform(-1, 1), random.uniform(-1, 1)} * scale;
    if (random.chance(0.2)) q.y = p.y;  // on the ±x axis
    if (random.chance(0.2)) q.x = p.x;  // on the ±y axis
    if (q == p) continue;
    const double key = pseudoAngle(q - p);
    const Rational dx = exact(q.x) - exact(p.x), dy = exact(q.y) - exact(p.y);
    const Rational exactKey = exactPseudoAngle(p, q);
    const Rational error = abs(exact(key) - exactKey);
    ASSERT_LE(error, exact(kPseudoAngleError)) << i;
    ASSERT_EQ(angleHalf(q - p), dy > 0 || (dy == 0 && dx > 0) ? 0 : 1);
  }
}

}  // namespace
}  // namespace camcov::geometry
