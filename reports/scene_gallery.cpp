#include "reports/scene_gallery.h"

#include <fmt/format.h>

#include <utility>

#include <numbers>

#include "reports/markup.h"
#include "reports/scene_drawing.h"
#include "reports/sections.h"

namespace camcov::reports {
namespace {

using geometry::Vec2;

std::string points(const std::vector<Vec2>& ring) {
  std::string out;
  for (const Vec2 p : ring) {
    if (!out.empty()) out += ' ';
    out += px(p.x) + ',' + px(p.y);
  }
  return out;
}

std::string svgOf(const SceneDrawing& d, std::string_view name) {
  std::string out = fmt::format(
      "<svg class=\"scene\" viewBox=\"0 0 {0} {1}\" width=\"{0}\" height=\"{1}\" role=\"img\" "
      "aria-label=\"{2} at t = 0\" font-size=\"{3}\">\n",
      px(d.width), px(d.height), escapeXml(name), SceneDrawing::kFont);
  out += fmt::format(
      "<polygon class=\"boundary\" points=\"{}\" fill=\"#fff\" stroke=\"#6b7280\" "
      "stroke-width=\"2\" stroke-linejoin=\"round\"/>\n",
      points(d.boundary));
  for (std::size_t i = 0; i < d.paths.size(); ++i) {
    out += fmt::format(
        "<polygon class=\"path\" points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.3\" "
        "stroke-linejoin=\"round\"/>\n<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"/>\n",
        points(d.paths[i]), kPathColor, px(d.pathStarts[i].x), px(d.pathStarts[i].y),
        SceneDrawing::kDotRadius, kPathColor);
  }
  for (const DrawnObject& o : d.objects) {
    const char* fill = o.isTarget ? kTargetColor : kObstacleColor;
    out += fmt::format(
        "<polygon class=\"{}\" points=\"{}\" fill=\"{}\" fill-opacity=\"{}\" stroke=\"{}\" "
        "stroke-width=\"1.2\"/>\n",
        o.isTarget ? "target" : "obstacle", points(o.ring), fill, o.isTarget ? 0.3 : 0.85, fill);
  }
  for (const DrawnCamera& c : d.cameras) {
    out += fmt::format(
        "<polygon class=\"view\" points=\"{}\" fill=\"{}\" fill-opacity=\"0.35\" stroke=\"{}\" "
        "stroke-width=\"0.8\"/>\n",
        points(c.wedge), kViewColor, kViewColor);
  }
  for (const DrawnCamera& c : d.cameras) {
    out += fmt::format(
        "<g class=\"camera\" data-camera=\"{}\"><path d=\"M{} {}L{} {}\" stroke=\"{}\" "
        "stroke-width=\"1.4\"/>"
        "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"/></g>\n",
        &c - d.cameras.data(), px(c.at.x), px(c.at.y), px(c.head.x), px(c.head.y), kCameraColor,
        px(c.at.x), px(c.at.y), DrawnCamera::kBodyRadius, kCameraColor);
  }
  // White halos keep the text legible where a label comes close to a line.
  for (const DrawnLabel& l : d.labels) {
    out += fmt::format(
        "<text class=\"label\" fill=\"{}\" stroke=\"#fff\" stroke-width=\"3\" "
        "stroke-linejoin=\"round\" paint-order=\"stroke\"",
        l.color);
    // Anchored at the side nearest what it labels (DrawnLabel::of).
    const auto [anchor, x] = l.of.x >= l.box.max.x ? std::pair{"end", l.box.max.x}
                             : l.of.x <= l.box.min.x
                                 ? std::pair{"start", l.box.min.x}
                                 : std::pair{"middle", (l.box.min.x + l.box.max.x) / 2};
    out += fmt::format(" text-anchor=\"{}\">", anchor);
    for (std::size_t i = 0; i < l.lines.size(); ++i) {
      out += fmt::format("<tspan x=\"{}\" y=\"{}\">{}</tspan>", px(x),
                         px(l.box.min.y + i * SceneDrawing::lineHeight() +
                            SceneDrawing::kAscent * SceneDrawing::kFont),
                         escapeXml(l.lines[i]));
    }
    out += "</text>\n";
  }
  return out + "</svg>\n";
}

// "field of view 60° (half-angle θ 30°)", or the range of a team of unlike cameras: "fields of
// view 40°–90° (θ 20°–45°)". The file's cameraFoV is θ, half the width, so both are named.
std::string fieldsOfView(const scene::Scene& s) {
  double lo = s.cameras.front().lens.halfFov, hi = lo;
  for (const auto& c : s.cameras) {
    lo = std::min(lo, c.lens.halfFov);
    hi = std::max(hi, c.lens.halfFov);
  }
  const auto degrees = [](double halfFov) { return halfFov * 180.0 / std::numbers::pi; };
  if (lo == hi)
    return fmt::format("field of view {:g}° (half-angle θ {:g}°)", 2 * degrees(lo), degrees(lo));
  return fmt::format("fields of view {:g}°–{:g}° (half-angles θ {:g}°–{:g}°)", 2 * degrees(lo),
                     2 * degrees(hi), degrees(lo), degrees(hi));
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
    const SceneDrawing drawing = drawScene(s);
    out += svgOf(drawing, s.name);
    // What the picture had no room for is said here, not squeezed over other things.
    const std::string leftOut =
        drawing.leftOut.empty()
            ? std::string()
            : fmt::format(
                  "<br><span class=\"left-out\">Not on the picture for lack of room: {}."
                  "</span>",
                  escapeXml(join(drawing.leftOut, "; ")));
    out += fmt::format(
        "<figcaption><b><a href=\"#{}\">{}</a></b> <span class=\"muted\">{} · {} camera{}, "
        "{}, {} target{}, {} obstacle{}, {} moving</span>{}{}</figcaption>\n",
        anchorId("ts", data.name), escapeXml(data.name), groupName(data.group), s.cameras.size(),
        s.cameras.size() == 1 ? "" : "s", fieldsOfView(s), s.targets.size(),
        s.targets.size() == 1 ? "" : "s", s.obstacles.size(), s.obstacles.size() == 1 ? "" : "s",
        moving,
        s.description.empty() ? std::string() : fmt::format("<br>{}", escapeXml(s.description)),
        leftOut);
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
  return svgOf(drawScene(s, maxSize), s.name);
}

std::string sceneGallerySection(const ReportData& data) {
  std::string out = fmt::format(
      "<section id=\"scenes\">\n<h2>Scenes (Fig. 3)</h2>\n<p class=\"key\">Each scene at "
      "t&nbsp;=&nbsp;0: <span class=\"swatch\" style=\"--c:{}\"></span>targets, "
      "<span class=\"swatch\" style=\"--c:{}\"></span>obstacles, <span class=\"swatch line\" "
      "style=\"--c:{}\"></span>the loop a moving object's reference point travels (dot: start) "
      "with its speed, <span class=\"swatch\" style=\"--c:{}\"></span>each camera's field of "
      "view at its initial heading, labelled with its number (as in the frames), "
      "v<sub>max</sub>, γ̇<sub>max</sub> and the heading (0° to 359°, counter-clockwise from "
      "+x). A label with no free room is left off the picture and listed under it.</p>\n<div "
      "class=\"gallery\">\n",
      kTargetColor, kObstacleColor, kPathColor, kViewColor);
  for (const auto& scene : data.scenes)
    out += sceneCard(scene);
  return out + "</div>\n</section>\n";
}

}  // namespace camcov::reports
