#pragma once
// The WKT forms the scene format uses, read through Boost.Geometry: POLYGON((x y, ...)) for
// shapes, the boundary and looping paths, POINT(x y) for camera positions and still paths,
// LINESTRING(x y, ...) for paths that go back and forth. Every error names the form to write.
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

// The forms as a person writes them, for messages and help.
inline constexpr std::string_view kPolygonForm = "POLYGON((x1 y1, x2 y2, x3 y3, ...))";
inline constexpr std::string_view kPointForm = "POINT(x y)";
inline constexpr std::string_view kLineStringForm = "LINESTRING(x1 y1, x2 y2, ...)";

// The outer ring exactly as written (open or closed, any orientation, any vertex count >= 1).
// Rejects interior rings, non-finite coordinates and tuples that are not exactly "x y".
std::vector<geometry::Vec2> parseWktPolygonRing(std::string_view text);
geometry::Vec2 parseWktPoint(std::string_view text);
// The points exactly as written (any count >= 1, repeats kept).
std::vector<geometry::Vec2> parseWktLineString(std::string_view text);

// The geometry type a WKT text starts with, upper-cased ("POLYGON", "POINT", ...), or empty.
std::string wktKeyword(std::string_view text);

}  // namespace camcov::scene
