#include "viz/cairo_drawing.h"

#include <cairo-svg.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/ring.h"

// GCC says ASan is on with __SANITIZE_ADDRESS__, clang 14 only through __has_feature.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CAMCOV_ADDRESS_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(CAMCOV_ADDRESS_SANITIZER)
// Fontconfig keeps the font patterns Cairo's text matched in a cache that only FcFini()
// frees, and nothing calls that before exit: LeakSanitizer would report the cache as a leak
// of every program that draws a caption. Suppressed here, where the text is drawn.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libfontconfig.so\n";
}
extern "C" const char* __lsan_default_options() {
  return "print_suppressions=0";
}
#endif

namespace camcov::viz {

using geometry::Vec2;

void setColour(cairo_t* cr, Rgb c, double alpha) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

void text(cairo_t* cr, Vec2 at, const std::string& s, double size, Rgb colour, Align align,
          bool bold) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, s.c_str(), &extents);
  const double shift = align == Align::Left     ? 0.0
                       : align == Align::Centre ? extents.x_advance / 2.0
                                                : extents.x_advance;
  cairo_move_to(cr, at.x - shift, at.y);
  setColour(cr, colour);
  cairo_show_text(cr, s.c_str());
}

void Painter::polylinePath(std::span<const Vec2> points) const {
  if (points.empty()) return;
  moveTo(points.front());
  for (const Vec2& p : points.subspan(1))
    lineTo(p);
}

void Painter::ringPath(std::span<const Vec2> ring) const {
  polylinePath(ring);
  cairo_close_path(cr_);
}

void Painter::linePath(Vec2 a, Vec2 b) const {
  moveTo(a);
  lineTo(b);
}

void Painter::fill(Rgb colour, double alpha) const {
  setColour(cr_, colour, alpha);
  cairo_fill(cr_);
}

void Painter::stroke(Rgb colour, double widthEm, double alpha) const {
  setColour(cr_, colour, alpha);
  cairo_set_line_width(cr_, widthEm * em_);
  cairo_stroke(cr_);
}

void Painter::moveTo(Vec2 world) const {
  const Vec2 p = image(world);
  cairo_move_to(cr_, p.x, p.y);
}

void Painter::lineTo(Vec2 world) const {
  const Vec2 p = image(world);
  cairo_line_to(cr_, p.x, p.y);
}

Vec2 imageHeading(double yaw) {
  return {std::cos(yaw), -std::sin(yaw)};
}

void drawArena(const Painter& p, const kinematics::World& world) {
  p.ringPath(world.boundary);
  cairo_t* cr = p.cr();
  setColour(cr, kFloor);
  cairo_fill_preserve(cr);
  p.stroke(kWall, 0.14);
}

namespace {

Enlargement enlargementOf(const Painter& p, const geometry::Ring& ring) {
  if (ring.empty()) return {};
  Vec2 mean{};
  geometry::Box box{p.image(ring[0]), p.image(ring[0])};
  for (const Vec2& v : ring) {
    mean = mean + v;
    const Vec2 q = p.image(v);
    box = {{std::min(box.min.x, q.x), std::min(box.min.y, q.y)},
           {std::max(box.max.x, q.x), std::max(box.max.y, q.y)}};
  }
  const double across = std::max(box.max.x - box.min.x, box.max.y - box.min.y);
  const double wanted = kMinObjectEm * p.em();
  return {mean * (1.0 / static_cast<double>(ring.size())),
          across >= wanted ? 1.0 : wanted / std::max(across, 1e-9)};
}

// `ring` as drawn: itself, or enlarged into `scratch`.
std::span<const Vec2> asDrawn(const geometry::Ring& ring, const Enlargement& e,
                              std::vector<Vec2>& scratch) {
  if (e.factor == 1.0) return ring;
  scratch.clear();
  for (const Vec2& v : ring)
    scratch.push_back(e(v));
  return scratch;
}

Enlargement enlargementAt(const std::vector<Enlargement>* list, std::size_t i) {
  return list != nullptr && i < list->size() ? (*list)[i] : Enlargement{};
}

}  // namespace

Enlargements enlargementsFor(const Painter& p, const kinematics::World& world) {
  Enlargements out;
  for (const auto& t : world.targets)
    out.targets.push_back(enlargementOf(p, t));
  for (const auto& o : world.obstacles)
    out.obstacles.push_back(enlargementOf(p, o));
  return out;
}

void drawEnlargedMarks(const Painter& p, const kinematics::World& world,
                       const Enlargements& enlarged) {
  cairo_t* cr = p.cr();
  const double em = p.em();
  const double dots[] = {0.01 * em, 0.22 * em};
  cairo_save(cr);
  cairo_set_dash(cr, dots, 2, 0.0);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  const auto ring = [&](const Enlargement& e) {
    if (e.factor == 1.0) return;
    const Vec2 at = p.image(e.centre);
    cairo_new_sub_path(cr);
    cairo_arc(cr, at.x, at.y, 0.5 * kMinObjectEm * em + 0.3 * em, 0.0, 2.0 * std::numbers::pi);
  };
  for (std::size_t i = 0; i < world.targets.size(); ++i)
    ring(enlargementAt(&enlarged.targets, i));
  for (std::size_t i = 0; i < world.obstacles.size(); ++i)
    ring(enlargementAt(&enlarged.obstacles, i));
  setColour(cr, kText);
  cairo_set_line_width(cr, 0.12 * em);
  cairo_stroke(cr);
  cairo_restore(cr);
}

void drawObjects(const Painter& p, const kinematics::World& world,
                 std::span<const std::optional<Rgb>> targetColours, const Enlargements* enlarged) {
  std::vector<Vec2> scratch;
  const auto target = [&](std::size_t i) {
    return asDrawn(world.targets[i], enlargementAt(enlarged ? &enlarged->targets : nullptr, i),
                   scratch);
  };
  for (std::size_t i = 0; i < world.obstacles.size(); ++i)
    p.ringPath(asDrawn(world.obstacles[i],
                       enlargementAt(enlarged ? &enlarged->obstacles : nullptr, i), scratch));
  p.fill(kObstacle);
  // Targets in the palette's grey as one path; those with a colour of their own one by one.
  for (std::size_t i = 0; i < world.targets.size(); ++i) {
    if (i >= targetColours.size() || !targetColours[i]) p.ringPath(target(i));
  }
  p.fill(kTarget);
  for (std::size_t i = 0; i < std::min(targetColours.size(), world.targets.size()); ++i) {
    if (!targetColours[i]) continue;
    p.ringPath(target(i));
    p.fill(*targetColours[i]);
  }
}

// Red under green: where a seen and an unseen piece meet, the round caps favour what is seen.
void drawSegments(const Painter& p, std::span<const visibility::Segment> segments,
                  const Enlargements* enlarged, const std::vector<std::vector<double>>& weights,
                  Rgb seenColour) {
  cairo_t* cr = p.cr();
  // Round caps and joins: a run of segments that continue one another is one polyline, the
  // same shape as its segments stroked one by one, with fewer edges for Cairo to scan.
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  const auto widthOf = [&](const visibility::Segment& s) {
    return weights.empty() ? kSegmentWidth
                           : kSegmentWidth * importanceWidthFactor(weights[s.target][s.edge]);
  };
  for (const bool seen : {false, true}) {
    const visibility::Segment* last = nullptr;  // the one of this colour drawn before
    for (const auto& s : segments) {
      if ((!s.visibleBy.empty()) != seen) continue;
      const Enlargement e = enlargementAt(enlarged ? &enlarged->targets : nullptr, s.target);
      // A polyline has one width: a segment of another weight starts a new one.
      if (last != nullptr && widthOf(*last) != widthOf(s)) {
        p.stroke(seen ? seenColour : kUnseen, widthOf(*last));
        last = nullptr;
      }
      if (last != nullptr && last->target == s.target && last->b == s.a) {
        p.lineTo(e(s.b));
      } else {
        p.linePath(e(s.a), e(s.b));
      }
      last = &s;
    }
    if (last != nullptr) p.stroke(seen ? seenColour : kUnseen, widthOf(*last));
  }
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
}

void drawView(const Painter& p, std::span<const Vec2> view, double alpha) {
  if (view.size() < 3) return;
  p.ringPath(view);
  // Fill only: the tint's edge is outline enough, and an antialiased outline cost Cairo as
  // much as the fill (its scan converter walks every row the view spans): 1 to 1.5 ms of a
  // dynamic9 video frame.
  p.fill(kView, alpha);
}

namespace {

// A convex polygon with each side moved out by `by`: the outer edge of its stroke of width
// 2 × by with mitred corners (Cairo's default join).
template <std::size_t N>
std::array<Vec2, N> grown(const std::array<Vec2, N>& polygon, double by) {
  const double out = geometry::signedArea(polygon) > 0.0 ? 1.0 : -1.0;  // outside's side
  const auto side = [&](std::size_t i) { return polygon[(i + 1) % N] - polygon[i]; };
  const auto shifted = [&](std::size_t i) {  // a point of side i moved out
    const Vec2 e = side(i);
    return polygon[i] + Vec2{e.y, -e.x} * (out * by / geometry::norm(e));
  };
  std::array<Vec2, N> corners;
  for (std::size_t i = 0; i < N; ++i) {
    const std::size_t before = (i + N - 1) % N;  // the corner where sides `before` and i meet
    const Vec2 a = shifted(before), e = side(before);
    corners[i] = a + e * (geometry::cross(shifted(i) - a, side(i)) / geometry::cross(e, side(i)));
  }
  return corners;
}

void markerPath(cairo_t* cr, Vec2 at, double radius, const std::array<Vec2, 3>& nose) {
  cairo_move_to(cr, nose[0].x, nose[0].y);
  cairo_line_to(cr, nose[1].x, nose[1].y);
  cairo_line_to(cr, nose[2].x, nose[2].y);
  cairo_close_path(cr);
  cairo_new_sub_path(cr);
  cairo_arc(cr, at.x, at.y, radius, 0.0, 2.0 * std::numbers::pi);
}

}  // namespace

void drawCameraMarker(cairo_t* cr, Vec2 at, double yaw, const std::string& label, double em) {
  const Vec2 d = imageHeading(yaw), n{-d.y, d.x};
  const Vec2 base = at + d * (0.3 * em);
  // Tip, then the base's corners: the same turn as the arc's, so the two add up inside.
  const std::array<Vec2, 3> nose{at + d * (1.3 * em), base + n * (0.5 * em), base - n * (0.5 * em)};
  // A pale halo 0.1 em wide around disc and nose together, under them: the shapes grown by
  // that much and filled. Stroking their outline 0.2 em wide drew the same, up to the
  // antialiased rims (tested), but Cairo's stroker makes both edges of the ring and
  // scan-converts between them: the marker took 60 % more instructions (callgrind).
  constexpr double kRadius = 0.6, kHalo = 0.1;  // em
  markerPath(cr, at, (kRadius + kHalo) * em, grown(nose, kHalo * em));
  setColour(cr, kFloor);
  cairo_fill(cr);
  markerPath(cr, at, kRadius * em, nose);
  setColour(cr, kCamera);
  cairo_fill(cr);
  if (!label.empty()) {
    text(cr, {at.x, at.y + 0.25 * em}, label, 0.68 * em, kFloor, Align::Centre, true);
  }
}

std::string svgDocument(int width, int height, const std::function<void(cairo_t*)>& draw) {
  std::string svg;
  const cairo_write_func_t append = [](void* out, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(out)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
  };
  Surface surface(cairo_svg_surface_create_for_stream(append, &svg, width, height));
  // Pixels rather than Cairo's default points, so a browser shows the SVG as large as the PNG.
  cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
  {
    const Context cr(cairo_create(surface.get()));
    draw(cr.get());
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) {
      throw std::runtime_error(std::string("drawing an SVG failed: ") +
                               cairo_status_to_string(cairo_status(cr.get())));
    }
  }
  cairo_surface_finish(surface.get());
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("writing an SVG failed: ") +
                             cairo_status_to_string(cairo_surface_status(surface.get())));
  }
  return svg;
}

}  // namespace camcov::viz
