#include "viz/frame_layout.h"

#include <algorithm>

namespace camcov::viz {
namespace {

// Text stays legible in small frames and scales with large ones: 16 px at 720 lines.
double fontSize(double width, double height) {
  return std::max(9.0, std::min(width, height) / 45.0);
}

int ceilDiv(int a, int b) {
  return (a + b - 1) / b;
}

FrameLayout panelRight(double width, double height, const geometry::Box& world, int rows,
                       double em) {
  FrameLayout l;
  l.em = em;
  const double pad = em;
  l.rowsPerColumn = std::max(1, static_cast<int>((height - 2.0 * pad) / l.rowHeight()));
  l.columns = ceilDiv(rows, l.rowsPerColumn);
  const double panelWidth = std::min(width, l.columns * l.columnWidth() + 2.0 * pad);
  l.panel = {width - panelWidth, 0.0, panelWidth, height};
  l.worldArea = {0.0, 0.0, width - panelWidth, height};
  l.toImage = WorldToImage(world, l.worldArea, em);
  return l;
}

FrameLayout panelBottom(double width, double height, const geometry::Box& world, int rows,
                        double em) {
  FrameLayout l;
  l.em = em;
  const double pad = em;
  l.columns = std::max(1, static_cast<int>((width - 2.0 * pad) / l.columnWidth()));
  l.rowsPerColumn = ceilDiv(rows, l.columns);
  const double panelHeight = std::min(height, l.rowsPerColumn * l.rowHeight() + 2.0 * pad);
  l.panel = {0.0, height - panelHeight, width, panelHeight};
  l.worldArea = {0.0, 0.0, width, height - panelHeight};
  l.toImage = WorldToImage(world, l.worldArea, em);
  return l;
}

}  // namespace

geometry::Vec2 FrameLayout::rowOrigin(int row) const {
  const int column = row / rowsPerColumn;
  return {panel.x + em + column * columnWidth(),
          panel.y + em + (row % rowsPerColumn) * rowHeight()};
}

FrameLayout layoutFrame(int width, int height, const geometry::Box& world, int panelRows) {
  const double w = width, h = height;
  const double em = fontSize(w, h);
  const int rows = std::max(1, panelRows);
  FrameLayout right = panelRight(w, h, world, rows, em);
  FrameLayout bottom = panelBottom(w, h, world, rows, em);
  return right.toImage.scale() >= bottom.toImage.scale() ? right : bottom;
}

}  // namespace camcov::viz
