#pragma once
// Bit-for-bit equality of the numbers a kept result was computed from: a cache (the sweep's
// per-camera memo, the reward's incremental terms) reuses a result only for exactly the inputs
// that made it, so it is the one a new computation would give (−0 and +0 differ here).
// Compared as bytes (memcmp), not std::bit_cast, which the WebAssembly toolchain's library
// lacks; the compilers make both the same few integer compares.
#include <cstring>
#include <span>

#include "geometry/vec2.h"

namespace camcov::geometry {

static_assert(sizeof(Vec2) == 2 * sizeof(double) && sizeof(Pose) == 3 * sizeof(double),
              "no padding: equal bytes are equal numbers");

inline bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

inline bool sameBits(const geometry::Pose& a, const geometry::Pose& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

inline bool sameBits(geometry::Vec2 a, geometry::Vec2 b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// The same count of numbers, each with the same bits (a ring's vertices, an edge list's weights).
template <typename T>
bool sameBits(std::span<const T> a, std::span<const T> b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size_bytes()) == 0);
}

}  // namespace camcov::geometry
