#pragma once
// Where things go in a frame: the world area, with the boundary fitted into it, and a panel
// for the caption and the legend. The two never overlap, so nothing drawn in the world can
// hide the numbers. The panel goes to the right or along the bottom, whichever leaves the
// world larger (right for 16:9 frames of a square world, bottom for square or tall frames).
#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "viz/world_to_image.h"

namespace camcov::viz {

struct PanelRows {
  int caption = 1;
  int legend = 0;
};

struct FrameLayout {
  static constexpr double kRowHeight = 1.6;     // em, one caption or legend row
  static constexpr double kColumnWidth = 16.0;  // em, one column of panel rows

  double em = 16.0;  // font size, px: every length in a frame is a multiple of it
  // Whole pixels. Each is the clip of what is drawn in it, and Cairo clips to a rectangle on
  // pixel edges without a mask: with fractional edges every fill and stroke in the world
  // went through one, which cost a dynamic9 frame 0.3 to 0.5 ms.
  PixelRect worldArea;
  PixelRect panel;
  // The panel is a grid of rows, filled top to bottom, then on in the next column. The
  // legend starts after a blank row below the caption, or at the top of the next column.
  int columns = 1;
  int rowsPerColumn = 1;
  int legendStart = 0;  // grid row of the legend's first row
  PanelRows rows;       // the caption's and the legend's
  WorldToImage toImage;

  double rowHeight() const { return kRowHeight * em; }
  double columnWidth() const { return kColumnWidth * em; }
  // Top-left corners of caption row i and legend row i.
  geometry::Vec2 captionRow(int i) const { return gridRow(i); }
  geometry::Vec2 legendRow(int i) const { return gridRow(legendStart + i); }

 private:
  geometry::Vec2 gridRow(int row) const;
};

// For a frame of width × height px showing `world` (the boundary's box) and `rows`.
FrameLayout layoutFrame(int width, int height, const geometry::Box& world, PanelRows rows);

}  // namespace camcov::viz
