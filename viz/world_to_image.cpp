#include "viz/world_to_image.h"

#include <algorithm>

namespace camcov::viz {

WorldToImage::WorldToImage(const geometry::Box& world, const PixelRect& area, double margin) {
  // A degenerate box (a point) still gets a finite scale instead of a division by zero.
  constexpr double kMinExtent = 1e-9;
  const double w = std::max(world.max.x - world.min.x, kMinExtent);
  const double h = std::max(world.max.y - world.min.y, kMinExtent);
  const double usableW = std::max(area.width - 2.0 * margin, 1.0);
  const double usableH = std::max(area.height - 2.0 * margin, 1.0);
  scale_ = std::min(usableW / w, usableH / h);
  const geometry::Vec2 centre = (world.min + world.max) * 0.5;
  offset_ = {area.x + 0.5 * area.width - scale_ * centre.x,
             area.y + 0.5 * area.height + scale_ * centre.y};
}

}  // namespace camcov::viz
