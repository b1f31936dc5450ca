#include "viz/frame_drawing.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "viz/cairo_drawing.h"
#include "viz/path_labels.h"

namespace camcov::viz {

namespace {

using geometry::Vec2;

// Frame-only colours and widths; the shared palette is palette.h.
constexpr Rgb kBarTrack{0.84, 0.85, 0.87};
constexpr double kPlanWidth = 0.14;
constexpr double kObjectPathWidth = 0.09;
constexpr double kPitchLineWidth = 0.08;

// The caption's rows are drawPanelStill's and drawPanelMoving's; the legend has one row per
// entry (palette.h). A weighted scene's frames have a row more of each: weighted coverage, and
// what an edge's width means; so have the frames of a scene that asks a resolution: resolved
// coverage, and what the amber pieces are.
std::vector<Legend> legendEntries(const Caption& caption) {
  std::vector<Legend> entries(std::begin(kLegendEntries), std::end(kLegendEntries));
  if (caption.weightedCoverage) entries.push_back(Legend::Importance);
  if (caption.resolutionCoverage) entries.push_back(Legend::Unresolved);
  return entries;
}
// The caption rows that change every frame: time, coverage, a weighted scene's weighted
// coverage, the resolved coverage of a scene that asks a resolution, and utilization.
enum class MovingRow { Time, Coverage, Weighted, Resolved, Utilization };
struct PlacedRow {
  MovingRow what;
  int row;  // caption row
};
// Under the title and subtitle, in this order.
std::vector<PlacedRow> movingRows(const Caption& caption) {
  std::vector<PlacedRow> rows;
  for (const MovingRow what : {MovingRow::Time, MovingRow::Coverage, MovingRow::Weighted,
                               MovingRow::Resolved, MovingRow::Utilization}) {
    if (what == MovingRow::Weighted && !caption.weightedCoverage) continue;
    if (what == MovingRow::Resolved && !caption.resolutionCoverage) continue;
    rows.push_back({what, 2 + static_cast<int>(rows.size())});
  }
  return rows;
}
PanelRows panelRows(const Caption& caption) {
  return {2 + static_cast<int>(movingRows(caption).size()),
          static_cast<int>(legendEntries(caption).size())};
}

// Object paths are dashed: they are where things will be, not where they are.
void setPathDash(cairo_t* cr, double em) {
  const double dash[] = {0.35 * em, 0.25 * em};
  cairo_set_dash(cr, dash, 2, 0.0);
}

// A pitch's lines, thin and pale: the ground, not a thing to see.
void drawMarkings(const Painter& p, std::span<const std::vector<Vec2>> lines) {
  for (const auto& line : lines) {
    p.polylinePath(line);
    p.stroke(kPitchLine, kPitchLineWidth);
  }
}

// Thin dashed loops with an arrow in the direction of travel on the longest leg.
void drawObjectPaths(const Painter& p, std::span<const ObjectPath> paths) {
  cairo_t* cr = p.cr();
  setPathDash(cr, p.em());
  for (const ObjectPath& path : paths) {
    if (path.waypoints.size() < 2) continue;
    p.ringPath(path.waypoints);
    p.stroke(kObjectPath, kObjectPathWidth);
  }
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

// Arrows in the direction of travel, and the speeds on pale boxes where path_labels.h puts
// them: drawn over every shape but the cameras and their plans, which matter more.
void drawPathLabels(const Painter& p, const Frame& frame, const PixelRect& area) {
  cairo_t* cr = p.cr();
  const double em = p.em();
  for (const ObjectPath& path : frame.paths) {
    const PathAnchor anchor = anchorOf(p, path);
    const Vec2 d = anchor.direction;
    if (d == Vec2{}) continue;  // an object turning in place: no arrow
    const Vec2 n{-d.y, d.x};
    const Vec2 tip = anchor.point + d * (0.35 * em);
    const Vec2 back = anchor.point - d * (0.35 * em);
    cairo_move_to(cr, tip.x, tip.y);
    cairo_line_to(cr, back.x + n.x * 0.3 * em, back.y + n.y * 0.3 * em);
    cairo_line_to(cr, back.x - n.x * 0.3 * em, back.y - n.y * 0.3 * em);
    cairo_close_path(cr);
    p.fill(kObjectPath);
  }
  const double size = kPathLabelSize * em;
  for (const PathLabel& label : placePathLabels(p, frame, area)) {
    const geometry::Box& box = label.box;
    cairo_rectangle(cr, box.min.x, box.min.y, box.max.x - box.min.x, box.max.y - box.min.y);
    p.fill(kFloor, 0.8);
    const Vec2 centre = (box.min + box.max) * 0.5;
    text(cr, {centre.x, centre.y + 0.36 * size}, label.text, size, kMutedText, Align::Centre);
  }
}

void drawViews(const Painter& p, std::span<const CameraView> cameras, FrameUse use) {
  cairo_t* cr = p.cr();
  cairo_save(cr);
  if (use == FrameUse::Video) cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);  // see FrameUse
  const double alpha = viewAlphaFor(cameras.size());
  for (const CameraView& c : cameras)
    drawView(p, c.view, alpha);
  cairo_restore(cr);
}

// A ring with a tick in the goal's heading, as a path for the caller to stroke.
void goalMarkerPath(cairo_t* cr, Vec2 at, double yaw, double em) {
  const Vec2 tip = at + imageHeading(yaw) * (1.0 * em);
  cairo_new_sub_path(cr);
  cairo_arc(cr, at.x, at.y, 0.42 * em, 0.0, 2.0 * std::numbers::pi);
  cairo_move_to(cr, at.x, at.y);
  cairo_line_to(cr, tip.x, tip.y);
}

void drawPlans(const Painter& p, std::span<const CameraView> cameras) {
  cairo_t* cr = p.cr();
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const CameraView& c : cameras) {
    if (c.plan.size() >= 2) {
      p.polylinePath(c.plan);
      p.stroke(kPlan, kPlanWidth, 0.9);
    }
    if (c.goal) {
      goalMarkerPath(cr, p.image(c.goal->position()), c.goal->yaw, p.em());
      p.stroke(kPlan, kPlanWidth);
    }
  }
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
}

void drawCameras(const Painter& p, std::span<const CameraView> cameras) {
  for (std::size_t j = 0; j < cameras.size(); ++j) {
    const geometry::Pose& pose = cameras[j].pose;
    drawCameraMarker(p.cr(), p.image(pose.position()), pose.yaw, std::to_string(j), p.em());
  }
}

// "coverage   65.6 %  [=====     ]": a label, its value and a bar of it.
void drawMeter(cairo_t* cr, Vec2 baseline, const std::string& label, double value, Rgb colour,
               double em) {
  text(cr, baseline, label, 0.95 * em, kText);
  text(cr, {baseline.x + 10.2 * em, baseline.y}, fmt::format("{:.1f} %", 100.0 * value), 0.95 * em,
       kText, Align::Right, true);
  const double x = baseline.x + 10.8 * em, y = baseline.y - 0.62 * em;
  const double width = 4.2 * em, height = 0.55 * em;
  cairo_rectangle(cr, x, y, width, height);
  setColour(cr, kBarTrack);
  cairo_fill(cr);
  cairo_rectangle(cr, x, y, width * std::clamp(value, 0.0, 1.0), height);
  setColour(cr, colour);
  cairo_fill(cr);
}

// The legend's sample of each thing, in a box 2 em wide centred on the row's middle.
void drawLegendSample(cairo_t* cr, Legend entry, Vec2 middleLeft, double em) {
  const Vec2 centre = middleLeft + Vec2{1.0 * em, 0.0};
  const Vec2 left = middleLeft + Vec2{0.15 * em, 0.0}, right = middleLeft + Vec2{1.85 * em, 0.0};
  const auto box = [&](Rgb fill) {
    cairo_rectangle(cr, left.x, centre.y - 0.45 * em, right.x - left.x, 0.9 * em);
    setColour(cr, fill);
    cairo_fill(cr);
  };
  const auto line = [&](Rgb colour, double width) {
    cairo_move_to(cr, left.x, left.y);
    cairo_line_to(cr, right.x, right.y);
    setColour(cr, colour);
    cairo_set_line_width(cr, width * em);
    cairo_stroke(cr);
  };
  switch (entry) {
    case Legend::Seen:
      line(kSeen, kSegmentWidth);
      break;
    case Legend::Unseen:
      line(kUnseen, kSegmentWidth);
      break;
    case Legend::Target:
      box(kTarget);
      break;
    case Legend::Obstacle:
      box(kObstacle);
      break;
    case Legend::Camera: {
      const Vec2 apex = left + Vec2{0.1 * em, 0.0};
      cairo_move_to(cr, apex.x, apex.y);
      cairo_line_to(cr, right.x + 0.15 * em, centre.y - 0.6 * em);
      cairo_line_to(cr, right.x + 0.15 * em, centre.y + 0.6 * em);
      cairo_close_path(cr);
      setColour(cr, kView, kViewAlpha + 0.1);
      cairo_fill(cr);
      drawCameraMarker(cr, apex + Vec2{0.35 * em, 0.0}, 0.0, "", 0.6 * em);
      break;
    }
    case Legend::Plan:
      cairo_move_to(cr, left.x, left.y);
      cairo_line_to(cr, right.x - 0.4 * em, right.y);
      goalMarkerPath(cr, right - Vec2{0.4 * em, 0.0}, std::numbers::pi / 2.0, 0.8 * em);
      setColour(cr, kPlan);
      cairo_set_line_width(cr, kPlanWidth * em);
      cairo_stroke(cr);
      break;
    case Legend::ObjectPath:
      setPathDash(cr, em);
      line(kObjectPath, kObjectPathWidth);
      cairo_set_dash(cr, nullptr, 0, 0.0);
      break;
    case Legend::Unresolved:
      line(kUnresolved, kSegmentWidth);
      break;
    case Legend::Importance:
      // Three pieces of edge, from the least important to the most.
      for (int k = 0; k < 3; ++k) {
        const double x0 = left.x + k * 0.6 * em;
        cairo_move_to(cr, x0, left.y);
        cairo_line_to(cr, x0 + 0.4 * em, left.y);
        setColour(cr, kSeen);
        cairo_set_line_width(cr, kSegmentWidth * importanceWidthFactor(0.5 * k) * em);
        cairo_stroke(cr);
      }
      break;
  }
}

// Baseline of a panel row: text sits in the lower part of its 1.6 em.
Vec2 rowBaseline(Vec2 rowTopLeft, double em) {
  return rowTopLeft + Vec2{0.0, 1.15 * em};
}

// Text that fits `width` px: at `size`, else smaller down to three quarters of it, else cut
// with an ellipsis at that size. Never clipped at the frame's edge.
struct Fitted {
  std::string text;
  double size = 0.0;
};
Fitted fitted(cairo_t* cr, const std::string& s, double size, double width, bool bold) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  const auto advance = [&](const std::string& t, double at) {
    cairo_set_font_size(cr, at);
    cairo_text_extents_t extents;
    cairo_text_extents(cr, t.c_str(), &extents);
    return extents.x_advance;
  };
  const double full = advance(s, size);
  if (full <= width) return {s, size};
  const double smallest = 0.75 * size;
  if (full * smallest / size <= width) return {s, size * width / full};
  // Whole UTF-8 characters off the end until it fits with the ellipsis.
  std::string cut = s;
  while (!cut.empty() && advance(cut + "…", smallest) > width) {
    while (!cut.empty() && (static_cast<unsigned char>(cut.back()) & 0xC0) == 0x80)
      cut.pop_back();                  // the last character's continuation bytes
    if (!cut.empty()) cut.pop_back();  // and its first
  }
  return {cut + "…", smallest};
}

// The panel's rows that stay the same through a video: title, subtitle and legend.
void drawPanelStill(cairo_t* cr, const FrameLayout& layout, const Caption& caption) {
  const double em = layout.em;
  const auto line = [&](int row, const std::string& s, double size, Rgb colour, bool bold) {
    const Vec2 at = rowBaseline(layout.captionRow(row), em);
    const double width = layout.panel.x + layout.panel.width - at.x - 0.5 * em;
    const Fitted f = fitted(cr, s, size, width, bold);
    text(cr, at, f.text, f.size, colour, Align::Left, bold);
  };
  line(0, caption.title, 1.25 * em, kText, true);
  line(1, caption.subtitle, 0.9 * em, kMutedText, false);
  const std::vector<Legend> entries = legendEntries(caption);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const Legend entry = entries[i];
    const Vec2 row = layout.legendRow(static_cast<int>(i));
    drawLegendSample(cr, entry, row + Vec2{0.0, 0.8 * em}, em);
    text(cr, rowBaseline(row, em) + Vec2{2.6 * em, 0.0}, legendText(entry), 0.88 * em, kText);
  }
}

// Runs `draw` clipped to `area`: the world never runs into the panel, nor the panel into it.
template <typename Draw>
void clippedTo(cairo_t* cr, const PixelRect& area, Draw draw) {
  cairo_save(cr);
  cairo_rectangle(cr, area.x, area.y, area.width, area.height);
  cairo_clip(cr);
  draw();
  cairo_restore(cr);
}

// A moving row's whole pixels (half an em to the left of its text, for overhanging glyphs),
// inside the panel.
PixelRect movingRowArea(const FrameLayout& layout, int row) {
  const Vec2 topLeft = layout.captionRow(row) - Vec2{0.5 * layout.em, 0.0};
  const PixelRect& panel = layout.panel;
  const double left = std::max(std::floor(topLeft.x), panel.x);
  const double top = std::max(std::floor(topLeft.y), panel.y);
  const double right = std::min(std::ceil(topLeft.x + layout.columnWidth()), panel.x + panel.width);
  const double bottom = std::min(std::ceil(topLeft.y + layout.rowHeight()), panel.y + panel.height);
  return {left, top, std::max(right - left, 0.0), std::max(bottom - top, 0.0)};
}

// Each moving row clipped to its area, so that nothing of it lands outside movingAreas().
void drawPanelMoving(cairo_t* cr, const FrameLayout& layout, const Caption& caption) {
  const double em = layout.em;
  for (const PlacedRow& placed : movingRows(caption)) {
    clippedTo(cr, movingRowArea(layout, placed.row), [&] {
      const Vec2 baseline = rowBaseline(layout.captionRow(placed.row), em);
      switch (placed.what) {
        case MovingRow::Time:
          text(cr, baseline, fmt::format("t = {:.1f} s", caption.time), 0.95 * em, kText);
          break;
        case MovingRow::Coverage:
          drawMeter(cr, baseline, "coverage", caption.coverage, kSeen, em);
          break;
        case MovingRow::Weighted:
          drawMeter(cr, baseline, "weighted", caption.weightedCoverage.value_or(0.0), kSeen, em);
          break;
        case MovingRow::Resolved:
          drawMeter(cr, baseline, "resolved", caption.resolutionCoverage.value_or(0.0), kSeen, em);
          break;
        case MovingRow::Utilization:
          drawMeter(cr, baseline, "utilization", caption.utilization, kView, em);
          break;
      }
    });
  }
}

}  // namespace

// Everything drawMoving() may touch: outside these a frame is its still part.
std::vector<PixelRect> movingAreas(const FrameLayout& layout, const Caption& caption) {
  std::vector<PixelRect> areas{layout.worldArea};
  for (const PlacedRow& placed : movingRows(caption))
    areas.push_back(movingRowArea(layout, placed.row));
  return areas;
}

FrameLayout layoutFor(const Frame& frame, int width, int height) {
  return layoutFrame(width, height, geometry::boundingBox(frame.world.boundary),
                     panelRows(frame.caption));
}

// A frame is drawn in two parts. The still part is what a frame shares with every other
// frame of its video: the page, floor and wall, the object paths (under the views), the
// title, subtitle and legend. The raster keeps it and copies it under each frame (it costs
// about a third of the drawing); a frame that differs in stillKeyOf() redraws it.
void drawStill(cairo_t* cr, const Frame& frame, const FrameLayout& layout) {
  setColour(cr, kPage);
  cairo_paint(cr);
  clippedTo(cr, layout.worldArea, [&] {
    const Painter painter(cr, layout.toImage, layout.em);
    drawArena(painter, frame.world);
    drawMarkings(painter, frame.markings);
    drawObjectPaths(painter, frame.paths);
  });
  clippedTo(cr, layout.panel, [&] { drawPanelStill(cr, layout, frame.caption); });
}

// Everything else, over the still part.
void drawMoving(cairo_t* cr, const Frame& frame, const FrameLayout& layout, FrameUse use) {
  clippedTo(cr, layout.worldArea, [&] {
    const Painter painter(cr, layout.toImage, layout.em);
    drawViews(painter, frame.cameras, use);
    const Enlargements enlarged = enlargementsFor(painter, frame.world);
    drawObjects(painter, frame.world, frame.targetColours, &enlarged);
    drawSegments(painter, frame.segments, &enlarged, frame.world.targetEdgeWeights);
    drawSegments(painter, frame.unresolved, &enlarged, frame.world.targetEdgeWeights, kUnresolved);
    drawEnlargedMarks(painter, frame.world, enlarged);
    drawPathLabels(painter, frame, layout.worldArea);
    drawPlans(painter, frame.cameras);
    drawCameras(painter, frame.cameras);
  });
  clippedTo(cr, layout.panel, [&] { drawPanelMoving(cr, layout, frame.caption); });
}

void throwIfFailed(cairo_t* cr) {
  if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("drawing a frame failed: ") +
                             cairo_status_to_string(cairo_status(cr)));
  }
}

// The one drawing routine behind every surface.
void drawFrame(cairo_t* cr, const Frame& frame, int width, int height) {
  const FrameLayout layout = layoutFor(frame, width, height);
  drawStill(cr, frame, layout);
  drawMoving(cr, frame, layout, FrameUse::Still);
  throwIfFailed(cr);
}

}  // namespace camcov::viz
