#pragma once
// World metres to image pixels for one frame: one uniform scale, so shapes keep their aspect,
// and y flipped, since the world's y points up and an image's rows run down.
#include "geometry/ring.h"
#include "geometry/vec2.h"

namespace camcov::viz {

// An axis-aligned rectangle in pixels, (x, y) its top-left corner.
struct PixelRect {
  double x = 0.0;
  double y = 0.0;
  double width = 0.0;
  double height = 0.0;

  bool overlaps(const PixelRect& o) const {
    return x < o.x + o.width && o.x < x + width && y < o.y + o.height && o.y < y + height;
  }
};

class WorldToImage {
 public:
  WorldToImage() = default;
  // Fits `world` into `area` shrunk by `margin` px on every side, centred.
  WorldToImage(const geometry::Box& world, const PixelRect& area, double margin);

  geometry::Vec2 operator()(geometry::Vec2 p) const {
    return {offset_.x + scale_ * p.x, offset_.y - scale_ * p.y};
  }
  double scale() const { return scale_; }  // px per metre

 private:
  double scale_ = 1.0;
  geometry::Vec2 offset_;  // image position of the world's origin
};

}  // namespace camcov::viz
