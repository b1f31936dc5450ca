#pragma once
// Plain 2D vector and SE(2) pose: the vocabulary every stage above speaks.
// Deliberately not Eigen: these are copied by the million in the visibility sweep and a
// trivially copyable aggregate keeps that loop free of expression templates.
#include <cmath>
#include <numbers>

namespace camcov::geometry {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator-() const { return {-x, -y}; }
  constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
  constexpr Vec2 operator/(double s) const { return {x / s, y / s}; }
  constexpr Vec2& operator+=(Vec2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  constexpr Vec2& operator-=(Vec2 o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  constexpr bool operator==(const Vec2&) const = default;
};

constexpr Vec2 operator*(double s, Vec2 v) {
  return v * s;
}
constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
// z-component of the 3D cross product: > 0 when b is counter-clockwise from a.
constexpr double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
constexpr double norm2(Vec2 a) {
  return dot(a, a);
}
// sqrt of the sum, not std::hypot: hypot guards against overflow that metre-scale
// coordinates never reach, and is several times slower in the hot loops.
inline double norm(Vec2 a) {
  return std::sqrt(norm2(a));
}
inline double distance(Vec2 a, Vec2 b) {
  return norm(a - b);
}
// Twice the signed area of triangle (a, b, c): > 0 for a left turn a -> b -> c.
constexpr double orient(Vec2 a, Vec2 b, Vec2 c) {
  return cross(b - a, c - a);
}
inline Vec2 rotated(Vec2 v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}
inline Vec2 lerp(Vec2 a, Vec2 b, double u) {
  return a + (b - a) * u;
}
inline Vec2 unitVector(double angle) {
  return {std::cos(angle), std::sin(angle)};
}

// The paper keeps every angle in [-π, π] (section II); this maps any finite angle there.
inline double wrapAngle(double a) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  a = std::remainder(a, kTwoPi);  // exact, in [-π, π]
  return a;
}

inline double degToRad(double deg) {
  return deg * std::numbers::pi / 180.0;
}
inline double radToDeg(double rad) {
  return rad * 180.0 / std::numbers::pi;
}

// Camera pose p = [x, y, γ] ∈ SE(2) (paper section II); γ (yaw) in radians.
struct Pose {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;

  constexpr Vec2 position() const { return {x, y}; }
  // Coordinate `axis` of SE(2): 0 x, 1 y, 2 yaw (not wrapped: the caller decides), for
  // searches that probe one axis at a time.
  constexpr double& operator[](int axis) { return axis == 0 ? x : axis == 1 ? y : yaw; }
  constexpr bool operator==(const Pose&) const = default;
};

}  // namespace camcov::geometry
