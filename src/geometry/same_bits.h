#pragma once
// Bit-for-bit equality of the numbers a kept result was computed from: a cache (the sweep's
// per-camera memo, the reward's incremental terms) reuses a result only for exactly the inputs
// that made it, so it is the one a new computation would give (−0 and +0 differ here).
#include <array>
#include <bit>
#include <cstdint>

#include "geometry/vec2.h"

namespace camcov::geometry {

inline bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

inline bool sameBits(const geometry::Pose& a, const geometry::Pose& b) {
  return std::bit_cast<std::array<std::uint64_t, 3>>(a) ==
         std::bit_cast<std::array<std::uint64_t, 3>>(b);
}

inline bool sameBits(geometry::Vec2 a, geometry::Vec2 b) {
  return std::bit_cast<std::array<std::uint64_t, 2>>(a) ==
         std::bit_cast<std::array<std::uint64_t, 2>>(b);
}

}  // namespace camcov::geometry
