#include "viz/frame_layout.h"

#include <algorithm>
#include <cmath>

namespace camcov::viz {
namespace {

// Text stays legible in small frames and scales with large ones: 16 px at 720 lines.
double fontSize(double width, double height) {
  return std::max(9.0, std::min(width, height) / 45.0);
}

int ceilDiv(int a, int b) {
  return (a + b - 1) / b;
}

// Pixels the world takes in `area`, margins included.
geometry::Vec2 worldSize(const geometry::Box& world, const PixelRect& area, double margin) {
  const double scale = WorldToImage(world, area, margin).scale();
  return (world.max - world.min) * scale + geometry::Vec2{2.0 * margin, 2.0 * margin};
}

// One column, the legend a blank row below the caption; more columns only if it is too tall.
FrameLayout panelRight(double width, double height, const geometry::Box& world, PanelRows rows,
                       double em) {
  FrameLayout l;
  l.em = em;
  const double pad = em;
  l.legendStart = rows.caption + 1;
  l.rowsPerColumn = std::max(1, static_cast<int>((height - 2.0 * pad) / l.rowHeight()));
  l.columns = ceilDiv(l.legendStart + rows.legend, l.rowsPerColumn);
  // Both areas are whole pixels (see FrameLayout).
  const double panelWidth = std::min(width, std::ceil(l.columns * l.columnWidth() + 2.0 * pad));
  // The world and the panel side by side, centred together rather than the world alone, so
  // the panel sits next to the drawing instead of at the frame's far edge.
  const PixelRect available{0.0, 0.0, width - panelWidth, height};
  const double used = std::floor(std::min(available.width, worldSize(world, available, em).x));
  const double left = std::round(0.5 * (width - used - panelWidth));
  l.worldArea = {left, 0.0, used, height};
  l.panel = {left + used, 0.0, panelWidth, height};
  l.toImage = WorldToImage(world, l.worldArea, em);
  return l;
}

// The caption in the first column, the legend in the columns beside it.
FrameLayout panelBottom(double width, double height, const geometry::Box& world, PanelRows rows,
                        double em) {
  FrameLayout l;
  l.em = em;
  const double pad = em;
  const int fit = std::max(1, static_cast<int>((width - 2.0 * pad) / l.columnWidth()));
  if (fit == 1) {
    l.legendStart = rows.caption + 1;
    l.rowsPerColumn = l.legendStart + rows.legend;
  } else {
    l.rowsPerColumn = std::max(rows.caption, ceilDiv(rows.legend, fit - 1));
    l.legendStart = l.rowsPerColumn;
  }
  l.columns = ceilDiv(l.legendStart + rows.legend, l.rowsPerColumn);
  const double panelHeight =
      std::min(height, std::ceil(l.rowsPerColumn * l.rowHeight() + 2.0 * pad));
  const PixelRect available{0.0, 0.0, width, height - panelHeight};
  const double used = std::floor(std::min(available.height, worldSize(world, available, em).y));
  const double top = std::round(0.5 * (height - used - panelHeight));
  l.worldArea = {0.0, top, width, used};
  l.panel = {0.0, top + used, width, panelHeight};
  l.toImage = WorldToImage(world, l.worldArea, em);
  return l;
}

}  // namespace

geometry::Vec2 FrameLayout::gridRow(int row) const {
  const int column = row / rowsPerColumn;
  return {panel.x + em + column * columnWidth(),
          panel.y + em + (row % rowsPerColumn) * rowHeight()};
}

FrameLayout layoutFrame(int width, int height, const geometry::Box& world, PanelRows rows) {
  const double w = width, h = height;
  const double em = fontSize(w, h);
  rows.caption = std::max(1, rows.caption);
  rows.legend = std::max(0, rows.legend);
  FrameLayout right = panelRight(w, h, world, rows, em);
  FrameLayout bottom = panelBottom(w, h, world, rows, em);
  FrameLayout& chosen = right.toImage.scale() >= bottom.toImage.scale() ? right : bottom;
  chosen.rows = rows;
  return chosen;
}

}  // namespace camcov::viz
