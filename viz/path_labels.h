#pragma once
// Where a frame writes each moving object's speed: beside its path, clear of the walls,
// objects, paths and their arrows, cameras, plans and goals, and of each other, by the placer
// the report's scene pictures use too (labels/label_placer.h). The views are a pale tint under
// the labels and a pitch's markings are the ground, so labels may lie on them. A speed with no
// such place is left out of the frame: the report's scene pictures show it, and the run
// explorer on pointing at the loop. Internal to viz/: Cairo measures the text.
#include <cstddef>
#include <string>
#include <vector>

#include "geometry/ring.h"
#include "viz/cairo_drawing.h"
#include "viz/frame.h"

namespace camcov::viz {

inline constexpr double kPathLabelSize = 0.78;  // em, the text
inline constexpr double kPathLabelPad = 0.18;   // em, of the pale box around it

// Where an object path's arrow goes: the middle of its longest leg, the direction of travel
// there (image space); the point itself, without a direction, for an object turning in place.
struct PathAnchor {
  geometry::Vec2 point;      // image px
  geometry::Vec2 direction;  // unit, image space; zero for a turning object
};
PathAnchor anchorOf(const Painter& p, const ObjectPath& path);

struct PathLabel {
  std::size_t path;   // index in Frame::paths
  std::string text;   // ObjectPath::speedLabel()
  geometry::Box box;  // image px: the pale box, text centred in it
};

// The labels that find a place in `area` (the world's), in the order of frame.paths.
std::vector<PathLabel> placePathLabels(const Painter& p, const Frame& frame, const PixelRect& area);

}  // namespace camcov::viz
