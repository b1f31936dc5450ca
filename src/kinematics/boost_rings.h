#pragma once
// Our rings as Boost.Geometry polygons, for the kinematics files that cut or overlay objects.
// Internal to the kinematics stage.
#include <boost/geometry.hpp>

#include <vector>

#include "geometry/ring.h"

namespace camcov::kinematics {

namespace bg = boost::geometry;
using BgPoint = bg::model::d2::point_xy<double>;
// Counter-clockwise and open, as our rings are.
using BgPolygon = bg::model::polygon<BgPoint, /*clockwise=*/false, /*closed=*/false>;

inline BgPolygon toPolygon(const geometry::Ring& ring) {
  BgPolygon p;
  for (const geometry::Vec2 v : ring)
    p.outer().emplace_back(v.x, v.y);
  return p;
}

// The pieces where the interiors of `a` and `b` meet.
inline std::vector<BgPolygon> intersectionPieces(const geometry::Ring& a, const geometry::Ring& b) {
  std::vector<BgPolygon> pieces;
  // GCC 12 at -O2 sees Boost 1.74's rescale policy read a factor it always sets first (clang
  // has no such warning).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
  bg::intersection(toPolygon(a), toPolygon(b), pieces);
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
  return pieces;
}

}  // namespace camcov::kinematics
