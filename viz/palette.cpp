#include "viz/palette.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace camcov::viz {

double viewAlphaFor(std::size_t cameras) {
  constexpr double kFloorShowingThrough = 0.17;
  if (cameras == 0) return kViewAlpha;
  return std::min(kViewAlpha,
                  1.0 - std::pow(kFloorShowingThrough, 1.0 / static_cast<double>(cameras)));
}

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

std::optional<Rgb> rgbFromHex(std::string_view hex) {
  if (hex.size() != 7 || hex[0] != '#') return std::nullopt;
  unsigned value = 0;
  for (const char c : hex.substr(1)) {
    const int digit = std::isdigit(static_cast<unsigned char>(c)) ? c - '0'
                      : std::isxdigit(static_cast<unsigned char>(c))
                          ? std::tolower(static_cast<unsigned char>(c)) - 'a' + 10
                          : -1;
    if (digit < 0) return std::nullopt;
    value = value * 16 + static_cast<unsigned>(digit);
  }
  return Rgb{(value >> 16 & 255) / 255.0, (value >> 8 & 255) / 255.0, (value & 255) / 255.0};
}

}  // namespace camcov::viz
