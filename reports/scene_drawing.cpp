#include "reports/scene_drawing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

#include "kinematics/kinematics.h"
#include "labels/label_placer.h"
#include "reports/markup.h"

namespace camcov::reports {
namespace {

using geometry::Box;
using geometry::Vec2;

constexpr double kMargin = 18.0;  // px around the boundary: room for a row of labels
constexpr double kFont = SceneDrawing::kFont;
constexpr double kLabelGap = 2.0;  // px between a label and anything else: its white halo
// px at most between a camera's body and its label: any farther, a label in the open reads as
// nobody's (or as the nearest target's), so it is left off and listed under the picture.
constexpr double kMaxCameraLabelGap = 24.0;
constexpr double kReach = 34.0;  // px, a wedge's radius: it shows a direction, not a range

class WorldToSvg {
 public:
  WorldToSvg(const geometry::Box& box, double maxSize)
      : box_(box),
        scale_((maxSize - 2 * kMargin) /
               std::max({box.max.x - box.min.x, box.max.y - box.min.y, 1e-9})) {}
  Vec2 operator()(Vec2 p) const {
    return {kMargin + (p.x - box_.min.x) * scale_, kMargin + (box_.max.y - p.y) * scale_};
  }
  std::vector<Vec2> operator()(std::span<const Vec2> points) const {
    std::vector<Vec2> out;
    for (const Vec2 p : points)
      out.push_back((*this)(p));
    return out;
  }
  double width() const { return (box_.max.x - box_.min.x) * scale_ + 2 * kMargin; }
  double height() const { return (box_.max.y - box_.min.y) * scale_ + 2 * kMargin; }

 private:
  geometry::Box box_;
  double scale_;
};

Box boxAround(Vec2 centre, double radius) {
  return {{centre.x - radius, centre.y - radius}, {centre.x + radius, centre.y + radius}};
}

// Candidates for a label of `size` px around `around` (labels/label_placer.h).
std::vector<Box> compassBoxes(const Box& around, Vec2 size, Vec2 first,
                              const std::vector<double>& gaps) {
  return labels::boxesAround(around, size, first, gaps);
}

std::string motionText(const scene::MovingObject& o) {
  std::vector<std::string> parts;
  if (o.path.size() > 1) parts.push_back(fmt::format("{:g} m/s", o.velocity));
  if (o.angularVelocity != 0.0) parts.push_back(fmt::format("{:g} rad/s", o.angularVelocity));
  if (o.deformation) parts.push_back("deforms");
  return join(parts, " · ");
}

// The wedge of a camera, from the camera over the arc; SVG's y runs down, so world angles
// turn the other way.
std::vector<Vec2> wedgeOf(Vec2 at, const scene::CameraSpec& c) {
  std::vector<Vec2> wedge{at};
  constexpr int kArcSteps = 12;
  for (int k = 0; k <= kArcSteps; ++k) {
    const double a = c.initial.yaw - c.lens.halfFov + 2 * c.lens.halfFov * k / kArcSteps;
    wedge.push_back(at + Vec2{std::cos(a), -std::sin(a)} * kReach);
  }
  return wedge;
}

// Everything drawn, for the placer to keep labels off.
void avoidDrawn(const SceneDrawing& d, labels::LabelPlacer& placer) {
  placer.avoidLine(d.boundary, true);
  for (const auto& o : d.objects)
    placer.avoidArea(o.ring);
  for (const auto& path : d.paths)
    placer.avoidLine(path, true);
  for (const Vec2 dot : d.pathStarts)
    placer.avoidBox(boxAround(dot, SceneDrawing::kDotRadius));
  for (const auto& c : d.cameras) {
    placer.avoidArea(c.wedge);
    placer.avoidBox(boxAround(c.at, DrawnCamera::kBodyRadius));
  }
}

// Places a label of these lines at the first clear box of the candidates `boxesFor` makes
// for its size.
bool placeLabel(SceneDrawing& d, labels::LabelPlacer& placer, std::vector<std::string> lines,
                std::string_view color, Vec2 of, const auto& boxesFor) {
  double width = 0.0;
  for (const std::string& line : lines)
    width = std::max(width, textWidth(line, kFont));
  const std::vector<Box> candidates =
      boxesFor(Vec2{width, static_cast<double>(lines.size()) * SceneDrawing::lineHeight()});
  const std::optional<std::size_t> chosen = placer.place(candidates);
  if (chosen) d.labels.push_back({std::move(lines), color, candidates[*chosen], of});
  return chosen.has_value();
}

std::string cameraName(std::size_t j) {
  return fmt::format("cam {}", j);
}

// Camera j's v_max, γ̇_max and heading.
std::string cameraValues(const scene::Scene& s, std::size_t j) {
  const scene::CameraSpec& c = s.cameras[j];
  return fmt::format("{:g} m/s · {:g} rad/s · {}°", c.maxVelocity, c.maxAngularVelocity,
                     headingDegrees(c.initial.yaw));
}

double distanceToBox(Vec2 p, const Box& b) {
  return geometry::distance(p,
                            {std::clamp(p.x, b.min.x, b.max.x), std::clamp(p.y, b.min.y, b.max.y)});
}

// Boxes of `size` round camera j at each of `gaps` px from its body, behind it first (where
// its own view is not), keeping only those nearer camera j than any other camera: a label
// read as another camera's is worse than none.
std::vector<Box> cameraBoxes(const SceneDrawing& d, std::size_t j, Vec2 size,
                             const std::vector<double>& gaps) {
  const DrawnCamera& c = d.cameras[j];
  std::vector<Box> boxes =
      compassBoxes(boxAround(c.at, DrawnCamera::kBodyRadius), size, (c.at - c.head) / kReach, gaps);
  std::erase_if(boxes, [&](const Box& box) {
    const double own = distanceToBox(c.at, box);
    return std::any_of(d.cameras.begin(), d.cameras.end(), [&](const DrawnCamera& other) {
      return &other != &c && distanceToBox(other.at, box) < own;
    });
  });
  return boxes;
}

void labelCameras(const scene::Scene& s, SceneDrawing& d, labels::LabelPlacer& placer) {
  std::vector<std::size_t> withoutValues;
  for (std::size_t j = 0; j < s.cameras.size(); ++j) {
    const std::string name = cameraName(j), values = cameraValues(s, j);
    // Near the camera before far from it; at each distance on one line, else on two
    // (narrower).
    const auto placedAt = [&](double gap) {
      const auto boxes = [&](Vec2 size) { return cameraBoxes(d, j, size, {gap}); };
      return placeLabel(d, placer, {name + " · " + values}, kCameraColor, d.cameras[j].at, boxes) ||
             placeLabel(d, placer, {name, values}, kCameraColor, d.cameras[j].at, boxes);
    };
    if (!(placedAt(3.0) || placedAt(12.0) || placedAt(kMaxCameraLabelGap)))
      withoutValues.push_back(j);
  }
  // Cameras whose values found no room still show their number; the caption has the rest.
  for (const std::size_t j : withoutValues) {
    placeLabel(d, placer, {cameraName(j)}, kCameraColor, d.cameras[j].at, [&](Vec2 size) {
      return cameraBoxes(d, j, size, {2.0, 5.0, 8.0, 12.0, 16.0, kMaxCameraLabelGap});
    });
    d.leftOut.push_back(cameraName(j) + " · " + cameraValues(s, j));
  }
}

// Speed labels beside the object, else beside a leg of its path.
void labelMotion(const std::vector<scene::MovingObject>& specs, std::string_view kind,
                 std::string_view fill, std::span<const std::uint32_t> ids,
                 std::span<const geometry::Ring> placed, const WorldToSvg& map, SceneDrawing& d,
                 labels::LabelPlacer& placer) {
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const auto& o = specs[ids[i]];
    const std::string text = motionText(o);
    if (text.empty()) continue;
    const Box shape = geometry::boundingBox(map(placed[i]));
    const std::vector<Vec2> path = map(o.path);
    const bool placedIt = placeLabel(
        d, placer, {text}, o.path.size() > 1 ? kPathColor : fill, (shape.min + shape.max) * 0.5,
        [&](Vec2 size) {
          std::vector<Box> boxes = compassBoxes(shape, size, {0.0, -1.0}, {3.0, 10.0, 20.0});
          for (std::size_t k = 0; path.size() > 1 && k < path.size(); ++k) {
            const Vec2 a = path[k], b = path[(k + 1) % path.size()];
            const auto beside =
                compassBoxes(boxAround((a + b) * 0.5, 0.0), size, {0.0, -1.0}, {4.0, 10.0});
            boxes.insert(boxes.end(), beside.begin(), beside.end());
          }
          return boxes;
        });
    if (!placedIt) d.leftOut.push_back(fmt::format("{} {} · {}", kind, ids[i], text));
  }
}

}  // namespace

std::string DrawnLabel::text() const {
  return join(lines, " · ");
}

int headingDegrees(double yaw) {
  const long degrees = std::lround(yaw * 180.0 / std::numbers::pi);
  return static_cast<int>((degrees % 360 + 360) % 360);
}

SceneDrawing drawScene(const scene::Scene& s, double maxSize) {
  const kinematics::World world = kinematics::Kinematics(s).worldAt(0.0);
  const WorldToSvg map(geometry::boundingBox(world.boundary), maxSize);
  SceneDrawing d;
  d.width = map.width();
  d.height = map.height();
  d.boundary = map(world.boundary);
  const auto addObjects = [&](const std::vector<scene::MovingObject>& specs,
                              const std::vector<geometry::Ring>& placed,
                              std::span<const std::uint32_t> ids, bool isTarget) {
    for (std::size_t i = 0; i < placed.size(); ++i) {
      d.objects.push_back({map(placed[i]), isTarget});
      const auto& path = specs[ids[i]].path;
      if (path.size() < 2) continue;
      d.paths.push_back(map(path));
      d.pathStarts.push_back(map(path.front()));
    }
  };
  addObjects(s.obstacles, world.obstacles, world.obstacleIds, false);
  addObjects(s.targets, world.targets, world.targetIds, true);
  for (const auto& c : s.cameras) {
    const Vec2 at = map(c.initial.position());
    d.cameras.push_back({at, at + Vec2{std::cos(c.initial.yaw), -std::sin(c.initial.yaw)} * kReach,
                         wedgeOf(at, c)});
  }

  labels::LabelPlacer placer({{1.0, 1.0}, {d.width - 1.0, d.height - 1.0}}, kLabelGap);
  avoidDrawn(d, placer);
  labelCameras(s, d, placer);
  labelMotion(s.obstacles, "obstacle", kObstacleColor, world.obstacleIds, world.obstacles, map, d,
              placer);
  labelMotion(s.targets, "target", kTargetColor, world.targetIds, world.targets, map, d, placer);
  return d;
}

}  // namespace camcov::reports
