#include "scene/scene_loader.h"

#include "util/fnv1a.h"

#include <fmt/format.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <span>

#include "scene/camera_keys.h"
#include "scene/motion_containment.h"
#include "scene/path_forms.h"
#include "scene/read_text.h"
#include "scene/scene_error.h"
#include "scene/scene_families.h"
#include "scene/scene_validation.h"
#include "scene/wkt.h"
#include "util/readable_number.h"
#include "util/strict_json.h"

namespace camcov::scene {
namespace {

using nlohmann::json;

// A JSON value together with where it sits in the file, so every error can say so.
class Node {
 public:
  Node(const json& value, std::string path, const std::string& file)
      : value_(value), path_(std::move(path)), file_(file) {}

  [[noreturn]] void fail(const std::string& problem) const {
    throw SceneError(file_, path_, problem);
  }

  const std::string& path() const { return path_; }
  bool has(const char* key) const { return value_.contains(key); }

  Node child(const char* key) const {
    if (!value_.contains(key)) {
      Node(value_, join(key), file_).fail("missing required key");
    }
    return Node(value_.at(key), join(key), file_);
  }
  Node element(std::size_t i) const {
    return Node(value_.at(i), path_ + "[" + std::to_string(i) + "]", file_);
  }

  const json& object(std::initializer_list<const char*> allowedKeys) const {
    return object(std::span(allowedKeys.begin(), allowedKeys.end()));
  }
  const json& object(std::span<const char* const> allowedKeys) const {
    if (!value_.is_object()) fail("expected an object, found " + typeName());
    // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
    for (const auto& item : value_.items()) {
      const std::string& key = item.key();
      if (std::none_of(allowedKeys.begin(), allowedKeys.end(),
                       [&](const char* k) { return key == k; })) {
        std::string allowed;
        for (const char* k : allowedKeys)
          allowed += std::string(allowed.empty() ? "" : ", ") + k;
        Node(value_, join(key.c_str()), file_).fail("unknown key (allowed here: " + allowed + ")");
      }
    }
    return value_;
  }
  std::size_t arraySize() const {
    if (!value_.is_array()) fail("expected an array, found " + typeName());
    return value_.size();
  }
  double number() const {
    if (!value_.is_number()) fail("expected a number, found " + typeName());
    const double v = value_.get<double>();
    if (!std::isfinite(v)) fail("number is not finite");
    return v;
  }
  bool boolean() const {
    if (!value_.is_boolean()) fail("expected true or false, found " + typeName());
    return value_.get<bool>();
  }
  std::string string() const {
    if (!value_.is_string()) fail("expected a string, found " + typeName());
    return value_.get<std::string>();
  }
  std::vector<geometry::Vec2> wktRing() const { return wktPoints(parseWktPolygonRing); }
  std::vector<geometry::Vec2> wktLineString() const { return wktPoints(parseWktLineString); }
  geometry::Vec2 wktPoint() const {
    return wktPoints([](std::string_view text) { return std::vector{parseWktPoint(text)}; })[0];
  }

 private:
  // The points `parse` (one of wkt.h's) reads from this string, each within range; the
  // parser's problems are this node's.
  template <class Parse>
  std::vector<geometry::Vec2> wktPoints(Parse&& parse) const {
    std::vector<geometry::Vec2> points;
    try {
      points = parse(string());
    } catch (const WktError& e) {
      fail(e.what());
    }
    for (std::size_t i = 0; i < points.size(); ++i)
      requireWithinRange(points[i], i);
    return points;
  }
  void requireWithinRange(geometry::Vec2 v, std::size_t index) const {
    if (std::abs(v.x) > kMaxCoordinate || std::abs(v.y) > kMaxCoordinate) {
      fail(fmt::format("coordinate {} ({} {}) lies beyond ±{} m", index, readableNumber(v.x),
                       readableNumber(v.y), readableNumber(kMaxCoordinate)));
    }
  }
  std::string join(const char* key) const { return path_.empty() ? key : path_ + "." + key; }
  std::string typeName() const { return value_.type_name(); }

  const json& value_;
  std::string path_;
  const std::string& file_;
};

// A shape as written, open: what edgeWeights and deformation keyframes correspond to, edge by
// edge and vertex by vertex.
geometry::Ring writtenRing(const Node& shapeNode) {
  geometry::Ring written = shapeNode.wktRing();
  if (written.size() > 1 && written.front() == written.back()) written.pop_back();
  return written;
}

// Shapes and the boundary: at least 3 distinct vertices, no zero-length edge, non-zero area,
// no self-intersection. Returns the ring normalised to open + counter-clockwise.
geometry::Ring simpleRing(const Node& node) {
  geometry::Ring ring = writtenRing(node);
  std::set<std::pair<double, double>> distinct;
  for (const auto& v : ring)
    distinct.insert({v.x, v.y});
  if (distinct.size() < 3) {
    node.fail("polygon needs at least 3 distinct vertices, has " + std::to_string(distinct.size()));
  }
  if (const std::string problem = describeRingDefect(ring); !problem.empty()) node.fail(problem);
  geometry::normalizeRing(ring);
  return ring;
}

// A path in any of its written forms, as the closed loop of waypoints kinematics follows
// (kinematics/path_motion.h): POINT stays, LINESTRING goes back and forth, POLYGON loops.
std::vector<geometry::Vec2> path(const Node& node) {
  const std::string keyword = wktKeyword(node.string());
  if (keyword == "POINT") return {node.wktPoint()};
  if (keyword == "LINESTRING") {
    std::vector<geometry::Vec2> loop = backAndForthLoop(node.wktLineString());
    if (loop.size() < 2) {
      node.fail(
          fmt::format("a {} path goes back and forth between at least 2 distinct points, "
                      "has 1; a static object's path is {}",
                      keyword, kPointForm));
    }
    return loop;
  }
  if (keyword != "POLYGON") {
    node.fail(
        fmt::format("invalid WKT '{}': {} is not a path; write {} (a static object), {} "
                    "(back and forth along it) or {} (a loop through the waypoints)",
                    node.string(), keyword.empty() ? "no geometry type" : keyword, kPointForm,
                    kLineStringForm, kPolygonForm));
  }
  std::vector<geometry::Vec2> waypoints = node.wktRing();
  if (waypoints.size() > 1) {
    double length = 0.0;
    for (std::size_t i = 0; i < waypoints.size(); ++i) {
      length += geometry::distance(waypoints[i], waypoints[(i + 1) % waypoints.size()]);
    }
    if (length == 0.0) {
      node.fail(fmt::format("path of {} waypoints has zero length; a static object's path is {}",
                            waypoints.size(), kPointForm));
    }
  }
  return waypoints;
}

// `unit` follows every number a message shows, so that "1.5" never has to be guessed at.
double positive(const Node& node, const char* what, const char* unit) {
  const double v = node.number();
  if (v <= 0.0) node.fail(fmt::format("{} must be positive, is {} {}", what, v, unit));
  return v;
}

double speed(const Node& node, const char* what, const char* unit) {
  const double v = node.number();
  if (std::abs(v) > kMaxSpeed)
    node.fail(fmt::format("{} {} {} exceeds {} {}", what, readableNumber(v), unit,
                          readableNumber(kMaxSpeed), unit));
  return v;
}

double positiveSpeed(const Node& node, const char* what, const char* unit) {
  positive(node, what, unit);
  return speed(node, what, unit);
}

Deformation deformation(const Node& node, const geometry::Ring& writtenShape) {
  node.object({"period", "keyframes"});
  Deformation result;
  result.period = positive(node.child("period"), "period", "s");
  const Node frames = node.child("keyframes");
  const std::size_t count = frames.arraySize();
  if (count == 0) frames.fail("needs at least one keyframe");
  double previous = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const Node frame = frames.element(i);
    frame.object({"time", "shape"});
    const Node timeNode = frame.child("time");
    const double time = timeNode.number();
    if (time <= previous || time >= result.period) {
      timeNode.fail("keyframe times (s) must increase strictly inside (0, period)");
    }
    previous = time;
    const Node shapeNode = frame.child("shape");
    geometry::Ring shape = shapeNode.wktRing();
    if (shape.size() > 1 && shape.front() == shape.back()) shape.pop_back();
    if (shape.size() != writtenShape.size()) {
      shapeNode.fail("keyframe has " + std::to_string(shape.size()) + " vertices, shape has " +
                     std::to_string(writtenShape.size()) + "; vertex i must match vertex i");
    }
    if ((geometry::signedArea(shape) > 0) != (geometry::signedArea(writtenShape) > 0)) {
      shapeNode.fail("keyframe is written in the opposite orientation to shape");
    }
    if (const std::string problem = describeRingDefect(shape); !problem.empty()) {
      shapeNode.fail(problem);
    }
    result.keyframes.push_back({time, std::move(shape)});
  }
  return result;
}

// "track": {"samples": [[t, x, y], ...]} or [[t, x, y, heading°], ...] (every sample alike).
Track track(const Node& node) {
  node.object({"samples"});
  const Node samples = node.child("samples");
  const std::size_t count = samples.arraySize();
  if (count == 0) samples.fail("a track needs at least one sample");
  Track result;
  std::size_t width = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const Node sample = samples.element(i);
    const std::size_t n = sample.arraySize();
    if (n != 3 && n != 4)
      sample.fail(fmt::format("a sample is [t, x, y] or [t, x, y, heading], has {} numbers", n));
    if (i == 0) width = n;
    if (n != width)
      sample.fail(fmt::format("every sample of a track has {} numbers, like the first", width));
    const double t = sample.element(0).number();
    if (t < 0.0) sample.element(0).fail(fmt::format("time {} s is negative", t));
    if (i > 0 && t <= result.times.back()) {
      sample.element(0).fail(
          fmt::format("times must increase strictly: {} s after {} s", t, result.times.back()));
    }
    const geometry::Vec2 p{sample.element(1).number(), sample.element(2).number()};
    if (std::abs(p.x) > kMaxCoordinate || std::abs(p.y) > kMaxCoordinate) {
      sample.fail(fmt::format("position ({} {}) lies beyond ±{} m", readableNumber(p.x),
                              readableNumber(p.y), readableNumber(kMaxCoordinate)));
    }
    result.times.push_back(t);
    result.positions.push_back(p);
    if (n == 4) result.headings.push_back(geometry::degToRad(sample.element(3).number()));
  }
  return result;
}

std::string colour(const Node& node) {
  const std::string text = node.string();
  const bool hex =
      text.size() == 7 && text[0] == '#' && std::all_of(text.begin() + 1, text.end(), [](char c) {
        return std::isxdigit(static_cast<unsigned char>(c)) != 0;
      });
  if (!hex) node.fail("a colour is written #rrggbb, is \"" + text + "\"");
  return text;
}

// An importance weight: finite, >= 0, at most kMaxWeight.
double weight(const Node& node, const char* what) {
  const double w = node.number();
  if (w < 0.0 || w > kMaxWeight)
    node.fail(fmt::format("{} must lie in [0, {}], is {}", what, kMaxWeight, w));
  return w;
}

// "edgeWeights": one weight per edge of the shape as written (edge i from vertex i to i + 1),
// returned in the order of the normalised ring's edges.
std::vector<double> edgeWeights(const Node& node, const Node& shapeNode) {
  const geometry::Ring written = writtenRing(shapeNode);
  const std::size_t n = written.size(), count = node.arraySize();
  if (count != n)
    node.fail(fmt::format("needs one weight per edge of the shape: {}, has {}", n, count));
  std::vector<double> weights;
  for (std::size_t i = 0; i < n; ++i)
    weights.push_back(weight(node.element(i), "an edge weight"));
  if (std::all_of(weights.begin(), weights.end(), [](double w) { return w == 0.0; }))
    node.fail("every edge weight is 0: the target would count for nothing (make it an obstacle)");
  // normalizeRing() reversed a clockwise ring: its edge k is the written edge n − 2 − k.
  if (geometry::signedArea(written) < 0.0) {
    std::reverse(weights.begin(), weights.end());
    std::rotate(weights.begin(), weights.begin() + 1, weights.end());
  }
  return weights;
}

FrontWeighting front(const Node& object) {
  FrontWeighting f;
  f.weight = weight(object.child("frontWeight"), "frontWeight");
  double degrees = kDefaultFrontAngle;
  if (object.has("frontAngle")) {
    const Node angle = object.child("frontAngle");
    degrees = angle.number();
    if (degrees <= 0.0 || degrees > 180.0)
      angle.fail(fmt::format("frontAngle must be in (0, 180] degrees, is {}°", degrees));
  }
  f.halfAngle = geometry::degToRad(degrees);
  return f;
}

// `isTarget`: importance weights are allowed (obstacles are not covered).
MovingObject movingObject(const Node& node, bool isTarget) {
  node.object({"shape", "path", "velocity", "angularVelocity", "deformation", "track", "color",
               "edgeWeights", "frontWeight", "frontAngle"});
  MovingObject object;
  const Node shapeNode = node.child("shape");
  object.shape = simpleRing(shapeNode);
  if (node.has("color")) object.color = colour(node.child("color"));
  for (const char* key : {"edgeWeights", "frontWeight", "frontAngle"}) {
    if (!isTarget && node.has(key))
      node.child(key).fail("an obstacle is not covered, so it has no importance weights");
  }
  if (node.has("frontAngle") && !node.has("frontWeight"))
    node.child("frontAngle").fail("frontAngle needs frontWeight");
  if (node.has("edgeWeights"))
    object.edgeWeights = edgeWeights(node.child("edgeWeights"), shapeNode);
  if (node.has("frontWeight")) object.front = front(node);
  if (node.has("track")) {
    // Recorded motion replaces the loop: the two cannot be mixed.
    for (const char* key : {"path", "velocity", "angularVelocity", "deformation"}) {
      if (node.has(key)) node.child(key).fail("an object with a track has no " + std::string(key));
    }
    object.track = track(node.child("track"));
    object.path = {object.track->positions.front()};
    return object;
  }
  object.path = path(node.child("path"));
  if (node.has("velocity"))
    object.velocity = positiveSpeed(node.child("velocity"), "velocity", "m/s");
  if (node.has("angularVelocity"))
    object.angularVelocity = speed(node.child("angularVelocity"), "angularVelocity", "rad/s");
  if (node.has("deformation")) {
    // Keyframes correspond vertex by vertex to the shape as written; normalise them together.
    const geometry::Ring written = writtenRing(shapeNode);
    Deformation d = deformation(node.child("deformation"), written);
    if (geometry::signedArea(written) < 0) {
      for (auto& frame : d.keyframes)
        std::reverse(frame.shape.begin(), frame.shape.end());
    }
    object.deformation = std::move(d);
    if (const std::string problem = describeDeformationDefect(object); !problem.empty()) {
      node.child("deformation").fail(problem);
    }
  }
  return object;
}

// The problems of a scene file, gathered so that one message names them all: each part that
// does not depend on another (the boundary, each object, each camera) is read on its own, and
// what it refuses is kept while the others are read.
class Problems {
 public:
  explicit Problems(std::string file) : file_(std::move(file)) {}
  // Runs `read`; a SceneError it throws is kept. Returns whether it succeeded.
  template <class Read>
  bool attempt(Read&& read) {
    try {
      read();
      return true;
    } catch (const SceneError& e) {
      found_.push_back({e.jsonPath(), e.problem()});
      return false;
    }
  }
  void add(PlacementDefect defect) { found_.push_back(std::move(defect)); }
  bool empty() const { return found_.empty(); }
  // SceneError naming the first problem's place, the others following it.
  void throwIfAny() const {
    if (found_.empty()) return;
    std::string others;
    for (std::size_t k = 1; k < found_.size(); ++k)
      others += "; " +
                (found_[k].jsonPath.empty() ? std::string("(top level)") : found_[k].jsonPath) +
                ": " + found_[k].problem;
    throw SceneError(file_, found_.front().jsonPath, found_.front().problem + others);
  }

 private:
  std::string file_;
  std::vector<PlacementDefect> found_;
};

std::vector<MovingObject> objects(const Node& node, Problems& problems, bool isTarget) {
  std::vector<MovingObject> result;
  for (std::size_t i = 0, n = node.arraySize(); i < n; ++i)
    problems.attempt([&] { result.push_back(movingObject(node.element(i), isTarget)); });
  return result;
}

// The value of a camera table row (camera_keys.h) in memory (radians for the file's degrees),
// within the row's limits.
double cameraKeyValue(const Node& node, const CameraKey& row) {
  const double v = node.number();
  if (const auto problem = row.problem(v)) node.fail(*problem);
  return row.fromFile(v);
}

// What a scene asks of its images: {"minDensity": ρ_min in pixels per metre, "proportional":
// false}.
ResolutionRequirement resolutionRequirement(const Node& node) {
  node.object({"minDensity", "proportional"});
  ResolutionRequirement requirement;
  const Node density = node.child("minDensity");
  requirement.minDensity = positive(density, "minDensity", "pixels per metre");
  if (requirement.minDensity > kMaxMinDensity)
    density.fail(fmt::format("minDensity {} pixels per metre lies beyond {}",
                             readableNumber(requirement.minDensity),
                             readableNumber(kMaxMinDensity)));
  if (node.has("proportional")) requirement.proportional = node.child("proportional").boolean();
  return requirement;
}

// `sceneCamera` holds the scene's values of the keys a camera may take from it ("cameraFoV",
// "imageWidth"), which the camera's own keys override.
CameraSpec camera(const Node& node, const CameraSpec& sceneCamera) {
  node.object(cameraEntryKeys());
  CameraSpec camera = sceneCamera;
  const geometry::Vec2 pos = node.child(kCameraPositionKey).wktPoint();
  camera.initial.x = pos.x;
  camera.initial.y = pos.y;
  for (const CameraKey& row : kCameraKeys)
    if (node.has(row.name) || !row.optional())
      row.set(camera, cameraKeyValue(node.child(row.name), row));
  return camera;
}

}  // namespace

Scene parseScene(std::string_view jsonText, const std::string& sourceName) {
  json document;
  try {
    document = parseStrictJson(jsonText);
  } catch (const json::exception& e) {  // parse errors, and numbers beyond double range
    throw SceneError(sourceName, "", std::string("invalid JSON: ") + e.what());
  } catch (const DuplicateJsonKey& e) {
    throw SceneError(sourceName, "", e.what());
  }
  const Node root(document, "", sourceName);
  std::vector<const char*> rootKeys{"boundary",    "targets",   "obstacles", "cameras",
                                    "description", "family",    "pitch",     "duration",
                                    "resolution",  "knowledge", "comms"};
  for (const CameraKey& row : kCameraKeys)
    if (row.atSceneLevel()) rootKeys.push_back(row.name);
  root.object(rootKeys);

  Scene scene;
  scene.name = std::filesystem::path(sourceName).stem().string();
  Problems problems(sourceName);
  problems.attempt([&] {
    if (root.has("description")) scene.description = root.child("description").string();
  });
  problems.attempt([&] {
    if (!root.has("family")) return;
    const Node node = root.child("family");
    scene.family = node.string();
    if (!isSceneFamily(scene.family))
      node.fail(fmt::format("\"{}\" is no family of `camcov generate --family list` ({})",
                            scene.family, familyNames()));
  });
  problems.attempt([&] { scene.boundary = simpleRing(root.child("boundary")); });
  problems.attempt([&] {
    if (!root.has("duration")) return;
    const Node node = root.child("duration");
    const double seconds = positive(node, "duration", "s");
    if (!(seconds <= kMaxDuration))
      node.fail(fmt::format("duration {} s lies beyond {} s", readableNumber(seconds),
                            readableNumber(kMaxDuration)));
    scene.duration = seconds;
  });
  // Kept as written: the parameter table, one stage up, owns their names and ranges.
  for (const char* group : {"knowledge", "comms"}) {
    problems.attempt([&] {
      if (!root.has(group)) return;
      const json& settings = document.at(group);
      if (!settings.is_object())
        root.child(group).fail("expected an object, as the group in a parameter file");
      scene.knowledgeSettings[group] = settings;
    });
  }
  problems.attempt([&] {
    if (!root.has("pitch")) return;
    const Node pitch = root.child("pitch");
    pitch.object({"length", "width"});
    const auto size = [](const Node& n, const char* what) {
      const double v = positive(n, what, "m");
      if (v > kMaxCoordinate)
        n.fail(fmt::format("{} {} m lies beyond {} m", what, readableNumber(v),
                           readableNumber(kMaxCoordinate)));
      return v;
    };
    scene.pitch = Pitch{size(pitch.child("length"), "length"), size(pitch.child("width"), "width")};
  });

  problems.attempt([&] {
    const Node targets = root.child("targets");
    const std::size_t written = targets.arraySize();
    scene.targets = objects(targets, problems, true);
    if (written == 0) targets.fail("a scene needs at least one target");
  });
  problems.attempt([&] {
    if (root.has("obstacles")) scene.obstacles = objects(root.child("obstacles"), problems, false);
  });

  // A camera without its own field of view or image width (the table's keys with a scene-level
  // fallback) takes the scene's; if that is bad, the cameras are still read for their own
  // problems.
  CameraSpec sceneCamera = cameraWithoutOptions();
  for (const CameraKey& row : kCameraKeys) {
    if (!row.atSceneLevel()) continue;
    problems.attempt([&] {
      if (root.has(row.name) || row.fallback == CameraKeyFallback::scene)
        row.set(sceneCamera, cameraKeyValue(root.child(row.name), row));
    });
  }
  problems.attempt([&] {
    if (root.has("resolution")) scene.resolution = resolutionRequirement(root.child("resolution"));
  });

  problems.attempt([&] {
    const Node cameras = root.child("cameras");
    const std::size_t cameraCount = cameras.arraySize();
    if (cameraCount == 0) cameras.fail("a scene needs at least one camera");
    if (cameraCount > kMaxCameras) {
      cameras.fail("at most " + std::to_string(kMaxCameras) + " cameras are supported, found " +
                   std::to_string(cameraCount));
    }
    for (std::size_t i = 0; i < cameraCount; ++i)
      problems.attempt([&] { scene.cameras.push_back(camera(cameras.element(i), sceneCamera)); });
  });
  // An image model and a requirement go together: either alone would say nothing.
  problems.attempt([&] {
    const bool required = scene.resolution.has_value();
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
      if (scene.cameras[i].lens.hasImage() == required) continue;
      root.child("cameras").element(i).fail(
          required ? "the scene's resolution needs every camera's imageWidth (pixels across "
                     "its field of view), here or at the top level"
                   : "imageWidth has no effect without the scene's \"resolution\": "
                     "{\"minDensity\": …} (pixels per metre a covered edge needs)");
    }
  });
  // Where the file's structure is wrong, placing its objects would judge a scene that is not
  // the one written.
  problems.throwIfAny();

  // Every misplaced camera or object at t = 0 and every object that leaves the boundary later,
  // at once.
  const std::vector<PlacementDefect> atStart = findPlacementDefects(scene);
  for (const PlacementDefect& d : atStart)
    problems.add(d);
  const MotionCheck motion = checkMotion(scene);
  for (const PlacementDefect& e : motion.errors) {
    // An object already misplaced at t = 0 is named once.
    const bool named = std::any_of(atStart.begin(), atStart.end(), [&](const PlacementDefect& d) {
      return d.jsonPath.starts_with(e.jsonPath + ".");
    });
    if (!named) problems.add(e);
  }
  problems.throwIfAny();
  for (const PlacementDefect& w : motion.warnings)
    scene.warnings.push_back(w.jsonPath + ": " + w.problem);
  return scene;
}

Scene loadScene(const std::filesystem::path& file) {
  return parseScene(readText(file), file.string());
}

SceneFile loadSceneFile(const std::filesystem::path& file) {
  const std::string text = readText(file);
  return {parseScene(text, file.string()), fnv1a(text)};
}

std::uint64_t sceneFileHash(const std::filesystem::path& file) {
  return fnv1a(readText(file));
}

}  // namespace camcov::scene
