#include "reports/scene_gallery.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

#include "kinematics/kinematics.h"
#include "reports/markup.h"
#include "reports/sections.h"

namespace camcov::reports {
namespace {

using geometry::Vec2;

constexpr double kMargin = 16.0;  // px around the boundary, room for labels at the edge
constexpr double kFont = 11.0;

class WorldToSvg {
 public:
  WorldToSvg(const geometry::Box& box, double maxSize)
      : box_(box),
        scale_((maxSize - 2 * kMargin) /
               std::max({box.max.x - box.min.x, box.max.y - box.min.y, 1e-9})) {}
  Vec2 operator()(Vec2 p) const {
    return {kMargin + (p.x - box_.min.x) * scale_, kMargin + (box_.max.y - p.y) * scale_};
  }
  double width() const { return (box_.max.x - box_.min.x) * scale_ + 2 * kMargin; }
  double height() const { return (box_.max.y - box_.min.y) * scale_ + 2 * kMargin; }

 private:
  geometry::Box box_;
  double scale_;
};

void appendPoint(std::string& points, Vec2 p) {
  if (!points.empty()) points += ' ';
  points += px(p.x);
  points += ',';
  points += px(p.y);
}

std::vector<Vec2> mapped(const WorldToSvg& map, const std::vector<Vec2>& ring) {
  std::vector<Vec2> out;
  for (const Vec2 p : ring)
    out.push_back(map(p));
  return out;
}

std::string points(const std::vector<Vec2>& ring) {
  std::string out;
  for (const Vec2 p : ring)
    appendPoint(out, p);
  return out;
}

enum class Anchor { Start, Middle, End };

struct LabelSpot {
  Vec2 at;  // the text's anchor point on its baseline
  Anchor anchor;
};

struct PixelBox {
  double x0, y0, x1, y1;
  bool overlaps(const PixelBox& o) const {
    return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
  }
};

PixelBox boxOf(const std::vector<Vec2>& points) {
  PixelBox b{points.front().x, points.front().y, points.front().x, points.front().y};
  for (const Vec2 p : points) {
    b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
  }
  return b;
}

// Spots around a box in order of preference: above, below (centred, then flush with either
// side), right, left.
std::vector<LabelSpot> spotsAround(const PixelBox& b) {
  const double cx = (b.x0 + b.x1) / 2, above = b.y0 - 4.0, below = b.y1 + kFont + 2.0;
  const double middle = (b.y0 + b.y1) / 2 + kFont / 3;
  return {{{cx, above}, Anchor::Middle},         {{cx, below}, Anchor::Middle},
          {{b.x0, above}, Anchor::Start},        {{b.x1, above}, Anchor::End},
          {{b.x0, below}, Anchor::Start},        {{b.x1, below}, Anchor::End},
          {{b.x1 + 5.0, middle}, Anchor::Start}, {{b.x0 - 5.0, middle}, Anchor::End}};
}

// Whether segment ab meets the box (Liang–Barsky clipping).
bool segmentMeetsBox(Vec2 a, Vec2 b, const PixelBox& box) {
  const Vec2 d = b - a;
  const double p[] = {-d.x, d.x, -d.y, d.y};
  const double q[] = {a.x - box.x0, box.x1 - a.x, a.y - box.y0, box.y1 - a.y};
  double t0 = 0.0, t1 = 1.0;
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) return false;
  }
  return true;
}

// Places labels greedily: each takes its first spot that lies inside the drawing, off the
// walls and clear of what was placed or reserved before it; failing that, its first spot moved
// inside.
class LabelPlacer {
 public:
  LabelPlacer(double width, double height, std::vector<Vec2> walls)
      : width_(width), height_(height), walls_(std::move(walls)) {}

  void reserve(const PixelBox& box) { taken_.push_back(box); }

  void place(const std::string& text, std::string_view color, const std::vector<LabelSpot>& spots) {
    const double width = textWidth(text, kFont);
    std::optional<PixelBox> chosen;
    for (const LabelSpot& spot : spots) {
      const PixelBox r = boxOf(spot, width);
      const bool inside =
          r.x0 >= 1.0 && r.x1 <= width_ - 1.0 && r.y0 >= 1.0 && r.y1 <= height_ - 1.0;
      if (inside && !onWall(r) &&
          std::none_of(taken_.begin(), taken_.end(),
                       [&](const PixelBox& t) { return t.overlaps(r); })) {
        chosen = r;
        break;
      }
    }
    if (!chosen) {
      const PixelBox r = boxOf(spots.front(), width);
      const double dx = std::clamp(r.x0, 1.0, std::max(1.0, width_ - 1.0 - width)) - r.x0;
      const double dy = std::clamp(r.y0, 1.0, std::max(1.0, height_ - 1.0 - (r.y1 - r.y0))) - r.y0;
      chosen = PixelBox{r.x0 + dx, r.y0 + dy, r.x1 + dx, r.y1 + dy};
    }
    taken_.push_back(*chosen);
    svg_ += fmt::format(
        "<text x=\"{}\" y=\"{}\" fill=\"{}\" stroke=\"#fff\" stroke-width=\"3\" "
        "stroke-linejoin=\"round\" paint-order=\"stroke\">{}</text>\n",
        px(chosen->x0), px(chosen->y0 + kAscent * kFont), color, escapeXml(text));
  }

  const std::string& svg() const { return svg_; }

 private:
  static constexpr double kAscent = 0.8;  // of the font size, above the baseline
  static constexpr double kDescent = 0.25;

  bool onWall(const PixelBox& box) const {
    for (std::size_t i = 0; i < walls_.size(); ++i) {
      if (segmentMeetsBox(walls_[i], walls_[(i + 1) % walls_.size()], box)) return true;
    }
    return false;
  }

  static PixelBox boxOf(const LabelSpot& spot, double width) {
    const double left = spot.anchor == Anchor::Start    ? spot.at.x
                        : spot.anchor == Anchor::Middle ? spot.at.x - width / 2
                                                        : spot.at.x - width;
    return {left, spot.at.y - kAscent * kFont, left + width, spot.at.y + kDescent * kFont};
  }

  double width_;
  double height_;
  std::vector<Vec2> walls_;  // the boundary ring, px
  std::vector<PixelBox> taken_;
  std::string svg_;
};

std::string motionText(const scene::MovingObject& o) {
  std::vector<std::string> parts;
  if (o.path.size() > 1) parts.push_back(fmt::format("{:g} m/s", o.velocity));
  if (o.angularVelocity != 0.0) parts.push_back(fmt::format("{:g} rad/s", o.angularVelocity));
  if (o.deformation) parts.push_back("deforms");
  return join(parts, " · ");
}

// Shapes and paths of targets or obstacles; their speed labels go to `labels`.
// Those present at t = 0 (a recorded person may enter later): placed[i] is specs[ids[i]].
std::string objects(const WorldToSvg& map, const std::vector<scene::MovingObject>& specs,
                    const std::vector<geometry::Ring>& placed, std::span<const std::uint32_t> ids,
                    std::string_view fill, double fillOpacity, std::string_view kind,
                    LabelPlacer& labels) {
  std::string shapes, paths;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const auto& o = specs[ids[i]];
    shapes += fmt::format(
        "<polygon class=\"{}\" points=\"{}\" fill=\"{}\" fill-opacity=\"{}\" stroke=\"{}\" "
        "stroke-width=\"1.2\"/>\n",
        kind, points(mapped(map, placed[i])), fill, fillOpacity, fill);
    if (o.path.size() > 1) {
      paths += fmt::format(
          "<polygon class=\"path\" points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.3\" "
          "stroke-linejoin=\"round\"/>\n",
          points(mapped(map, o.path)), kPathColor);
      const Vec2 start = map(o.path.front());
      paths += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"2.2\" fill=\"{}\"/>\n", px(start.x),
                           px(start.y), kPathColor);
    }
    const std::string motion = motionText(o);
    if (motion.empty()) continue;
    labels.place(motion, o.path.size() > 1 ? kPathColor : fill,
                 spotsAround(boxOf(mapped(map, placed[i]))));
  }
  return paths + shapes;
}

// "field of view 60° (half-angle θ 30°)", or the range of a team of unlike cameras: "fields of
// view 40°–90° (θ 20°–45°)". The file's cameraFoV is θ, half the width, so both are named.
std::string fieldsOfView(const scene::Scene& s) {
  double lo = s.cameras.front().halfFov, hi = lo;
  for (const auto& c : s.cameras) {
    lo = std::min(lo, c.halfFov);
    hi = std::max(hi, c.halfFov);
  }
  const auto degrees = [](double halfFov) { return halfFov * 180.0 / std::numbers::pi; };
  if (lo == hi)
    return fmt::format("field of view {:g}° (half-angle θ {:g}°)", 2 * degrees(lo), degrees(lo));
  return fmt::format("fields of view {:g}°–{:g}° (half-angles θ {:g}°–{:g}°)", 2 * degrees(lo),
                     2 * degrees(hi), degrees(lo), degrees(hi));
}

// Field-of-view wedges and camera bodies; their labels go to `labels`.
std::string cameras(const WorldToSvg& map, const scene::Scene& s, LabelPlacer& labels) {
  const double reach = 34.0;  // px: the wedge shows a direction, not a range
  std::string wedges, bodies;
  // The wedge of camera j, from the camera over the arc; SVG's y runs down, so world angles
  // turn the other way.
  const auto wedgeOf = [&](const scene::CameraSpec& c) {
    const Vec2 at = map(c.initial.position());
    std::vector<Vec2> wedge{at};
    constexpr int kArcSteps = 12;
    for (int k = 0; k <= kArcSteps; ++k) {
      const double a = c.initial.yaw - c.halfFov + 2 * c.halfFov * k / kArcSteps;
      wedge.push_back(at + Vec2{std::cos(a), -std::sin(a)} * reach);
    }
    return wedge;
  };
  // Every camera's body and view is reserved before any label is placed.
  for (const auto& c : s.cameras)
    labels.reserve(boxOf(wedgeOf(c)));
  for (const auto& c : s.cameras) {
    const Vec2 at = map(c.initial.position());
    const std::vector<Vec2> wedge = wedgeOf(c);
    wedges += fmt::format(
        "<polygon class=\"view\" points=\"{}\" fill=\"{}\" fill-opacity=\"0.35\" stroke=\"{}\" "
        "stroke-width=\"0.8\"/>\n",
        points(wedge), kViewColor, kViewColor);
    const Vec2 head = at + Vec2{std::cos(c.initial.yaw), -std::sin(c.initial.yaw)} * reach;
    bodies += fmt::format(
        "<g class=\"camera\"><path d=\"M{} {}L{} {}\" stroke=\"#21262f\" stroke-width=\"1.4\"/>"
        "<circle cx=\"{}\" cy=\"{}\" r=\"3.6\" fill=\"#21262f\"/></g>\n",
        px(at.x), px(at.y), px(head.x), px(head.y), px(at.x), px(at.y));
    // Best behind the camera, where its own view is not; else around camera and view.
    const Vec2 back = (at - head) / reach;
    const Anchor behind = back.x > 0.4    ? Anchor::Start
                          : back.x < -0.4 ? Anchor::End
                                          : Anchor::Middle;
    const double baseline = back.y > 0.4 ? kFont : back.y < -0.4 ? -3.0 : kFont / 3;
    const Vec2 behindAt = at + back * 7.0 + Vec2{0.0, baseline};
    std::vector<LabelSpot> spots{
        {behindAt, behind}, {behindAt, Anchor::End}, {behindAt, Anchor::Start}};
    const auto around = spotsAround(boxOf(wedge));
    spots.insert(spots.end(), around.begin(), around.end());
    labels.place(fmt::format("{:g} m/s · {:g} rad/s · {}°", c.maxVelocity, c.maxAngularVelocity,
                             fixed(c.initial.yaw * 180.0 / std::numbers::pi, 0)),
                 "#21262f", spots);
  }
  return wedges + bodies;
}

std::string sceneCard(const SceneData& data) {
  std::string out = fmt::format(
      "<figure class=\"scene-card\" id=\"{}\" data-figure=\"scene\" data-scene=\"{}\">\n",
      anchorId("scene", data.name), escapeXml(data.name));
  if (data.scene) {
    const auto& s = *data.scene;
    int moving = 0;
    for (const auto* group : {&s.targets, &s.obstacles}) {
      for (const auto& o : *group)
        moving += !o.isStatic();
    }
    out += sceneSvg(s);
    out += fmt::format(
        "<figcaption><b><a href=\"#{}\">{}</a></b> <span class=\"muted\">{} · {} camera{}, "
        "{}, {} target{}, {} obstacle{}, {} moving</span>{}</figcaption>\n",
        anchorId("ts", data.name), escapeXml(data.name), groupName(data.group), s.cameras.size(),
        s.cameras.size() == 1 ? "" : "s", fieldsOfView(s), s.targets.size(),
        s.targets.size() == 1 ? "" : "s", s.obstacles.size(), s.obstacles.size() == 1 ? "" : "s",
        moving,
        s.description.empty() ? std::string() : fmt::format("<br>{}", escapeXml(s.description)));
  } else {
    out += fmt::format("<figcaption><b>{}</b></figcaption>\n", escapeXml(data.name));
  }
  if (!data.sceneNote.empty()) {
    out += fmt::format("<p class=\"note\">{}</p>\n", escapeXml(data.sceneNote));
  }
  for (const std::string& warning : data.warnings)
    out += fmt::format("<p class=\"note scene-warning\">warning: {}</p>\n", escapeXml(warning));
  return out + "</figure>\n";
}

}  // namespace

std::string sceneSvg(const scene::Scene& s, double maxSize) {
  const kinematics::World world = kinematics::Kinematics(s).worldAt(0.0);
  const WorldToSvg map(geometry::boundingBox(world.boundary), maxSize);
  std::string out = fmt::format(
      "<svg class=\"scene\" viewBox=\"0 0 {0} {1}\" width=\"{0}\" height=\"{1}\" role=\"img\" "
      "aria-label=\"{2} at t = 0\" font-size=\"{3}\">\n",
      px(map.width()), px(map.height()), escapeXml(s.name), kFont);
  out += fmt::format(
      "<polygon class=\"boundary\" points=\"{}\" fill=\"#fff\" stroke=\"#6b7280\" "
      "stroke-width=\"2\" stroke-linejoin=\"round\"/>\n",
      points(mapped(map, world.boundary)));
  // Labels keep off the objects; cameras claim their spots first, they carry the most text.
  LabelPlacer labels(map.width(), map.height(), mapped(map, world.boundary));
  for (const auto* rings : {&world.obstacles, &world.targets}) {
    for (const auto& ring : *rings)
      labels.reserve(boxOf(mapped(map, ring)));
  }
  const std::string views = cameras(map, s, labels);
  out += objects(map, s.obstacles, world.obstacles, world.obstacleIds, kObstacleColor, 0.85,
                 "obstacle", labels);
  out +=
      objects(map, s.targets, world.targets, world.targetIds, kTargetColor, 0.3, "target", labels);
  return out + views + labels.svg() + "</svg>\n";
}

std::string sceneGallerySection(const ReportData& data) {
  std::string out = fmt::format(
      "<section id=\"scenes\">\n<h2>Scenes (Fig. 3)</h2>\n<p class=\"key\">Each scene at "
      "t&nbsp;=&nbsp;0: <span class=\"swatch\" style=\"--c:{}\"></span>targets, "
      "<span class=\"swatch\" style=\"--c:{}\"></span>obstacles, <span class=\"swatch line\" "
      "style=\"--c:{}\"></span>the loop a moving object's reference point travels (dot: start) "
      "with its speed, <span class=\"swatch\" style=\"--c:{}\"></span>each camera's field of "
      "view at its initial heading, labelled with v<sub>max</sub>, γ̇<sub>max</sub> and the "
      "heading.</p>\n<div class=\"gallery\">\n",
      kTargetColor, kObstacleColor, kPathColor, kViewColor);
  for (const auto& scene : data.scenes)
    out += sceneCard(scene);
  return out + "</div>\n</section>\n";
}

}  // namespace camcov::reports
