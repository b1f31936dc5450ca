#include "viz/frame_layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace camcov::viz {
namespace {

const geometry::Box kSquareWorld{{-15.0, -15.0}, {15.0, 15.0}};
constexpr PanelRows kRows{5, 7};

void expectInside(const PixelRect& inner, const PixelRect& outer) {
  EXPECT_GE(inner.x, outer.x - 1e-9);
  EXPECT_GE(inner.y, outer.y - 1e-9);
  EXPECT_LE(inner.x + inner.width, outer.x + outer.width + 1e-9);
  EXPECT_LE(inner.y + inner.height, outer.y + outer.height + 1e-9);
}

TEST(FrameLayout, WideFramePutsThePanelRightOfTheWorldWithoutOverlap) {
  const FrameLayout l = layoutFrame(1280, 720, kSquareWorld, kRows);
  EXPECT_FALSE(l.worldArea.overlaps(l.panel));
  EXPECT_GE(l.panel.x, l.worldArea.x + l.worldArea.width);
  EXPECT_EQ(l.columns, 1);
  // The boundary's corners land inside the world area.
  const PixelRect frame{0.0, 0.0, 1280.0, 720.0};
  expectInside(l.worldArea, frame);
  expectInside(l.panel, frame);
  for (const geometry::Vec2 corner : {kSquareWorld.min, kSquareWorld.max}) {
    const geometry::Vec2 p = l.toImage(corner);
    EXPECT_GT(p.x, l.worldArea.x);
    EXPECT_LT(p.x, l.worldArea.x + l.worldArea.width);
    EXPECT_GT(p.y, l.worldArea.y);
    EXPECT_LT(p.y, l.worldArea.y + l.worldArea.height);
  }
  // The legend follows the caption in the same column, and every row fits in the panel.
  EXPECT_EQ(l.legendRow(0).x, l.captionRow(0).x);
  EXPECT_GT(l.legendRow(0).y, l.captionRow(4).y + l.rowHeight());
  const geometry::Vec2 last = l.legendRow(6);
  EXPECT_LE(last.y + l.rowHeight(), l.panel.y + l.panel.height);
}

TEST(FrameLayout, SquareFramePutsTheCaptionBelowWithTheLegendBesideIt) {
  const FrameLayout l = layoutFrame(720, 720, kSquareWorld, kRows);
  EXPECT_FALSE(l.worldArea.overlaps(l.panel));
  EXPECT_GE(l.panel.y, l.worldArea.y + l.worldArea.height);
  EXPECT_EQ(l.columns, 2);
  EXPECT_EQ(l.legendRow(0).y, l.captionRow(0).y);
  EXPECT_GE(l.legendRow(0).x, l.captionRow(0).x + l.columnWidth());
  const geometry::Vec2 last = l.legendRow(6);
  EXPECT_LE(last.x + l.columnWidth(), l.panel.x + l.panel.width);
  EXPECT_LE(last.y + l.rowHeight(), l.panel.y + l.panel.height);
}

// Cairo clips to a rectangle on pixel edges without a mask; the renderer clips to both areas.
TEST(FrameLayout, WorldAreaAndPanelLieOnWholePixels) {
  const geometry::Box wide{{0.0, 0.0}, {37.3, 11.9}}, tall{{0.0, 0.0}, {7.1, 23.7}};
  for (const auto& [width, height] : {std::pair{1280, 720}, {720, 720}, {1000, 562}, {642, 998}}) {
    for (const geometry::Box& world : {kSquareWorld, wide, tall}) {
      const FrameLayout l = layoutFrame(width, height, world, kRows);
      for (const PixelRect& r : {l.worldArea, l.panel}) {
        SCOPED_TRACE(::testing::Message()
                     << width << "x" << height << " world " << world.max.x << "x" << world.max.y);
        for (const double edge : {r.x, r.y, r.width, r.height})
          EXPECT_EQ(edge, std::round(edge));
      }
      EXPECT_FALSE(l.worldArea.overlaps(l.panel));
    }
  }
}

TEST(FrameLayout, TextScalesWithTheFrame) {
  EXPECT_DOUBLE_EQ(layoutFrame(1280, 720, kSquareWorld, kRows).em, 16.0);
  EXPECT_DOUBLE_EQ(layoutFrame(2560, 1440, kSquareWorld, kRows).em, 32.0);
  EXPECT_DOUBLE_EQ(layoutFrame(160, 90, kSquareWorld, kRows).em, 9.0);  // legible minimum
}

}  // namespace
}  // namespace camcov::viz
