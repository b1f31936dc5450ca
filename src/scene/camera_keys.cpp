#include "scene/camera_keys.h"

#include <cmath>

#include <fmt/format.h>

#include "geometry/vec2.h"
#include "scene/scene_writer.h"
#include "util/readable_number.h"

namespace camcov::scene {

bool CameraKey::carried(const CameraSpec& camera) const {
  const bool switchable =
      fallback == CameraKeyFallback::absent || fallback == CameraKeyFallback::sceneOrAbsent;
  return !switchable || get(camera) != absent;
}

std::optional<std::string> CameraKey::problem(double v) const {
  // Written so that NaN fails every comparison, and so every check.
  const bool aboveLower = lowerOpen ? v > lower : v >= lower;
  const bool belowUpper = upperOpen ? v < upper : v <= upper;
  const std::string value = readableNumber(v);
  if (integral && !(aboveLower && belowUpper && v == std::floor(v))) {
    const double smallest = lowerOpen ? std::floor(lower) + 1.0 : std::ceil(lower);
    return fmt::format("{} must be a whole number of {} from {} to {}, is {}", what, unit,
                       readableNumber(smallest), readableNumber(upper), value);
  }
  if (aboveLower && belowUpper) return std::nullopt;
  const std::string because = note ? fmt::format(" ({})", note) : "";
  if (!aboveLower && lower == 0.0 && lowerOpen && (cap || std::isinf(upper)))
    return fmt::format("{} must be positive, is {} {}", what, value, unit);
  if (aboveLower && std::isinf(upper))
    return fmt::format("{} must be finite, is {} {}{}", what, value, unit, because);
  if (aboveLower && cap)
    return fmt::format("{} {} {} exceeds {} {}", what, value, unit, readableNumber(upper), unit);
  return fmt::format("{} must be in {}{}, {}{} {}{}, is {} {}", what, lowerOpen ? "(" : "[",
                     readableNumber(lower), readableNumber(upper), upperOpen ? ")" : "]", unit,
                     because, value, unit);
}

double CameraKey::fromFile(double v) const {
  return degrees ? geometry::degToRad(v) : v;
}

double CameraKey::toFile(double v) const {
  return degrees ? writtenDegrees(v) : v;
}

const CameraKey* cameraKeyNamed(std::string_view key) {
  for (const CameraKey& row : kCameraKeys)
    if (key == row.name) return &row;
  return nullptr;
}

std::array<const char*, kCameraKeys.size() + 1> cameraEntryKeys() {
  std::array<const char*, kCameraKeys.size() + 1> keys{kCameraPositionKey};
  for (std::size_t k = 0; k < kCameraKeys.size(); ++k)
    keys[k + 1] = kCameraKeys[k].name;
  return keys;
}

CameraSpec cameraWithoutOptions() {
  CameraSpec camera;
  for (const CameraKey& row : kCameraKeys)
    if (row.optional()) row.set(camera, row.absent);
  return camera;
}

}  // namespace camcov::scene
