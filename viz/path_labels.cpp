#include "viz/path_labels.h"

#include <span>

#include "labels/label_placer.h"

namespace camcov::viz {

using geometry::Vec2;

PathAnchor anchorOf(const Painter& p, const ObjectPath& path) {
  const auto& w = path.waypoints;
  if (w.size() < 2) return {p.image(w.front()), {}};
  std::size_t best = 0;
  double bestLength = -1.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double length = geometry::distance(w[i], w[(i + 1) % w.size()]);
    if (length > bestLength) {
      bestLength = length;
      best = i;
    }
  }
  const Vec2 a = p.image(w[best]), b = p.image(w[(best + 1) % w.size()]);
  const double length = geometry::distance(a, b);
  return {(a + b) * 0.5, length > 0.0 ? (b - a) / length : Vec2{}};
}

namespace {

// Labels keep off everything drawn in the world but the views (a pale tint, under the labels)
// and a pitch's markings (the ground): walls, objects, paths and their arrows, cameras, plans
// and goals, and each other.
labels::LabelPlacer pathLabelPlacer(const Painter& p, const Frame& frame, const PixelRect& area) {
  const double em = p.em();
  labels::LabelPlacer placer({{area.x, area.y}, {area.x + area.width, area.y + area.height}},
                             0.15 * em);
  const auto image = [&](std::span<const Vec2> points) {
    std::vector<Vec2> out;
    for (const Vec2 q : points)
      out.push_back(p.image(q));
    return out;
  };
  const auto around = [](Vec2 at, double radius) {
    return geometry::Box{{at.x - radius, at.y - radius}, {at.x + radius, at.y + radius}};
  };
  placer.avoidLine(image(frame.world.boundary), true);
  for (const auto* rings : {&frame.world.obstacles, &frame.world.targets}) {
    for (const auto& ring : *rings)
      placer.avoidArea(image(ring));
  }
  for (const ObjectPath& path : frame.paths) {
    placer.avoidLine(image(path.waypoints), true);
    placer.avoidBox(around(anchorOf(p, path).point, 0.4 * em));  // the arrowhead
  }
  for (const CameraView& c : frame.cameras) {
    placer.avoidBox(around(p.image(c.pose.position()), 1.4 * em));  // disc and nose
    if (c.plan.size() >= 2) placer.avoidLine(image(c.plan), false);
    if (c.goal) placer.avoidBox(around(p.image(c.goal->position()), 1.0 * em));
  }
  return placer;
}

// Where a path's label may go, best first: beside the middle of its longest leg, left of the
// direction of travel, then round that spot, then beside the middles and quarters of every
// leg; all of these close to the path before any further out. Around the centre of an object
// turning in place.
std::vector<geometry::Box> pathLabelCandidates(const Painter& p, const ObjectPath& path,
                                               Vec2 size) {
  const double em = p.em();
  const PathAnchor anchor = anchorOf(p, path);
  if (anchor.direction == Vec2{}) {
    const double gaps[] = {0.6 * em, 1.2 * em, 2.4 * em, 4.0 * em, 6.0 * em};
    return labels::boxesAround({anchor.point, anchor.point}, size, {0.0, -1.0}, gaps);
  }
  struct Spot {
    Vec2 at;
    Vec2 left;  // of the direction of travel on the leg there, image space
  };
  const auto leftOf = [](Vec2 d) { return Vec2{d.y, -d.x}; };
  std::vector<Spot> spots{{anchor.point, leftOf(anchor.direction)}};
  const auto& w = path.waypoints;
  for (const double t : {0.5, 0.25, 0.75}) {
    for (std::size_t i = 0; i < w.size(); ++i) {
      const Vec2 a = p.image(w[i]), b = p.image(w[(i + 1) % w.size()]);
      if (a != b) spots.push_back({a + (b - a) * t, leftOf(b - a)});
    }
  }
  std::vector<geometry::Box> out;
  for (const double gap : {0.5 * em, 1.2 * em, 2.4 * em}) {
    for (const Spot& spot : spots) {
      const double gaps[] = {gap};
      const auto round = labels::boxesAround({spot.at, spot.at}, size, spot.left, gaps);
      out.insert(out.end(), round.begin(), round.end());
    }
  }
  return out;
}

}  // namespace

std::vector<PathLabel> placePathLabels(const Painter& p, const Frame& frame,
                                       const PixelRect& area) {
  std::vector<PathLabel> out;
  if (frame.paths.empty()) return out;
  cairo_t* cr = p.cr();
  const double em = p.em(), size = kPathLabelSize * em, pad = kPathLabelPad * em;
  labels::LabelPlacer placer = pathLabelPlacer(p, frame, area);
  cairo_save(cr);
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  for (std::size_t i = 0; i < frame.paths.size(); ++i) {
    std::string text = frame.paths[i].speedLabel();
    cairo_text_extents_t e;
    cairo_text_extents(cr, text.c_str(), &e);
    const std::vector<geometry::Box> candidates =
        pathLabelCandidates(p, frame.paths[i], {e.x_advance + 2 * pad, size + 2 * pad});
    if (const auto chosen = placer.place(candidates))
      out.push_back({i, std::move(text), candidates[*chosen]});
  }
  cairo_restore(cr);
  return out;
}

}  // namespace camcov::viz
