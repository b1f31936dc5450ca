#pragma once
// The two WKT forms the scene format uses, read through Boost.Geometry:
// POLYGON((x y, ...)) for shapes, paths and the boundary, POINT(x y) for camera positions.
#include <stdexcept>
#include <string_view>
#include <vector>

#include "geometry/vec2.h"

namespace camcov::scene {

// Thrown with a short problem description; the loader adds file and JSON path.
class WktError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The outer ring exactly as written (open or closed, any orientation, any vertex count >= 1).
// Rejects interior rings, non-finite coordinates and tuples that are not exactly "x y".
std::vector<geometry::Vec2> parseWktPolygonRing(std::string_view text);
geometry::Vec2 parseWktPoint(std::string_view text);

}  // namespace camcov::scene
