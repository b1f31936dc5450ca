#pragma once
// Every number a scene file gives a camera, declared once: its key, unit, limits, what a camera
// without it takes, whether it changes what the camera sees (sensing) or how it moves
// (kinematic), and where CameraSpec keeps it. The loader checks a camera's keys by this table,
// the writer writes them by it, describeCamera shows them by it (`camcov state`, the explorer's
// camera panel, Python's Scene.cameras), Python's hand-made lenses take one array per sensing
// key, and the observation encoding's camera slot holds a column per observed row. A new camera
// property is a row here, a field of CameraSpec, and the code that acts on it (the sweep, say).
// The camera's position, the one key that is not a number, is `pos` (a WKT point).
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "scene/camera.h"
#include "scene/scene_validation.h"

namespace camcov::scene {

inline constexpr const char* kCameraPositionKey = "pos";

// Whether a property changes what a camera sees (its lens) or how it moves.
enum class CameraKeyKind { kinematic, sensing };

// What a camera that leaves its key out takes.
enum class CameraKeyFallback {
  required,       // nothing: every camera gives the key
  scene,          // the scene's top-level key of the same name, which every file gives
  sceneOrAbsent,  // the scene's key if the file gives one, else `absent`
  absent,         // `absent`, the property switched off (e.g. a range without limit)
};

// What a property measures, in memory: how the observation encoding scales an observed one.
enum class CameraQuantity { angle, length, rate, pixels };

// The rows, in the table's order (the order of the observation encoding's columns too).
enum class CameraKeyId : std::size_t {
  angle,
  maxVelocity,
  maxAngularVelocity,
  cameraFoV,
  sensingRange,
  imageWidth,
};

struct CameraKey {
  CameraKeyId id;
  const char* name;  // the scene file's key
  const char* what;  // what an error message calls it
  const char* unit;  // in the file
  CameraKeyKind kind;
  CameraQuantity quantity;
  // The file's values lie from `lower` to `upper`, an end excluded if open. A `cap` upper bound
  // guards against overflow rather than saying what the value means ("exceeds" in a message).
  double lower;
  bool lowerOpen;
  double upper;
  bool upperOpen;
  bool cap;
  bool integral;  // a whole number
  CameraKeyFallback fallback;
  double absent;     // in memory: the value of a camera without the property
  bool degrees;      // the file gives degrees, memory holds radians
  bool observed;     // a column of the observation encoding's camera slot
  const char* note;  // added to an error message in parentheses, or nullptr
  double (*get)(const CameraSpec&);
  void (*set)(CameraSpec&, double);

  bool optional() const { return fallback != CameraKeyFallback::required; }
  bool atSceneLevel() const {
    return fallback == CameraKeyFallback::scene || fallback == CameraKeyFallback::sceneOrAbsent;
  }
  // Whether `camera` has the property switched on (a row with an `absent` value), so that a
  // description or a written file shows the key.
  bool carried(const CameraSpec& camera) const;
  // What is wrong with the file's value `v`, or nothing.
  std::optional<std::string> problem(double v) const;
  // The value in memory from the file's, and back (degrees as written: 30, not 29.999…).
  double fromFile(double v) const;
  double toFile(double v) const;
};

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

inline constexpr std::array<CameraKey, 6> kCameraKeys{{
    {.id = CameraKeyId::angle,
     .name = "angle",
     .what = "angle",
     .unit = "degrees",
     .kind = CameraKeyKind::kinematic,
     .quantity = CameraQuantity::angle,
     .lower = -kUnbounded,
     .lowerOpen = true,
     .upper = kUnbounded,
     .upperOpen = true,
     .cap = false,
     .integral = false,
     .fallback = CameraKeyFallback::required,
     .absent = 0.0,
     .degrees = true,
     .observed = false,  // the pose at t is observed, as cos γ and sin γ
     .note = nullptr,
     .get = [](const CameraSpec& c) { return c.initial.yaw; },
     .set = [](CameraSpec& c, double v) { c.initial.yaw = geometry::wrapAngle(v); }},
    {.id = CameraKeyId::maxVelocity,
     .name = "maxVelocity",
     .what = "maxVelocity",
     .unit = "m/s",
     .kind = CameraKeyKind::kinematic,
     .quantity = CameraQuantity::length,
     .lower = 0.0,
     .lowerOpen = true,
     .upper = kMaxSpeed,
     .upperOpen = false,
     .cap = true,
     .integral = false,
     .fallback = CameraKeyFallback::required,
     .absent = 0.0,
     .degrees = false,
     .observed = true,
     .note = nullptr,
     .get = [](const CameraSpec& c) { return c.maxVelocity; },
     .set = [](CameraSpec& c, double v) { c.maxVelocity = v; }},
    {.id = CameraKeyId::maxAngularVelocity,
     .name = "maxAngularVelocity",
     .what = "maxAngularVelocity",
     .unit = "rad/s",
     .kind = CameraKeyKind::kinematic,
     .quantity = CameraQuantity::rate,
     .lower = 0.0,
     .lowerOpen = true,
     .upper = kMaxSpeed,
     .upperOpen = false,
     .cap = true,
     .integral = false,
     .fallback = CameraKeyFallback::required,
     .absent = 0.0,
     .degrees = false,
     .observed = true,
     .note = nullptr,
     .get = [](const CameraSpec& c) { return c.maxAngularVelocity; },
     .set = [](CameraSpec& c, double v) { c.maxAngularVelocity = v; }},
    {.id = CameraKeyId::cameraFoV,
     .name = "cameraFoV",
     .what = "the half-angle θ of the field of view",
     .unit = "degrees",
     .kind = CameraKeyKind::sensing,
     .quantity = CameraQuantity::angle,
     .lower = 0.0,
     .lowerOpen = true,
     .upper = 180.0,
     .upperOpen = true,
     .cap = false,
     .integral = false,
     .fallback = CameraKeyFallback::scene,
     .absent = 0.0,
     .degrees = true,
     .observed = true,
     .note = "the field of view is 2θ wide",
     .get = [](const CameraSpec& c) { return c.lens.halfFov; },
     .set = [](CameraSpec& c, double v) { c.lens.halfFov = v; }},
    {.id = CameraKeyId::sensingRange,
     .name = "sensingRange",
     .what = "sensingRange",
     .unit = "m",
     .kind = CameraKeyKind::sensing,
     .quantity = CameraQuantity::length,
     .lower = 0.0,
     .lowerOpen = true,
     .upper = kUnbounded,
     .upperOpen = true,
     .cap = false,
     .integral = false,
     .fallback = CameraKeyFallback::absent,
     .absent = kUnlimitedRange,
     .degrees = false,
     .observed = true,  // 0 when unlimited
     .note = "leave the key out for a camera that sees without limit",
     .get = [](const CameraSpec& c) { return c.lens.range; },
     .set = [](CameraSpec& c, double v) { c.lens.range = v; }},
    {.id = CameraKeyId::imageWidth,
     .name = "imageWidth",
     .what = "imageWidth",
     .unit = "pixels",
     .kind = CameraKeyKind::sensing,
     .quantity = CameraQuantity::pixels,
     .lower = 1.0,
     .lowerOpen = false,
     .upper = kMaxImageWidth,
     .upperOpen = false,
     .cap = false,
     .integral = true,
     .fallback = CameraKeyFallback::sceneOrAbsent,
     .absent = 0.0,
     .degrees = false,
     .observed = false,
     .note = nullptr,
     .get = [](const CameraSpec& c) { return c.lens.imageWidth; },
     .set = [](CameraSpec& c, double v) { c.lens.imageWidth = v; }},
}};

constexpr std::size_t index(CameraKeyId id) {
  return static_cast<std::size_t>(id);
}
constexpr const CameraKey& cameraKey(CameraKeyId id) {
  return kCameraKeys[index(id)];
}
consteval bool rowsInIdOrder() {
  for (std::size_t k = 0; k < kCameraKeys.size(); ++k)
    if (index(kCameraKeys[k].id) != k) return false;
  return true;
}
static_assert(rowsInIdOrder(), "kCameraKeys lists its rows in CameraKeyId's order");

// How many rows the observation encoding shows (`observed`).
consteval std::size_t observedCameraKeyCount() {
  std::size_t n = 0;
  for (const CameraKey& row : kCameraKeys)
    n += row.observed ? 1 : 0;
  return n;
}

// The row named `key` in a scene file, or nullptr.
const CameraKey* cameraKeyNamed(std::string_view key);

// Every key a camera entry may hold: pos, then the table's.
std::array<const char*, kCameraKeys.size() + 1> cameraEntryKeys();

// A camera with every optional property switched off (its `absent` value).
CameraSpec cameraWithoutOptions();

}  // namespace camcov::scene
