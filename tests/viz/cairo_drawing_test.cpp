// Two shapes drawn more cheaply than Cairo would draw them plainly, checked against the plain
// way: the camera marker's pale halo is its shapes grown by 0.1 em and filled under it, not
// their outline stroked 0.2 em wide (mitred); a run of target boundary segments that continue
// one another is stroked as one polyline with round joins, not segment by segment with round
// caps.
#include "viz/cairo_drawing.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <vector>

namespace camcov::viz {
namespace {

using geometry::Vec2;

constexpr int kSize = 96;

// Premultiplied opaque pixels of a kSize² grey image with `draw` on it.
template <typename Draw>
std::vector<std::uint32_t> drawn(Draw draw) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kSize, kSize);
  cairo_t* cr = cairo_create(s);
  cairo_set_source_rgb(cr, 0.5, 0.5, 0.5);
  cairo_paint(cr);
  draw(cr);
  cairo_destroy(cr);
  cairo_surface_flush(s);
  std::vector<std::uint32_t> pixels(kSize * kSize);
  for (int y = 0; y < kSize; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(cairo_image_surface_get_data(s) +
                                                             y * cairo_image_surface_get_stride(s));
    std::copy(row, row + kSize, pixels.begin() + y * kSize);
  }
  cairo_surface_destroy(s);
  return pixels;
}

// The marker as it was drawn before: the outline stroked, then filled.
void strokedHaloMarker(cairo_t* cr, Vec2 at, double yaw, double em) {
  const Vec2 d = imageHeading(yaw), n{-d.y, d.x};
  const Vec2 tip = at + d * (1.3 * em), base = at + d * (0.3 * em);
  cairo_move_to(cr, tip.x, tip.y);
  cairo_line_to(cr, base.x + n.x * 0.5 * em, base.y + n.y * 0.5 * em);
  cairo_line_to(cr, base.x - n.x * 0.5 * em, base.y - n.y * 0.5 * em);
  cairo_close_path(cr);
  cairo_new_sub_path(cr);
  cairo_arc(cr, at.x, at.y, 0.6 * em, 0.0, 2.0 * std::numbers::pi);
  setColour(cr, kFloor);
  cairo_set_line_width(cr, 0.2 * em);
  cairo_stroke_preserve(cr);
  setColour(cr, kCamera);
  cairo_fill(cr);
}

int channelDifference(std::uint32_t a, std::uint32_t b) {
  int most = 0;
  for (int shift = 0; shift < 24; shift += 8)
    most = std::max(most, std::abs(static_cast<int>((a >> shift) & 255) -
                                   static_cast<int>((b >> shift) & 255)));
  return most;
}

TEST(CameraMarker, HaloDrawnAsAFillMatchesCairosStrokeOfTheOutline) {
  for (const double em : {9.0, 13.0, 30.0}) {
    for (const double yaw : {0.0, 0.7, 2.0, -2.6}) {
      const Vec2 at{47.3, 48.6};
      const auto ours = drawn([&](cairo_t* cr) { drawCameraMarker(cr, at, yaw, "", em); });
      const auto stroked = drawn([&](cairo_t* cr) { strokedHaloMarker(cr, at, yaw, em); });
      int worst = 0, differing = 0, halo = 0;
      for (std::size_t i = 0; i < ours.size(); ++i) {
        const int d = channelDifference(ours[i], stroked[i]);
        worst = std::max(worst, d);
        differing += d > 2;
        halo += (stroked[i] & 255) > 128;  // lighter than the grey: the halo
      }
      EXPECT_GT(halo, 4 * em);  // about its length, 4.4 em, times its width, a pixel or more
      // Only antialiased rims differ, where Cairo flattens the two shapes differently: by
      // up to 17 levels at 9 px an em, in at most about the halo's length in pixels.
      EXPECT_LE(worst, 24) << "em " << em << " yaw " << yaw;
      EXPECT_LE(differing, 3 * em) << "em " << em << " yaw " << yaw;
    }
  }
}

// Five segments in a 10 m square drawn 8.6 px a metre: a run of three seen ones that turns
// sharply (a mitred join would stick out), then two unseen ones, the second of which starts
// away from where the first ends.
TEST(Segments, ARunIsStrokedAsOnePolylineWithTheShapeOfItsSegmentsStrokedOneByOne) {
  using scene::CameraSet;
  using visibility::Segment;
  const std::vector<Segment> segments{{{1.0, 1.0}, {6.0, 1.5}, 0, 0, CameraSet::fromBits(1)},
                                      {{6.0, 1.5}, {9.0, 5.0}, 0, 1, CameraSet::fromBits(1)},
                                      {{9.0, 5.0}, {4.0, 3.0}, 0, 2, CameraSet::fromBits(3)},
                                      {{7.0, 9.0}, {2.0, 8.0}, 0, 3, {}},
                                      {{2.5, 7.0}, {1.0, 1.2}, 0, 4, {}}};
  const WorldToImage toImage({{0.0, 0.0}, {10.0, 10.0}}, {0.0, 0.0, kSize, kSize}, 5.0);
  const double em = 12.0;
  const auto ours = drawn([&](cairo_t* cr) { drawSegments(Painter(cr, toImage, em), segments); });
  const auto oneByOne = drawn([&](cairo_t* cr) {
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_width(cr, kSegmentWidth * em);
    for (const bool seen : {false, true}) {
      for (const Segment& s : segments) {
        if ((!s.visibleBy.empty()) != seen) continue;
        const Vec2 a = toImage(s.a), b = toImage(s.b);
        cairo_move_to(cr, a.x, a.y);
        cairo_line_to(cr, b.x, b.y);
        setColour(cr, seen ? kSeen : kUnseen);
        cairo_stroke(cr);
      }
    }
  });
  int worst = 0, differing = 0, seenPixels = 0;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    const int d = channelDifference(ours[i], oneByOne[i]);
    worst = std::max(worst, d);
    differing += d > 2;
    seenPixels += ((oneByOne[i] >> 8) & 255) > 128 && ((oneByOne[i] >> 16) & 255) < 64;
  }
  EXPECT_GT(seenPixels, 200);
  // Where two strokes overlap, stroking them one by one composites the antialiased rim twice.
  EXPECT_LE(worst, 40);
  EXPECT_LE(differing, 30);
}

}  // namespace
}  // namespace camcov::viz
