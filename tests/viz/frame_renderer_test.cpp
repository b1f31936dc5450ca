// Frames of the tiny scene at t = 0: one camera at (-3, 0) looking along +x sees the left
// edge of the square target centred at (2, 0) and not its right edge; the obstacle at (-1, 3)
// is out of its view. Colours are sampled in the middle of thick strokes and fills, so
// antialiasing at their edges does not matter.
#include "viz/frame_renderer.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "viz_test_support.h"

namespace camcov::viz {
namespace {

using geometry::Vec2;
using testing::ScratchDir;

struct Colour {
  double r, g, b;
};

class TinyFrame : public ::testing::Test {
 protected:
  TinyFrame() : scene_(scene::loadScene(testing::tinyScene())), renderer_(800, 600) {
    FrameBuilder builder(scene_);
    builder.build(0.0, std::vector<geometry::Pose>{scene_.cameras[0].initial}, frame_);
    frame_.caption.subtitle = "test";
  }

  // The PNG written to disk, read back through Cairo.
  void writeAndLoad(const std::filesystem::path& file) {
    renderer_.write(frame_, file);
    png_.reset(cairo_image_surface_create_from_png(file.c_str()));
    ASSERT_EQ(cairo_surface_status(png_.get()), CAIRO_STATUS_SUCCESS);
    ASSERT_EQ(cairo_image_surface_get_width(png_.get()), 800);
    ASSERT_EQ(cairo_image_surface_get_height(png_.get()), 600);
  }

  Colour at(Vec2 world) const {
    const Vec2 p = renderer_.layoutOf(frame_).toImage(world);
    cairo_surface_t* s = png_.get();
    const unsigned char* row =
        cairo_image_surface_get_data(s) + static_cast<int>(p.y) * cairo_image_surface_get_stride(s);
    std::uint32_t word;
    std::memcpy(&word, row + 4 * static_cast<int>(p.x), 4);
    return {((word >> 16) & 255) / 255.0, ((word >> 8) & 255) / 255.0, (word & 255) / 255.0};
  }

  struct SurfaceDeleter {
    void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
  };
  scene::Scene scene_;
  FrameRenderer renderer_;
  Frame frame_;
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> png_;
};

TEST_F(TinyFrame, BuilderFindsTheSeenEdgeAndCoverage) {
  // The square's left edge (2 m of the 8 m perimeter) is all the camera sees of the targets.
  EXPECT_NEAR(frame_.caption.coverage, 2.0 / (8.0 + 1.0 + 2.0 * std::hypot(0.5, 0.8)), 1e-9);
  ASSERT_EQ(frame_.cameras.size(), 1u);
  EXPECT_GE(frame_.cameras[0].view.size(), 3u);
  ASSERT_EQ(frame_.paths.size(), 1u);  // only the sliding target moves
  EXPECT_EQ(frame_.paths[0].velocity, 0.5);
}

TEST_F(TinyFrame, PngShowsSeenGreenUnseenRedObstacleDarkAndEmptyFloorWhite) {
  ScratchDir dir;
  writeAndLoad(dir / "frame.png");
  const Colour seen = at({1.0, 0.0});
  EXPECT_GT(seen.g, seen.r + 0.3);
  EXPECT_GT(seen.g, seen.b + 0.3);
  const Colour unseen = at({3.0, 0.0});
  EXPECT_GT(unseen.r, unseen.g + 0.4);
  EXPECT_GT(unseen.r, unseen.b + 0.4);
  const Colour obstacle = at({-1.0, 3.0});
  EXPECT_LT(std::max({obstacle.r, obstacle.g, obstacle.b}), 0.35);
  const Colour floor = at({3.5, 4.0});
  EXPECT_GT(std::min({floor.r, floor.g, floor.b}), 0.97);
  const Colour target = at({2.0, 0.5});  // grey: no hue, mid lightness
  EXPECT_NEAR(target.r, target.b, 0.06);
  EXPECT_GT(target.g, 0.5);
  EXPECT_LT(target.g, 0.9);
  const Colour view = at({-1.0, 0.3});  // amber tint inside the field of view
  EXPECT_GT(view.r, view.b + 0.15);
}

// A target a few centimetres across is drawn kMinObjectEm across, its seen edge with it, and
// ringed with dots: without, it would be a pixel.
TEST_F(TinyFrame, ATargetTooSmallToMakeOutIsDrawnEnlargedAndRinged) {
  const Vec2 centre{2.0, -3.0};
  frame_.world.targets.push_back(
      {centre + Vec2{-0.01, -0.01}, centre + Vec2{0.01, -0.01}, centre + Vec2{0.0, 0.01}});
  frame_.segments.push_back({centre + Vec2{-0.01, -0.01}, centre + Vec2{0.01, -0.01},
                             static_cast<std::uint32_t>(frame_.world.targets.size() - 1), 0,
                             scene::CameraSet::only(0)});
  ScratchDir dir;
  writeAndLoad(dir / "small.png");
  const FrameLayout layout = renderer_.layoutOf(frame_);
  const Vec2 middle = layout.toImage(centre);
  cairo_surface_t* surface = png_.get();
  const auto dark = [&](int x, int y) {  // target grey, seen green or the ring's dots
    const unsigned char* row =
        cairo_image_surface_get_data(surface) + y * cairo_image_surface_get_stride(surface);
    std::uint32_t word;
    std::memcpy(&word, row + 4 * x, 4);
    return ((word >> 8) & 255) < 235;
  };
  int marked = 0, ringed = 0;
  const int reach = static_cast<int>(std::ceil(1.5 * layout.em));
  for (int y = static_cast<int>(middle.y) - reach; y <= static_cast<int>(middle.y) + reach; ++y) {
    for (int x = static_cast<int>(middle.x) - reach; x <= static_cast<int>(middle.x) + reach; ++x) {
      if (!dark(x, y)) continue;
      const double d = std::hypot(x + 0.5 - middle.x, y + 0.5 - middle.y);
      if (d < 0.45 * layout.em) ++marked;
      if (d > 0.7 * layout.em) ++ringed;
    }
  }
  // The triangle is half a square of kMinObjectEm: about a third of the disc of 0.45 em.
  EXPECT_GT(marked, static_cast<int>(0.2 * layout.em * layout.em)) << "enlarged";
  EXPECT_GT(ringed, 8) << "ringed with dots";
}

// A weighted scene's edges are as wide as they are important, and its panel has a row for
// weighted coverage and a legend row for the widths.
TEST_F(TinyFrame, AWeightedWorldsEdgesAreAsWideAsImportant) {
  const auto seenWidth = [&](double weight, const char* file) {
    frame_.world.targetEdgeWeights.clear();
    for (const geometry::Ring& ring : frame_.world.targets)
      frame_.world.targetEdgeWeights.emplace_back(ring.size(), weight);
    frame_.caption.weightedCoverage = frame_.caption.coverage;
    ScratchDir dir;
    writeAndLoad(dir / file);
    // Green pixels on the row through the seen left edge of the square (x = 1).
    int green = 0;
    for (double x = 0.5; x <= 1.5; x += 0.002) {
      const Colour c = at({x, 0.0});
      if (c.g > c.r + 0.3 && c.g > c.b + 0.3) ++green;
    }
    return green;
  };
  const int heavy = seenWidth(1.0, "heavy.png"), light = seenWidth(0.0, "light.png");
  EXPECT_GT(heavy, 3 * light) << "1.6 against 0.4 times the plain width";
  const FrameLayout layout = renderer_.layoutOf(frame_);
  EXPECT_EQ(layout.rows.caption, 6) << "time, coverage, utilization, weighted coverage";
  EXPECT_EQ(layout.rows.legend, 8) << "and what the widths mean";
  frame_.caption.weightedCoverage.reset();
  EXPECT_EQ(renderer_.layoutOf(frame_).rows.legend, 7);
}

// In a scene that asks a resolution, the seen pieces no camera resolves are amber, the rest
// green; the panel has a row for resolved coverage and a legend row for the amber. The camera
// 4 m from the seen edge x = 1 images it with k·h/d² pixels per metre (k = W / 2θ): with
// W = 431 and ρ_min = 100 the resolved disc has a radius √(k·4/100) = 4.06 m, so the middle of
// the edge (|y| < 0.7) is resolved and its ends are not.
TEST_F(TinyFrame, InASceneThatAsksAResolutionTheUnresolvedSeenPiecesAreAmber) {
  scene_.cameras[0].lens.imageWidth = 431.0;
  scene_.resolution = scene::ResolutionRequirement{100.0, false};
  FrameBuilder(scene_).build(0.0, std::vector<geometry::Pose>{scene_.cameras[0].initial}, frame_);
  ASSERT_TRUE(frame_.caption.resolutionCoverage.has_value());
  EXPECT_LT(*frame_.caption.resolutionCoverage, frame_.caption.coverage);
  ASSERT_EQ(frame_.unresolved.size(), 2u) << "both ends of the seen edge";
  ScratchDir dir;
  writeAndLoad(dir / "resolution.png");
  const auto amber = [](Colour c) { return c.r > 0.8 && c.g > 0.45 && c.g < 0.8 && c.b < 0.3; };
  const auto green = [](Colour c) { return c.g > c.r + 0.3 && c.g > c.b + 0.3; };
  EXPECT_TRUE(green(at({1.0, 0.0}))) << "the resolved middle";
  EXPECT_TRUE(amber(at({1.0, 0.9}))) << "an unresolved end";
  EXPECT_TRUE(amber(at({1.0, -0.9}))) << "the other";
  const FrameLayout layout = renderer_.layoutOf(frame_);
  EXPECT_EQ(layout.rows.caption, 6) << "time, coverage, resolved, utilization";
  EXPECT_EQ(layout.rows.legend, 8) << "and what amber means";
}

// A title wider than the panel is made smaller, then cut with an ellipsis: the panel's right
// margin stays the page's colour, never the title's clipped glyphs.
TEST_F(TinyFrame, ATitleWiderThanThePanelIsFittedNotClipped) {
  frame_.caption.title = std::string(120, 'W');
  ScratchDir dir;
  writeAndLoad(dir / "long.png");
  const FrameLayout layout = renderer_.layoutOf(frame_);
  cairo_surface_t* surface = png_.get();
  const int right = static_cast<int>(layout.panel.x + layout.panel.width) - 1;
  const int top = static_cast<int>(layout.captionRow(0).y);
  for (int y = top; y < top + static_cast<int>(layout.rowHeight()); ++y) {
    for (int x = right - static_cast<int>(0.4 * layout.em); x <= right; ++x) {
      const unsigned char* row =
          cairo_image_surface_get_data(surface) + y * cairo_image_surface_get_stride(surface);
      std::uint32_t word;
      std::memcpy(&word, row + 4 * x, 4);
      EXPECT_GT((word >> 8) & 255, 200u) << "title ink at x " << x << ", y " << y;
    }
  }
}

TEST_F(TinyFrame, SvgHoldsTheSameDrawingAsVectors) {
  ScratchDir dir;
  const auto file = dir / "frame.svg";
  renderer_.write(frame_, file);
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  const std::string svg = text.str();
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("width=\"800px\" height=\"600px\""), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  // Vectors, not an embedded raster.
  EXPECT_EQ(svg.find("<image"), std::string::npos);
  std::size_t paths = 0;
  for (auto i = svg.find("<path"); i != std::string::npos; i = svg.find("<path", i + 1))
    ++paths;
  EXPECT_GT(paths, 20u);
  // Text (caption, legend) as glyphs.
  EXPECT_NE(svg.find("<use xlink:href=\"#glyph"), std::string::npos);
}

TEST_F(TinyFrame, RasterIsReusedBetweenFrames) {
  const RasterImage first = renderer_.rasterize(frame_);
  const RasterImage second = renderer_.rasterize(frame_);
  EXPECT_EQ(first.pixels, second.pixels);
  EXPECT_EQ(second.width, 800);
  EXPECT_EQ(second.height, 600);
  EXPECT_GE(second.stride, 4 * 800);
}

std::vector<std::uint8_t> pixelsOf(const RasterImage& image) {
  return {image.pixels, image.pixels + static_cast<std::ptrdiff_t>(image.stride) * image.height};
}

// The raster keeps the still part of a frame (page, floor, wall, object paths, title,
// subtitle, legend) and, over the previous frame, restores only the areas where things move
// before drawing them: the pixels must be those of a renderer that draws the frame from
// scratch. Also with the panel at the bottom, where the caption's rows fill more columns.
TEST_F(TinyFrame, FrameOverTheKeptStillPartEqualsOneDrawnFromScratch) {
  Frame later;
  FrameBuilder(scene_).build(3.0, std::vector<geometry::Pose>{{-2.0, 1.0, 0.4}}, later);
  later.caption.subtitle = frame_.caption.subtitle;
  later.caption.coverage = 0.93;  // a longer meter than the first frame's, then a shorter one
  Frame last = later;
  last.caption.coverage = 0.05;
  last.caption.time = 12.5;
  for (const auto& [width, height] : {std::pair{800, 600}, {400, 700}, {300, 300}}) {
    FrameRenderer kept(width, height, FrameUse::Video), fresh(width, height, FrameUse::Video);
    const auto first = pixelsOf(kept.rasterize(frame_));
    const auto second = pixelsOf(kept.rasterize(later));
    EXPECT_NE(second, first);
    EXPECT_EQ(second, pixelsOf(fresh.rasterize(later))) << width << "x" << height;
    EXPECT_EQ(pixelsOf(kept.rasterize(last)), pixelsOf(fresh.rasterize(last)))
        << width << "x" << height;
  }
}

// An image says where it may differ from the one before it (what spares the encoder a
// conversion): checked pixel by pixel against the previous image, for the frame shapes of
// the test above. A changed still part makes no promise.
TEST_F(TinyFrame, ImagesDifferFromThePreviousOneOnlyWhereTheySay) {
  Frame later;
  FrameBuilder(scene_).build(3.0, std::vector<geometry::Pose>{{-2.0, 1.0, 0.4}}, later);
  later.caption.subtitle = frame_.caption.subtitle;
  later.caption.coverage = 0.93;
  for (const auto& [width, height] : {std::pair{800, 600}, {400, 700}, {300, 300}}) {
    FrameRenderer renderer(width, height, FrameUse::Video);
    const RasterImage first = renderer.rasterize(frame_);
    EXPECT_NE(first.serial, 0u);
    EXPECT_EQ(first.changedSince, 0u);
    const auto before = pixelsOf(first);
    const RasterImage second = renderer.rasterize(later);
    EXPECT_NE(second.serial, first.serial);
    EXPECT_EQ(second.changedSince, first.serial);
    const auto after = pixelsOf(second);
    std::size_t differing = 0;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const std::size_t at = static_cast<std::size_t>(y) * second.stride + 4 * x;
        if (std::memcmp(&before[at], &after[at], 4) == 0) continue;
        ++differing;
        const bool inChanged =
            std::any_of(second.changed.begin(), second.changed.end(), [&](const PixelBox& box) {
              return x >= box.x && x < box.x + box.width && y >= box.y && y < box.y + box.height;
            });
        ASSERT_TRUE(inChanged) << "pixel " << x << "," << y << " of " << width << "x" << height;
      }
    }
    EXPECT_GT(differing, 0u);
    Frame retitled = later;
    retitled.caption.subtitle = "another subtitle";
    EXPECT_EQ(renderer.rasterize(retitled).changedSince, 0u);
  }
}

TEST_F(TinyFrame, StillPartIsRedrawnWhenWhatItShowsChanges) {
  renderer_.rasterize(frame_);
  Frame other = frame_;
  other.caption.subtitle = "another subtitle";
  other.paths.clear();
  const auto kept = pixelsOf(renderer_.rasterize(other));
  FrameRenderer fresh(800, 600);
  EXPECT_EQ(kept, pixelsOf(fresh.rasterize(other)));
}

// Video frames draw the views' tint with aliased edges (FrameUse::Video): the same pixels as
// a still but along the tint's outline, where an edge of L px touches at most about 2 L
// pixels partly.
TEST_F(TinyFrame, VideoFramesDifferFromStillsOnlyAlongTheViewsOutline) {
  const auto still = pixelsOf(renderer_.rasterize(frame_));
  FrameRenderer video(800, 600, FrameUse::Video);
  const RasterImage image = video.rasterize(frame_);
  const auto moving = pixelsOf(image);
  ASSERT_EQ(moving.size(), still.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < still.size(); i += 4)
    differing += std::memcmp(&still[i], &moving[i], 4) != 0;
  const auto& view = frame_.cameras[0].view;
  const FrameLayout layout = renderer_.layoutOf(frame_);
  double outline = 0.0;  // px
  for (std::size_t i = 0; i < view.size(); ++i)
    outline +=
        geometry::distance(layout.toImage(view[i]), layout.toImage(view[(i + 1) % view.size()]));
  EXPECT_GT(differing, 0u);
  EXPECT_LT(static_cast<double>(differing), 2.0 * outline);
  // Well inside the tint nothing changes.
  const Vec2 inside = layout.toImage({-1.0, 0.3});
  const std::size_t at =
      static_cast<std::size_t>(inside.y) * image.stride + 4 * static_cast<std::size_t>(inside.x);
  EXPECT_EQ(std::memcmp(&still[at], &moving[at], 4), 0);
}

TEST(ImageFormat, ComesFromTheExtensionInAnyCase) {
  EXPECT_EQ(imageFormatOf("a/b.png"), ImageFormat::Png);
  EXPECT_EQ(imageFormatOf("b.SVG"), ImageFormat::Svg);
  EXPECT_THROW(imageFormatOf("b.jpg"), InputError);
  EXPECT_THROW(imageFormatOf("png"), InputError);
}

TEST_F(TinyFrame, MissingFoldersAreMadeAndAFileInTheWayIsAnInputError) {
  ScratchDir dir;
  for (const char* name : {"f.png", "f.svg"}) {
    renderer_.write(frame_, dir / "new" / "deeper" / name);
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "new" / "deeper" / name)) << name;
  }
  std::ofstream(dir / "plain") << "not a folder";
  EXPECT_THROW(renderer_.write(frame_, dir / "plain" / "f.png"), InputError);
  EXPECT_THROW(renderer_.write(frame_, dir / "plain" / "f.svg"), InputError);
}

TEST(FrameRenderer, RejectsSizesOutsideItsRange) {
  EXPECT_THROW(FrameRenderer(8, 600), std::invalid_argument);
  EXPECT_THROW(FrameRenderer(800, 100000), std::invalid_argument);
}

}  // namespace
}  // namespace camcov::viz
