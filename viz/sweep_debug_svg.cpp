#include "viz/sweep_debug_svg.h"

#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <stdexcept>
#include <string_view>

#include "kinematics/kinematics.h"
#include "util/escape_xml.h"
#include "util/input_error.h"
#include "visibility/occluders.h"
#include "visibility/sweep.h"
#include "viz/cairo_drawing.h"
#include "viz/file_extension.h"

namespace camcov::viz {
namespace {

using geometry::Vec2;
using visibility::RingKind;
using visibility::TracedEdge;
using visibility::TracedEvent;

// Every length in px. The drawing's longer side is fixed rather than fitted to a frame: the
// file is read zoomed in a browser, and the table beside it grows with the events.
constexpr double kEm = 13.0;
constexpr double kWorldSide = 1200.0;
constexpr double kMargin = 2.0 * kEm;
constexpr double kLabelSize = 0.8 * kEm;
constexpr double kTableSize = 11.0;
constexpr double kRowHeight = 15.0;
constexpr double kCharWidth = 0.61 * kTableSize;  // advance of DejaVu Sans Mono and its kin
constexpr int kMinRowsPerColumn = 24;
constexpr int kHeaderRows = 8;  // six lines of text, a blank one, the column titles
constexpr std::size_t kMaxRangesPerLabel = 4;

constexpr Rgb kFront = kPlan;                // the edge in front after an event, its rays
constexpr Rgb kHidden{0.55, 0.57, 0.61};     // a ray's part beyond the front edge
constexpr Rgb kStripe{0.87, 0.88, 0.90};     // every other ray in the table
constexpr Rgb kLabelSeen{0.05, 0.42, 0.17};  // kSeen, darker: text on white
constexpr Rgb kWedge{0.55, 0.35, 0.70};      // events of a blocked wedge

// Cairo's SVG surface writes text as glyph outlines, which no browser can search and no test
// can read; labels are collected here and written as <text> elements over Cairo's drawing.
class TextLayer {
 public:
  enum class Anchor { Start, Middle };
  struct Style {
    double size = kLabelSize;
    Rgb colour = kText;
    Anchor anchor = Anchor::Start;
    bool bold = false;
    bool mono = false;  // the table: monospace, spaces kept
    bool halo = false;  // a white outline under the glyphs, for text over lines
  };

  void add(Vec2 baseline, std::string_view s, const Style& style) {
    markup_ += fmt::format(R"(<text x="{:.1f}" y="{:.1f}" font-size="{:g}" fill="{}")", baseline.x,
                           baseline.y, style.size, css(style.colour));
    markup_ += style.mono ? R"( font-family="DejaVu Sans Mono, monospace" xml:space="preserve")"
                          : R"( font-family="sans-serif")";
    if (style.anchor == Anchor::Middle) markup_ += R"( text-anchor="middle")";
    if (style.bold) markup_ += R"( font-weight="bold")";
    if (style.halo) {
      markup_ += R"( stroke="#ffffff" stroke-width="3" stroke-linejoin="round")"
                 R"( paint-order="stroke")";
    }
    markup_ += '>';
    markup_ += escapeXml(s);
    markup_ += "</text>\n";
  }

  // Cairo's document with the labels as its last group, on top of everything.
  std::string appendTo(std::string svg) const {
    const std::size_t end = svg.rfind("</svg>");
    if (end == std::string::npos) throw std::logic_error("Cairo wrote no </svg>");
    svg.insert(end, "<g id=\"labels\">\n" + markup_ + "</g>\n");
    return svg;
  }

 private:
  static std::string css(Rgb c) {
    const auto byte = [](double v) { return static_cast<int>(std::lround(255.0 * v)); };
    return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
  }

  std::string markup_;
};

using Anchor = TextLayer::Anchor;

std::size_t codePoints(std::string_view s) {
  return static_cast<std::size_t>(
      std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xc0) != 0x80; }));
}

// About as wide as sans-serif text of this style is drawn: good enough to keep labels apart.
double textWidth(std::string_view s, const TextLayer::Style& style) {
  return static_cast<double>(codePoints(s)) * (style.bold ? 0.68 : 0.62) * style.size;
}

// The header's first line is the title; its last, the legend.
TextLayer::Style headerStyle(std::size_t line, std::size_t lines) {
  return {.size = line == 0 ? 1.2 * kEm : kTableSize,
          .colour = line + 2 >= lines ? kMutedText : kText,
          .bold = line == 0};
}

std::string ringName(RingKind ring, std::uint32_t owner) {
  switch (ring) {
    case RingKind::Boundary:
      return "boundary";
    case RingKind::Obstacle:
      return fmt::format("obstacle {}", owner);
    case RingKind::Target:
      break;
  }
  return fmt::format("target {}", owner);
}

std::string edgeName(const TracedEdge& e) {
  switch (e.kind) {
    case TracedEdge::Kind::None:
      return "nothing";
    case TracedEdge::Kind::Wedge:
      return "wedge (camera on a ring)";
    case TracedEdge::Kind::Edge:
      break;
  }
  return fmt::format("#{} {} edge {}", e.piece, ringName(e.ring, e.owner), e.edge);
}

std::string kindName(const TracedEvent& e) {
  switch (e.kind) {
    case TracedEvent::Kind::Vertex:
      break;
    case TracedEvent::Kind::WedgeStart:
      return "wedge start";
    case TracedEvent::Kind::WedgeEnd:
      return "wedge end";
    case TracedEvent::Kind::FovEnter:
      return "fov enter";
    case TracedEvent::Kind::FovLeave:
      return "fov leave";
  }
  if (e.inserted == 1 && e.removed == 1) return "remove+insert";
  const auto part = [](const char* what, int n) {
    return n == 0 ? std::string() : n == 1 ? std::string(what) : fmt::format("{} {}", what, n);
  };
  return part("remove", e.removed) + (e.removed && e.inserted ? "+" : "") +
         part("insert", e.inserted);
}

// "3–5, 9" for the event numbers {3, 4, 5, 9}; at most kMaxRangesPerLabel ranges, then "…".
std::string rangesOf(const std::vector<std::size_t>& numbers) {
  std::string out;
  std::size_t ranges = 0;
  for (std::size_t i = 0; i < numbers.size();) {
    std::size_t j = i;
    while (j + 1 < numbers.size() && numbers[j + 1] == numbers[j] + 1)
      ++j;
    if (ranges == kMaxRangesPerLabel) return out + ", …";
    if (ranges++ > 0) out += ", ";
    out += j == i ? fmt::format("{}", numbers[i]) : fmt::format("{}–{}", numbers[i], numbers[j]);
    i = j + 1;
  }
  return out;
}

std::string cameraSet(const scene::CameraSet& cameras) {
  std::string out = "{";
  cameras.forEach([&](std::size_t j) { out += fmt::format("{}{}", out.size() > 1 ? "," : "", j); });
  return out + "}";
}

struct Layout {
  WorldToImage toImage;
  double drawingWidth = 0.0, height = 0.0, width = 0.0;
  double tableX = 0.0, tableY = 0.0;  // top-left of the first event row
  int rowsPerColumn = 1;
  double columnWidth = 0.0;
};

Layout layoutFor(const SweepDebug& d, const std::vector<std::string>& header,
                 const std::vector<std::string>& rows) {
  // The boundary and every camera, even one outside it (a blind camera is a case to debug).
  geometry::Box box = geometry::boundingBox(d.world.boundary);
  for (const geometry::Pose& c : d.cameras) {
    box.min = {std::min(box.min.x, c.x), std::min(box.min.y, c.y)};
    box.max = {std::max(box.max.x, c.x), std::max(box.max.y, c.y)};
  }
  const Vec2 size = box.max - box.min;
  const double scale = kWorldSide / std::max({size.x, size.y, 1e-9});
  Layout l;
  l.drawingWidth = size.x * scale + 2.0 * kMargin;
  const double drawingHeight = size.y * scale + 2.0 * kMargin;
  l.toImage = WorldToImage(box, {0.0, 0.0, l.drawingWidth, drawingHeight}, kMargin);

  l.tableX = l.drawingWidth + kEm;
  l.tableY = kMargin + kHeaderRows * kRowHeight;
  l.height = std::max(drawingHeight, l.tableY + kMinRowsPerColumn * kRowHeight + kMargin);
  l.rowsPerColumn = std::max(1, static_cast<int>((l.height - l.tableY - kMargin) / kRowHeight));
  const int columns =
      std::max<int>(1, static_cast<int>((rows.size() + l.rowsPerColumn - 1) / l.rowsPerColumn));
  std::size_t rowChars = 0;
  for (const std::string& r : rows)
    rowChars = std::max(rowChars, codePoints(r));
  l.columnWidth = (static_cast<double>(rowChars) + 3.0) * kCharWidth;
  double headerWidth = 0.0;
  for (std::size_t i = 0; i < header.size(); ++i)
    headerWidth = std::max(headerWidth, textWidth(header[i], headerStyle(i, header.size())));
  l.width = l.tableX + std::max(columns * l.columnWidth, headerWidth) + kMargin;
  return l;
}

std::vector<std::string> headerOf(const SweepDebug& d) {
  const visibility::SweepTrace& t = d.trace;
  const geometry::Pose& c = t.camera;
  std::vector<std::string> h;
  h.push_back(d.title);
  h.push_back(fmt::format("camera {} at ({:.3f}, {:.3f}), yaw {:.2f}°, θ = {:.2f}°", d.camera, c.x,
                          c.y, geometry::radToDeg(c.yaw), geometry::radToDeg(t.lens.halfFov)));
  if (t.blind) {
    h.push_back("sees nothing (inside an object or outside the boundary): no events");
  } else {
    h.push_back(fmt::format("sweep start, just below +x: front {}, {} view",
                            edgeName(t.frontBefore), t.inFovBefore ? "in" : "out of"));
    h.push_back(fmt::format("{} events on {} rays, counter-clockwise from +x", t.events.size(),
                            t.events.empty() ? 0 : t.events.back().ray + 1));
  }
  h.push_back(
      "blue band: edge in front after the events named on it (#piece id); thin blue: "
      "each event's ray to it, dotted on to an event behind it");
  h.push_back(
      "amber: field of view, and lighter all the camera could see around it; "
      "green/red: target boundary seen/unseen, {visibleBy}");
  return h;
}

std::string columnTitles() {
  return fmt::format("{:<5}{:>4} {:>9} {:^22} {:<13} {:<4} {}", "event", "ray", "angle", "point",
                     "kind", "view", "→ front after");
}

std::vector<std::string> rowsOf(const visibility::SweepTrace& t) {
  std::vector<std::string> rows;
  for (std::size_t i = 0; i < t.events.size(); ++i) {
    const TracedEvent& e = t.events[i];
    rows.push_back(fmt::format("e{:<4}{:>4} {:>8.3f}° ({:>9.3f}, {:>9.3f}) {:<13} {:<4} → {}",
                               i + 1, e.ray, geometry::radToDeg(e.angle), e.point.x, e.point.y,
                               kindName(e), e.inFovAfter ? "in" : "out", edgeName(e.frontAfter)));
  }
  return rows;
}

Vec2 unit(Vec2 v, Vec2 fallback) {
  const double n = norm(v);
  return n > 0.0 ? v / n : fallback;
}

// The two field-of-view rays, dashed, long enough to leave the drawing.
void drawFieldOfViewRays(const Painter& p, const visibility::SweepTrace& t, double length) {
  cairo_t* cr = p.cr();
  const double dash[] = {0.5 * kEm, 0.3 * kEm};
  cairo_set_dash(cr, dash, 2, 0.0);
  const Vec2 c = t.camera.position();
  for (const double side : {-1.0, 1.0})
    p.linePath(c, c + length * geometry::unitVector(t.camera.yaw + side * t.lens.halfFov));
  p.stroke(kView, 0.12);
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

// Each event's ray from the camera to where it meets the front edge, and on, dotted, to the
// event's point when that lies behind the front edge.
void drawRays(const Painter& p, const visibility::SweepTrace& t) {
  cairo_t* cr = p.cr();
  const Vec2 c = t.camera.position();
  for (const TracedEvent& e : t.events)
    p.linePath(c, e.hitAfter);
  p.stroke(kFront, 0.06, 0.45);
  const double dot[] = {0.15 * kEm, 0.25 * kEm};
  cairo_set_dash(cr, dot, 2, 0.0);
  for (const TracedEvent& e : t.events) {
    if (distance(c, e.point) > distance(c, e.hitAfter)) p.linePath(e.hitAfter, e.point);
  }
  p.stroke(kHidden, 0.06);
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

// A wide translucent band under the segments, so a target edge keeps its seen/unseen colour.
void drawFrontEdges(const Painter& p, const visibility::SweepTrace& t) {
  std::set<std::uint32_t> drawn;
  const auto add = [&](const TracedEdge& e) {
    if (e.kind == TracedEdge::Kind::Edge && drawn.insert(e.piece).second) p.linePath(e.a, e.b);
  };
  add(t.frontBefore);
  for (const TracedEvent& e : t.events)
    add(e.frontAfter);
  cairo_set_line_cap(p.cr(), CAIRO_LINE_CAP_ROUND);
  p.stroke(kFront, 0.7, 0.4);
  cairo_set_line_cap(p.cr(), CAIRO_LINE_CAP_BUTT);
}

void drawEventMarkers(const Painter& p, const visibility::SweepTrace& t) {
  cairo_t* cr = p.cr();
  for (const TracedEvent& e : t.events) {
    const Vec2 q = p.image(e.point);
    cairo_new_sub_path(cr);
    cairo_arc(cr, q.x, q.y, 0.3 * kEm, 0.0, 2.0 * std::numbers::pi);
    const bool fov = e.kind == TracedEvent::Kind::FovEnter || e.kind == TracedEvent::Kind::FovLeave;
    const bool wedge =
        e.kind == TracedEvent::Kind::WedgeStart || e.kind == TracedEvent::Kind::WedgeEnd;
    setColour(cr, fov ? kView : wedge ? kWedge : kFloor);
    cairo_fill_preserve(cr);
    p.stroke(kCamera, 0.08);
  }
}

// Puts labels where they cover no other label and no marker, greedily in the order they come:
// first a little off their anchor in the preferred direction, then turned a little to either
// side, then farther out; where every place is taken, at the first one inside the drawing.
class LabelPlacer {
 public:
  // Labels stay inside `area`.
  LabelPlacer(TextLayer& text, const PixelRect& area) : text_(text), area_(area) {}

  void block(Vec2 centre, double radius) {
    taken_.push_back({centre.x - radius, centre.y - radius, 2.0 * radius, 2.0 * radius});
  }

  // `s` beside `anchor` (image px), towards the unit direction `away`.
  void add(Vec2 anchor, Vec2 away, const std::string& s, const TextLayer::Style& style) {
    const double width = textWidth(s, style), height = style.size;
    std::optional<PixelRect> fallback;
    bool fallbackInside = false;
    // Turned by at most 35°: farther, a label beside an edge would slide onto the edge.
    for (const double distance : {0.5, 1.3, 2.1, 2.9, 3.7}) {
      for (const double turn : {0.0, 0.6, -0.6}) {
        const Vec2 d = geometry::rotated(away, turn);
        const double reach =
            distance * kEm + 0.5 * (std::abs(d.x) * width + std::abs(d.y) * height);
        const Vec2 centre = anchor + d * reach;
        const PixelRect box{centre.x - 0.5 * width, centre.y - 0.5 * height, width, height};
        const bool inside = box.x >= area_.x && box.y >= area_.y &&
                            box.x + box.width <= area_.x + area_.width &&
                            box.y + box.height <= area_.y + area_.height;
        if (!fallback || (inside && !fallbackInside)) {
          fallback = box;
          fallbackInside = inside;
        }
        if (inside && std::none_of(taken_.begin(), taken_.end(),
                                   [&](const PixelRect& r) { return r.overlaps(box); })) {
          return put(box, s, style);
        }
      }
    }
    put(*fallback, s, style);
  }

 private:
  void put(const PixelRect& box, const std::string& s, const TextLayer::Style& style) {
    taken_.push_back(box);
    text_.add({box.x + 0.5 * box.width, box.y + 0.5 * box.height + 0.35 * style.size}, s,
              {style.size, style.colour, Anchor::Middle, style.bold, style.mono, style.halo});
  }

  TextLayer& text_;
  PixelRect area_;
  std::vector<PixelRect> taken_;
};

// Event numbers beside their points, away from the camera; events at one point share a label.
void labelEvents(const Painter& p, const visibility::SweepTrace& t, LabelPlacer& labels) {
  std::map<std::pair<double, double>, std::vector<std::size_t>> byPoint;
  for (std::size_t i = 0; i < t.events.size(); ++i)
    byPoint[{t.events[i].point.x, t.events[i].point.y}].push_back(i + 1);
  const Vec2 c = p.image(t.camera.position());
  for (const auto& [point, numbers] : byPoint) {
    const Vec2 q = p.image({point.first, point.second});
    labels.add(q, unit(q - c, {0.0, -1.0}), rangesOf(numbers), {.bold = true, .halo = true});
  }
}

// Where the ray at `angle` from `c` meets the line through a and b, clamped to the segment.
Vec2 meet(Vec2 c, double angle, Vec2 a, Vec2 b) {
  const Vec2 d = geometry::unitVector(angle), ab = b - a;
  const double den = cross(d, ab);
  if (den == 0.0) return a;
  return lerp(a, b, std::clamp(cross(d, c - a) / den, 0.0, 1.0));
}

// "e3–5, 9 → #12" on each front edge, in the middle of the longest stretch of it in front
// (from an event's ray to the next ray), on the camera's side.
void labelFrontEdges(const Painter& p, const visibility::SweepTrace& t, LabelPlacer& labels) {
  struct Front {
    std::vector<std::size_t> events;
    Vec2 middle;
    double length = -1.0;
  };
  std::map<std::uint32_t, Front> fronts;
  const Vec2 c = t.camera.position();
  const std::size_t n = t.events.size();
  for (std::size_t i = 0; i < n; ++i) {
    const TracedEvent& e = t.events[i];
    if (e.frontAfter.kind != TracedEdge::Kind::Edge) continue;
    Front& f = fronts[e.frontAfter.piece];
    f.events.push_back(i + 1);
    std::size_t next = (i + 1) % n;  // the sweep closes on its first ray
    while (next != i && t.events[next].ray == e.ray)
      next = (next + 1) % n;
    const Vec2 from = meet(c, e.angle, e.frontAfter.a, e.frontAfter.b);
    const Vec2 to = meet(c, t.events[next].angle, e.frontAfter.a, e.frontAfter.b);
    if (distance(from, to) > f.length) {
      f.length = distance(from, to);
      f.middle = (from + to) * 0.5;
    }
  }
  const Vec2 camera = p.image(c);
  for (const auto& [piece, f] : fronts) {
    const Vec2 q = p.image(f.middle);
    labels.add(q, unit(camera - q, {0.0, 1.0}), fmt::format("e{} → #{}", rangesOf(f.events), piece),
               {.colour = kFront, .halo = true});
  }
}

// "{0,2}" outside each seen segment (targets run counter-clockwise: outside is on the right).
void labelSegments(const Painter& p, std::span<const visibility::Segment> segments,
                   LabelPlacer& labels) {
  for (const visibility::Segment& s : segments) {
    if (s.visibleBy.empty()) continue;
    const Vec2 d = unit(s.b - s.a, {1.0, 0.0});
    const Vec2 outside{d.y, d.x};  // the world's right-hand normal (d.y, −d.x), y flipped
    labels.add(p.image((s.a + s.b) * 0.5), outside, cameraSet(s.visibleBy),
               {.colour = kLabelSeen, .bold = true, .halo = true});
  }
}

void drawWorld(cairo_t* cr, const SweepDebug& d, const Layout& l, TextLayer& text) {
  const visibility::SweepTrace& t = d.trace;
  cairo_save(cr);
  cairo_rectangle(cr, 0.0, 0.0, l.drawingWidth, l.height);
  cairo_clip(cr);
  const Painter p(cr, l.toImage, kEm);
  drawArena(p, d.world);
  p.ringPath(d.visibility);
  p.fill(kView, 0.12);
  drawView(p, t.fieldOfView);
  drawObjects(p, d.world);
  drawFrontEdges(p, t);
  drawSegments(p, d.segments);
  drawRays(p, t);
  drawFieldOfViewRays(p, t, 2.0 * (l.drawingWidth + l.height) / l.toImage.scale());
  drawEventMarkers(p, t);
  for (std::size_t j = 0; j < d.cameras.size(); ++j) {
    if (j == d.camera) continue;  // drawn last, over the others
    const geometry::Pose& c = d.cameras[j];
    drawCameraMarker(cr, p.image(c.position()), c.yaw, std::to_string(j), kEm);
  }
  drawCameraMarker(cr, p.image(t.camera.position()), t.camera.yaw, std::to_string(d.camera), kEm);
  cairo_restore(cr);
  // Event numbers matter most and go first, nearest their points; nothing covers a marker.
  LabelPlacer labels(text, {0.0, 0.0, l.drawingWidth, l.height});
  for (const TracedEvent& e : t.events)
    labels.block(p.image(e.point), 0.35 * kEm);
  for (const geometry::Pose& c : d.cameras)
    labels.block(p.image(c.position()), 0.7 * kEm);
  labelEvents(p, t, labels);
  labelSegments(p, d.segments, labels);
  labelFrontEdges(p, t, labels);
}

void drawTable(cairo_t* cr, const SweepDebug& d, const Layout& l,
               const std::vector<std::string>& header, const std::vector<std::string>& rows,
               TextLayer& text) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    text.add({l.tableX, kMargin + (static_cast<double>(i) + 0.8) * kRowHeight}, header[i],
             headerStyle(i, header.size()));
  }
  const auto rowTop = [&](std::size_t i) {
    const auto column = static_cast<double>(i / static_cast<std::size_t>(l.rowsPerColumn));
    const auto row = static_cast<double>(i % static_cast<std::size_t>(l.rowsPerColumn));
    return Vec2{l.tableX + column * l.columnWidth, l.tableY + row * kRowHeight};
  };
  // Rows of every other ray on a grey stripe, so the events of one ray read as one group.
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (d.trace.events[i].ray % 2 == 0) continue;
    const Vec2 top = rowTop(i);
    cairo_rectangle(cr, top.x - 0.3 * kEm, top.y, l.columnWidth - kEm, kRowHeight);
  }
  setColour(cr, kStripe);
  cairo_fill(cr);
  const std::string titles = columnTitles();
  for (std::size_t column = 0; column * l.rowsPerColumn < std::max<std::size_t>(rows.size(), 1);
       ++column) {
    text.add({l.tableX + column * l.columnWidth, l.tableY - 0.3 * kRowHeight}, titles,
             {.size = kTableSize, .colour = kMutedText, .bold = true, .mono = true});
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    text.add(rowTop(i) + Vec2{0.0, 0.75 * kRowHeight}, rows[i], {.size = kTableSize, .mono = true});
  }
}

}  // namespace

void requireSvg(const std::filesystem::path& file) {
  if (lowercaseExtension(file) != ".svg") {
    throw InputError(file.string() + ": the sweep debugger writes SVG; use a .svg file name");
  }
}

SweepDebug buildSweepDebug(const scene::Scene& scene, double time,
                           std::span<const geometry::Pose> cameras, unsigned camera) {
  if (camera >= cameras.size()) {
    throw std::invalid_argument(
        fmt::format("camera {} of {} cameras to debug", camera, cameras.size()));
  }
  SweepDebug d;
  d.title = fmt::format("{} at t = {:g} s: the sweep of camera {}", scene.name, time, camera);
  d.world = kinematics::Kinematics(scene).worldAt(time);
  d.cameras.assign(cameras.begin(), cameras.end());
  d.camera = camera;
  const visibility::Occluders occluders(d.world);
  visibility::Sweep sweep;
  const std::vector<scene::Lens> lenses = scene::lenses(scene);
  sweep.segments(occluders, cameras, lenses, d.segments);
  sweep.trace(occluders, cameras[camera], lenses[camera], d.trace);
  sweep.visibilityPolygon(occluders, cameras[camera].position(), d.visibility);
  return d;
}

std::string sweepDebugSvg(const SweepDebug& d) {
  const std::vector<std::string> header = headerOf(d);
  const std::vector<std::string> rows = rowsOf(d.trace);
  const Layout l = layoutFor(d, header, rows);
  TextLayer text;
  const int width = static_cast<int>(std::ceil(l.width));
  const int height = static_cast<int>(std::ceil(l.height));
  const std::string svg = svgDocument(width, height, [&](cairo_t* cr) {
    setColour(cr, kPage);
    cairo_paint(cr);
    drawWorld(cr, d, l, text);
    drawTable(cr, d, l, header, rows, text);
  });
  return text.appendTo(svg);
}

}  // namespace camcov::viz
