#include "scene/pitch_markings.h"

#include <cmath>
#include <numbers>

namespace camcov::scene {
namespace {

using geometry::Vec2;

constexpr double kCentreCircle = 9.15;
constexpr double kPenaltyDepth = 16.5, kPenaltyWidth = 40.32, kPenaltySpot = 11.0;
constexpr double kGoalAreaDepth = 5.5, kGoalAreaWidth = 18.32;
constexpr double kSpot = 0.2;  // radius the spots are drawn with
constexpr int kArcSteps = 48;  // per full circle

std::vector<Vec2> outline(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}};
}

// The arc of the circle about `c` from angle a0 to a1 (radians, counter-clockwise).
std::vector<Vec2> arc(Vec2 c, double r, double a0, double a1) {
  const int steps =
      std::max(2, static_cast<int>(std::ceil(kArcSteps * (a1 - a0) / (2 * std::numbers::pi))));
  std::vector<Vec2> out;
  for (int k = 0; k <= steps; ++k) {
    const double a = a0 + (a1 - a0) * k / steps;
    out.push_back(c + Vec2{r * std::cos(a), r * std::sin(a)});
  }
  return out;
}

}  // namespace

std::vector<std::vector<Vec2>> pitchMarkings(const Pitch& pitch) {
  const double l = pitch.length, w = pitch.width, mid = w / 2;
  std::vector<std::vector<Vec2>> lines{outline(0, 0, l, w),
                                       {{l / 2, 0}, {l / 2, w}},
                                       arc({l / 2, mid}, kCentreCircle, 0, 2 * std::numbers::pi),
                                       arc({l / 2, mid}, kSpot, 0, 2 * std::numbers::pi)};
  // Each end: x measured from its goal line, mirrored for the far end.
  for (const double side : {1.0, -1.0}) {
    const double goal = side > 0 ? 0.0 : l;
    const auto x = [&](double d) { return goal + side * d; };
    lines.push_back(outline(std::min(x(0), x(kPenaltyDepth)), mid - kPenaltyWidth / 2,
                            std::max(x(0), x(kPenaltyDepth)), mid + kPenaltyWidth / 2));
    lines.push_back(outline(std::min(x(0), x(kGoalAreaDepth)), mid - kGoalAreaWidth / 2,
                            std::max(x(0), x(kGoalAreaDepth)), mid + kGoalAreaWidth / 2));
    const Vec2 spot{x(kPenaltySpot), mid};
    lines.push_back(arc(spot, kSpot, 0, 2 * std::numbers::pi));
    // The penalty arc: the part of the 9.15 m circle about the spot outside the area.
    const double half = std::acos((kPenaltyDepth - kPenaltySpot) / kCentreCircle);
    lines.push_back(
        side > 0 ? arc(spot, kCentreCircle, -half, half)
                 : arc(spot, kCentreCircle, std::numbers::pi - half, std::numbers::pi + half));
  }
  return lines;
}

}  // namespace camcov::scene
