#pragma once
// Where things go in a frame: the world area, with the boundary fitted into it, and a panel
// for the caption and the legend. The two never overlap, so nothing drawn in the world can
// hide the numbers. The panel goes to the right or along the bottom, whichever leaves the
// world larger (right for 16:9 frames of a square world, bottom for square or tall frames).
#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "viz/world_to_image.h"

namespace camcov::viz {

struct FrameLayout {
  static constexpr double kRowHeight = 1.6;     // em, one caption or legend row
  static constexpr double kColumnWidth = 16.0;  // em, one column of panel rows

  double em = 16.0;  // font size, px: every length in a frame is a multiple of it
  PixelRect worldArea;
  PixelRect panel;
  // The panel's rows run top to bottom, then on in the next column.
  int columns = 1;
  int rowsPerColumn = 1;
  WorldToImage toImage;

  double rowHeight() const { return kRowHeight * em; }
  double columnWidth() const { return kColumnWidth * em; }
  // Top-left corner of panel row `row`.
  geometry::Vec2 rowOrigin(int row) const;
};

// For a frame of width × height px showing `world` (the boundary's box) and `panelRows` rows
// of caption and legend.
FrameLayout layoutFrame(int width, int height, const geometry::Box& world, int panelRows);

}  // namespace camcov::viz
