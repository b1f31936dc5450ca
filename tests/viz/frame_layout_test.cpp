#include "viz/frame_layout.h"

#include <gtest/gtest.h>

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

TEST(FrameLayout, TextScalesWithTheFrame) {
  EXPECT_DOUBLE_EQ(layoutFrame(1280, 720, kSquareWorld, kRows).em, 16.0);
  EXPECT_DOUBLE_EQ(layoutFrame(2560, 1440, kSquareWorld, kRows).em, 32.0);
  EXPECT_DOUBLE_EQ(layoutFrame(160, 90, kSquareWorld, kRows).em, 9.0);  // legible minimum
}

}  // namespace
}  // namespace camcov::viz
