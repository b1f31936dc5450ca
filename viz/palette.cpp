#include "viz/palette.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace camcov::viz {

Rgb seenByColour(int cameras) {
  if (cameras <= 0) return kUnseen;
  // Each further camera darkens the green by a fifth, down to three.
  const double shade = std::pow(0.8, std::min(cameras, 3) - 1);
  return {kSeen.r * shade, kSeen.g * shade, kSeen.b * shade};
}

std::string cssColour(Rgb c) {
  const auto byte = [](double v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
  };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
}

}  // namespace camcov::viz
