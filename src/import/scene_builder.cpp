#include "import/scene_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/ring.h"
#include "scene/scene_writer.h"
#include "util/counted.h"
#include "util/input_error.h"
#include "util/readable_number.h"

namespace camcov::import {
namespace {

using geometry::Vec2;

constexpr int kDiscVertices = 12;
constexpr double kCameraInset = 1.0;  // m inside the boundary

// Kept to the millimetre (scene::mm) and the microsecond: files stay small and read the same
// everywhere.
using scene::mm;
double us(double v) {
  return std::round(v * 1e6) / 1e6;
}

// To the millimetre, as the file gives it.
geometry::Ring mmRing(const geometry::Ring& ring) {
  geometry::Ring out;
  for (const Vec2 p : ring)
    out.push_back({mm(p.x), mm(p.y)});
  return out;
}

geometry::Ring disc(Vec2 centre, double radius) {
  geometry::Ring ring;
  for (int k = 0; k < kDiscVertices; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kDiscVertices;
    ring.push_back(centre + Vec2{radius * std::cos(a), radius * std::sin(a)});
  }
  return ring;
}

geometry::Ring wallRing(const Wall& w, double thickness) {
  const Vec2 d = w.b - w.a;
  const double length = geometry::norm(d);
  const Vec2 n =
      length > 0.0 ? Vec2{-d.y, d.x} * (0.5 * thickness / length) : Vec2{0.0, 0.5 * thickness};
  const Vec2 along = length > 0.0 ? d * (0.5 * thickness / length) : Vec2{0.5 * thickness, 0.0};
  // Ends extended by half the thickness, so walls that meet at a corner close it.
  const Vec2 a = w.a - along, b = w.b + along;
  return {a - n, b - n, b + n, a + n};
}

// A track's samples inside the window, shifted to start the scene's clock at `from`, split at
// gaps longer than maxGap.
std::vector<RecordedTrack> cut(const RecordedTrack& track, const SceneOptions& o) {
  std::vector<RecordedTrack> pieces;
  for (std::size_t k = 0; k < track.times.size(); ++k) {
    const double t = track.times[k];
    if (t < o.from - 1e-9 || t > o.to + 1e-9) continue;
    const bool gap = !pieces.empty() && t - o.from - pieces.back().times.back() > o.maxGap + 1e-9;
    if (pieces.empty() || gap) {
      RecordedTrack piece = track;
      piece.times.clear();
      piece.positions.clear();
      piece.headings.clear();
      if (!pieces.empty()) piece.id = fmt::format("{}#{}", track.id, pieces.size() + 1);
      pieces.push_back(std::move(piece));
    }
    pieces.back().times.push_back(us(t - o.from));
    pieces.back().positions.push_back(track.positions[k]);
    if (!track.headings.empty()) pieces.back().headings.push_back(track.headings[k]);
  }
  return pieces;
}

bool crossesAWall(const RecordedTrack& track, const std::vector<Wall>& walls) {
  for (std::size_t k = 0; k + 1 < track.positions.size(); ++k) {
    for (const Wall& w : walls) {
      if (geometry::segmentsIntersect(track.positions[k], track.positions[k + 1], w.a, w.b))
        return true;
    }
  }
  return false;
}

// The radius of the disc a tracked person or ball is: its own where the recording gives one.
double discRadius(const RecordedTrack& track, const SceneOptions& o) {
  if (track.radius > 0.0) return track.radius;
  return track.kind == "ball" ? o.ballRadius : o.personRadius;
}

constexpr double kTick = 0.1;  // s between the instants people are counted at

// How many of `tracks` are present (from their first sample to their last, as the scene
// format has it) at each tick from 0 to the last sample.
std::vector<int> presentPerTick(const std::vector<RecordedTrack>& tracks) {
  double end = 0.0;
  for (const auto& t : tracks)
    end = std::max(end, t.times.back());
  std::vector<int> present(static_cast<std::size_t>(std::floor(end / kTick + 1e-9)) + 1, 0);
  for (const auto& t : tracks) {
    const auto first = static_cast<std::size_t>(std::ceil(t.times.front() / kTick - 1e-9));
    const auto last = static_cast<std::size_t>(std::floor(t.times.back() / kTick + 1e-9));
    for (std::size_t i = first; i <= last && i < present.size(); ++i)
      ++present[i];
  }
  return present;
}

// The start (a whole second) of the `length` s window with the most people present on
// average, counting them as the scene will: tracks split at gaps longer than maxGap.
double busiestStart(const Recording& recording, double length, double maxGap) {
  SceneOptions whole;
  whole.maxGap = maxGap;
  std::vector<RecordedTrack> people;
  for (const auto& t : recording.tracks) {
    if (t.kind == "ball") continue;
    for (auto& piece : cut(t, whole))
      people.push_back(std::move(piece));
  }
  if (people.empty()) return 0.0;
  const std::vector<int> present = presentPerTick(people);
  const auto window = static_cast<std::size_t>(std::llround(length / kTick));
  const auto ticksPerSecond = static_cast<std::size_t>(std::llround(1.0 / kTick));
  // Prefix sums: the count over any window in one subtraction, so the search is linear in the
  // recording's length whatever the window's.
  std::vector<long> before(present.size() + 1, 0);  // before[i]: present[0] + ... + present[i-1]
  for (std::size_t i = 0; i < present.size(); ++i)
    before[i + 1] = before[i] + present[i];
  std::size_t best = 0;
  long bestSum = -1;
  for (std::size_t first = 0; first == 0 || first + window <= present.size();
       first += ticksPerSecond) {
    const long sum = before[std::min(present.size(), first + window)] - before[first];
    if (sum > bestSum) {
      bestSum = sum;
      best = first;
    }
  }
  return static_cast<double>(best) * kTick;
}

// The tracks the window keeps, cut where they vanish too long, in order of appearance, then by
// id (the same recording gives the same file); what was left out or cut is said in `notes`.
struct Selected {
  std::vector<RecordedTrack> targets, movingObstacles;
};
Selected selectTracks(const Recording& recording, const SceneOptions& o,
                      std::vector<std::string>& notes) {
  Selected kept;
  int split = 0, outside = 0, crossing = 0, ballsLeftOut = 0;
  for (const RecordedTrack& track : recording.tracks) {
    const bool ball = track.kind == "ball";
    if (ball && o.ball == BallAs::None) {
      ++ballsLeftOut;
      continue;
    }
    std::vector<RecordedTrack> pieces = cut(track, o);
    if (pieces.empty()) ++outside;
    if (pieces.size() > 1) ++split;
    for (auto& piece : pieces) {
      if (crossesAWall(piece, recording.walls)) ++crossing;
      (ball && o.ball == BallAs::Obstacle ? kept.movingObstacles : kept.targets)
          .push_back(std::move(piece));
    }
  }
  if (kept.targets.empty()) {
    throw InputError(fmt::format("{}: no {} in the window [{}, {}] s: nothing to cover",
                                 recording.source, recording.onPitch ? "player" : "person", o.from,
                                 o.to));
  }
  const auto byAppearance = [](const RecordedTrack& a, const RecordedTrack& b) {
    return a.times.front() != b.times.front() ? a.times.front() < b.times.front() : a.id < b.id;
  };
  std::stable_sort(kept.targets.begin(), kept.targets.end(), byAppearance);
  std::stable_sort(kept.movingObstacles.begin(), kept.movingObstacles.end(), byAppearance);
  if (ballsLeftOut > 0) notes.push_back("the ball is left out (--ball target|obstacle keeps it)");
  if (outside > 0)
    notes.push_back(
        fmt::format("{} no sample in the window", counted(outside, "track has", "tracks have")));
  if (split > 0) {
    notes.push_back(
        fmt::format("{} for more than {} s and {} back: each return is a new target (id#2, ...)",
                    counted(split, "track vanishes", "tracks vanish"), o.maxGap,
                    split == 1 ? "comes" : "come"));
  }
  if (crossing > 0) {
    notes.push_back(fmt::format(
        "{} a wall (recording noise): kept as recorded; walls occlude and block cameras but do "
        "not stop people",
        counted(crossing, "track crosses", "tracks cross")));
  }
  return kept;
}

// The boundary: the box around everything plus the margin, and on a pitch at least the pitch
// with its run-off (a player recorded beyond it, by noise or off the field, grows it: the
// boundary holds every object at all times, SPEC section 2), on whole metres.
geometry::Box boundaryBox(const Recording& recording, const Selected& kept, const SceneOptions& o,
                          std::vector<std::string>& notes) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  const auto grow = [&](Vec2 p, double r) {
    x0 = std::min(x0, p.x - r), y0 = std::min(y0, p.y - r);
    x1 = std::max(x1, p.x + r), y1 = std::max(y1, p.y + r);
  };
  for (const auto& t : kept.targets)
    for (const Vec2 p : t.positions)
      grow(p, discRadius(t, o));
  for (const auto& t : kept.movingObstacles)
    for (const Vec2 p : t.positions)
      grow(p, discRadius(t, o));
  for (const Wall& w : recording.walls) {
    grow(w.a, o.wallThickness);
    grow(w.b, o.wallThickness);
  }
  for (const Pillar& p : recording.pillars)
    grow(p.centre, p.radius);
  x0 -= o.margin, y0 -= o.margin, x1 += o.margin, y1 += o.margin;
  if (recording.onPitch) {
    const double runOff[] = {-o.margin, -o.margin, recording.pitch.length + o.margin,
                             recording.pitch.width + o.margin};
    if (x0 < runOff[0] || y0 < runOff[1] || x1 > runOff[2] || y1 > runOff[3]) {
      notes.push_back(fmt::format(
          "someone is recorded beyond the pitch's {} m run-off: the boundary grows to hold them",
          o.margin));
    }
    x0 = std::min(x0, runOff[0]), y0 = std::min(y0, runOff[1]);
    x1 = std::max(x1, runOff[2]), y1 = std::max(y1, runOff[3]);
  }
  return {{std::floor(x0), std::floor(y0)}, {std::ceil(x1), std::ceil(y1)}};
}

std::string describeScene(const Recording& recording, const SceneOptions& o) {
  if (!o.description.empty()) return o.description;
  const std::string until = std::isinf(o.to) ? std::string("its end") : fmt::format("{} s", o.to);
  return recording.onPitch
             ? fmt::format(
                   "Football players recorded in {} (Last Row, Friends of Tracking) on a {} m "
                   "x {} m pitch, {} s to {}",
                   recording.source, recording.pitch.length, recording.pitch.width, o.from, until)
             : fmt::format(
                   "Pedestrians recorded in {} (ETH/UCY via OpenTraj), {} s to {} of the "
                   "recording",
                   recording.source, o.from, until);
}

// The camera team unless the options give one: evenly along a rectangle kCameraInset inside the
// boundary, each moved on until 0.5 m clear of `solid`, looking at the centre.
std::vector<geometry::Pose> cameraTeam(const SceneOptions& o, const geometry::Box& box,
                                       const std::vector<geometry::Ring>& solid) {
  if (o.cameraPoses) return *o.cameraPoses;
  const auto [x0, y0] = box.min;
  const auto [x1, y1] = box.max;
  const Vec2 centre{(x0 + x1) / 2, (y0 + y1) / 2};
  const geometry::Ring inner{{x0 + kCameraInset, y0 + kCameraInset},
                             {x1 - kCameraInset, y0 + kCameraInset},
                             {x1 - kCameraInset, y1 - kCameraInset},
                             {x0 + kCameraInset, y1 - kCameraInset}};
  const double perimeter = geometry::perimeter(inner);
  const auto along = [&](double s) {  // the point at arc length s of the inner rectangle
    s = std::fmod(s, perimeter);
    for (std::size_t i = 0;; i = (i + 1) % 4) {
      const Vec2 a = inner[i], b = inner[(i + 1) % 4];
      const double l = geometry::distance(a, b);
      if (s <= l) return geometry::lerp(a, b, s / l);
      s -= l;
    }
  };
  const auto free = [&](Vec2 p) {
    return std::none_of(solid.begin(), solid.end(), [&](const geometry::Ring& r) {
      return geometry::distanceToPolygon(r, p) < 0.5;
    });
  };
  std::vector<geometry::Pose> poses;
  for (int j = 0; j < o.cameras; ++j) {
    double s = perimeter * (j + 0.5) / o.cameras;
    Vec2 p = along(s);
    for (int tries = 0; !free(p) && tries < 1000; ++tries)
      p = along(s += 0.25);
    const Vec2 d = centre - p;
    poses.push_back({mm(p.x), mm(p.y), std::atan2(d.y, d.x)});
  }
  return poses;
}

}  // namespace

BuiltScene buildScene(const Recording& recording, const SceneOptions& options) {
  SceneOptions o = options;
  BuiltScene built;
  if (o.busiest > 0.0) {
    o.from = busiestStart(recording, o.busiest, o.maxGap);
    o.to = o.from + o.busiest;
    built.notes.push_back(fmt::format("the busiest {} s: from {} s to {} s",
                                      roundedNumber(o.busiest), roundedNumber(o.from),
                                      roundedNumber(o.to)));
  }
  built.notes.insert(built.notes.begin(), recording.notes.begin(), recording.notes.end());
  const Selected kept = selectTracks(recording, o, built.notes);
  const std::vector<int> present = presentPerTick(kept.targets);
  built.mostAtOnce = *std::max_element(present.begin(), present.end());
  for (const auto& t : kept.targets)
    built.duration = std::max(built.duration, t.times.back());
  const geometry::Box box = boundaryBox(recording, kept, o, built.notes);

  scene::WrittenScene scene;
  scene.description = describeScene(recording, o);
  scene.boundary = mmRing({{box.min.x, box.min.y},
                           {box.max.x, box.min.y},
                           {box.max.x, box.max.y},
                           {box.min.x, box.max.y}});
  if (recording.onPitch) scene.pitch = scene::Pitch{recording.pitch.length, recording.pitch.width};
  // The window is how long a run of the scene lasts; to the recording's end, its last sample.
  // A window of one instant (every track a single sample at its start) has no length: the
  // scene then says nothing, and runs last what the command asks.
  const double window = std::min(
      scene::kMaxDuration, scene::roundTo(std::isinf(o.to) ? built.duration : o.to - o.from, 1e3));
  if (window > 0.0) {
    scene.duration = window;
  } else {
    built.notes.push_back(
        "the window holds a single instant: the scene has no duration of its own (runs last "
        "sim.duration)");
  }
  const auto still = [](geometry::Ring shape, Vec2 at) {
    scene::MovingObject object;
    object.shape = std::move(shape);
    object.path = {{mm(at.x), mm(at.y)}};
    return object;
  };
  const auto tracked = [&](const RecordedTrack& t) {
    scene::Track track;
    track.times = t.times;
    for (const Vec2 p : t.positions)
      track.positions.push_back({mm(p.x), mm(p.y)});
    track.headings = t.headings;
    scene::MovingObject object =
        still(mmRing(disc({0.0, 0.0}, discRadius(t, o))), track.positions.front());
    object.track = std::move(track);
    object.color = t.color;
    if (t.kind != "ball" && o.frontWeight != 1.0)
      object.front = scene::FrontWeighting{o.frontWeight, geometry::degToRad(o.frontAngleDeg)};
    return object;
  };
  for (const auto& t : kept.targets)
    scene.targets.push_back(tracked(t));
  std::vector<geometry::Ring> solid;  // where a camera must not start
  for (const Wall& w : recording.walls) {
    solid.push_back(wallRing(w, o.wallThickness));
    scene.obstacles.push_back(still(mmRing(solid.back()), {0.0, 0.0}));
  }
  for (const Pillar& p : recording.pillars) {
    solid.push_back(disc(p.centre, p.radius));
    scene.obstacles.push_back(still(mmRing(disc({0.0, 0.0}, p.radius)), p.centre));
  }
  for (const auto& t : kept.movingObstacles)
    scene.obstacles.push_back(tracked(t));
  scene.halfFovDegrees = o.cameraHalfFovDeg;
  const bool imaged = o.imageWidth > 0;
  if (imaged) scene.resolution = scene::ResolutionRequirement{o.minDensity, false};
  const double reach =
      imaged ? mm(o.imageWidth / (2.0 * geometry::degToRad(o.cameraHalfFovDeg)) / o.minDensity)
             : 0.0;
  const double range = o.sensingRange.value_or(reach);
  for (const auto& p : cameraTeam(o, box, solid)) {
    scene::CameraEntry& camera = scene.cameras.emplace_back(scene::cameraEntry(
        {mm(p.x), mm(p.y)}, std::round(p.yaw * 180.0 / std::numbers::pi * 100.0) / 100.0,
        o.cameraSpeed, o.cameraTurnRate));
    if (range > 0.0) camera[scene::CameraKeyId::sensingRange] = range;
    if (imaged) camera[scene::CameraKeyId::imageWidth] = o.imageWidth;
  }
  if (imaged) {
    built.notes.push_back(fmt::format(
        "cameras: {} pixels across {:g}°, resolving {:g} pixels per metre up to {:g} m face-on; "
        "sensing range {} (--image-width, --min-density, --sensing-range)",
        o.imageWidth, 2.0 * o.cameraHalfFovDeg, o.minDensity, reach,
        range > 0.0 ? fmt::format("{:g} m", range) : std::string("unlimited")));
  }
  built.scene = scene::sceneJson(scene);
  return built;
}

}  // namespace camcov::import
