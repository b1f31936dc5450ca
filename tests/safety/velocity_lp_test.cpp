#include "safety/velocity_lp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace camcov::safety {
namespace {

using geometry::Vec2;

bool admissible(std::span<const HalfPlane> hs, double vmax, Vec2 u, double slack = 1e-9) {
  if (geometry::norm(u) > vmax + slack) return false;
  for (const auto& h : hs) {
    if (geometry::dot(h.normal, u) < h.offset - slack) return false;
  }
  return true;
}

// The reference: the optimum of a strictly convex problem over a disc and half-planes lies at
// the unconstrained optimum, on one constraint's boundary (projection onto a line, or onto
// the circle), or where two boundaries meet. Enumerate every such point, keep the admissible
// ones, take the nearest: O(m³), independent of the incremental algorithm.
std::optional<Vec2> bruteForce(std::span<const HalfPlane> hs, double vmax, Vec2 desired) {
  std::vector<Vec2> candidates{desired};
  const double speed = geometry::norm(desired);
  if (speed > 0) candidates.push_back(desired * (vmax / speed));
  for (std::size_t i = 0; i < hs.size(); ++i) {
    const Vec2 n = hs[i].normal, p0 = n * hs[i].offset, d{-n.y, n.x};
    candidates.push_back(p0 + d * geometry::dot(d, desired - p0));
    const double c2 = vmax * vmax - hs[i].offset * hs[i].offset;
    if (c2 >= 0) {
      candidates.push_back(p0 + d * std::sqrt(c2));
      candidates.push_back(p0 - d * std::sqrt(c2));
    }
    for (std::size_t j = 0; j < i; ++j) {
      const double det = geometry::cross(hs[i].normal, hs[j].normal);
      if (std::abs(det) < 1e-14) continue;
      // Solve n_i·u = b_i, n_j·u = b_j by Cramer's rule.
      const Vec2 a = hs[i].normal, b = hs[j].normal;
      candidates.push_back({(hs[i].offset * b.y - hs[j].offset * a.y) / det,
                            (a.x * hs[j].offset - b.x * hs[i].offset) / det});
    }
  }
  std::optional<Vec2> best;
  for (const Vec2& c : candidates) {
    if (!admissible(hs, vmax, c, 1e-9)) continue;
    if (!best || geometry::distance(c, desired) < geometry::distance(*best, desired)) best = c;
  }
  return best;
}

std::vector<HalfPlane> randomPlanes(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), offset(-1.5, 0.8);
  std::vector<HalfPlane> hs;
  for (int i = 0; i < count; ++i)
    hs.push_back({geometry::unitVector(angle(rng)), offset(rng)});
  return hs;
}

TEST(VelocityLp, AgreesWithEnumeratingEveryCandidateOnRandomProblems) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-2.5, 2.5);
  int feasible = 0, infeasible = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const auto hs = randomPlanes(rng, 1 + trial % 7);
    const Vec2 desired{coordinate(rng), coordinate(rng)};
    const auto fast = closestAdmissibleVelocity(hs, 1.0, desired);
    const auto reference = bruteForce(hs, 1.0, desired);
    ASSERT_EQ(fast.has_value(), reference.has_value()) << "trial " << trial;
    if (!fast) {
      ++infeasible;
      continue;
    }
    ++feasible;
    EXPECT_TRUE(admissible(hs, 1.0, *fast)) << "trial " << trial;
    EXPECT_NEAR(geometry::distance(*fast, desired), geometry::distance(*reference, desired), 1e-9)
        << "trial " << trial;
  }
  // Both kinds must have been exercised for the comparison to mean something.
  EXPECT_GT(feasible, 500);
  EXPECT_GT(infeasible, 300);
}

TEST(VelocityLp, KeepsAnAdmissibleCommandAndCapsItsSpeed) {
  const std::vector<HalfPlane> hs{{{1, 0}, -0.5}};
  EXPECT_EQ(*closestAdmissibleVelocity(hs, 1.0, {0.3, 0.2}), (Vec2{0.3, 0.2}));
  const Vec2 capped = *closestAdmissibleVelocity({}, 2.0, {3, 4});
  EXPECT_NEAR(capped.x, 1.2, 1e-15);
  EXPECT_NEAR(capped.y, 1.6, 1e-15);
}

TEST(VelocityLp, ParallelHalfPlanesFacingApartLeaveNothing) {
  const std::vector<HalfPlane> hs{{{1, 0}, 0.2}, {{-1, 0}, 0.1}};  // x ≥ 0.2 and x ≤ −0.1
  EXPECT_FALSE(closestAdmissibleVelocity(hs, 1.0, {}).has_value());
}

TEST(VelocityLp, AHalfPlaneBeyondTheSpeedDiscLeavesNothing) {
  const std::vector<HalfPlane> hs{{{0, 1}, 1.5}};  // y ≥ 1.5 with ‖u‖ ≤ 1
  EXPECT_FALSE(closestAdmissibleVelocity(hs, 1.0, {0, 0}).has_value());
  // Exactly tangent: the single admissible point.
  const std::vector<HalfPlane> tangent{{{0, 1}, 1.0}};
  const Vec2 u = *closestAdmissibleVelocity(tangent, 1.0, {0.5, 0});
  EXPECT_NEAR(u.x, 0.0, 1e-9);
  EXPECT_NEAR(u.y, 1.0, 1e-12);
}

TEST(VelocityLp, LeastViolationIsTheSmallestRelaxationThatAdmitsAVelocity) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), coordinate(-2, 2);
  int checked = 0;
  for (int trial = 0; trial < 500; ++trial) {
    // A hard half-plane through the origin's side (admits u = 0), then soft ones.
    std::vector<HalfPlane> hs{{geometry::unitVector(angle(rng)), -0.3}};
    for (const auto& h : randomPlanes(rng, 2 + trial % 5))
      hs.push_back({h.normal, h.offset + 0.8});  // mostly beyond the disc: infeasible
    if (closestAdmissibleVelocity(hs, 1.0, {}).has_value()) continue;
    ++checked;
    const Vec2 desired{coordinate(rng), coordinate(rng)};
    const LeastViolation least = leastViolatingVelocity(hs, 1, 1.0, desired);
    ASSERT_GT(least.violation, 0.0);
    // The velocity keeps the hard half-plane and violates each soft one by at most s...
    EXPECT_TRUE(admissible(std::span(hs).first(1), 1.0, least.velocity));
    for (std::size_t i = 1; i < hs.size(); ++i)
      EXPECT_GE(geometry::dot(hs[i].normal, least.velocity), hs[i].offset - least.violation - 1e-9);
    // ...and no smaller s admits any velocity (the reference decides).
    std::vector<HalfPlane> tighter = hs;
    for (std::size_t i = 1; i < tighter.size(); ++i)
      tighter[i].offset -= least.violation - 1e-6;
    EXPECT_FALSE(bruteForce(tighter, 1.0, desired).has_value()) << "trial " << trial;
  }
  EXPECT_GT(checked, 200);
}

}  // namespace
}  // namespace camcov::safety
