#include "scene/wkt.h"

// Boost 1.74's WKT reader trips GCC 12's -Wmaybe-uninitialized inside its own ring appender
// (a false positive in a header we do not own); this file holds nothing else to hide.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <cctype>
#include <cmath>
#include <string>

namespace camcov::scene {
namespace {

namespace bg = boost::geometry;
using BgPoint = bg::model::d2::point_xy<double>;
using BgPolygon = bg::model::polygon<BgPoint, /*ClockWise=*/false, /*Closed=*/false>;

// Boost's reader is lenient: "1 0 1 1" inside one tuple silently becomes two points, and
// "POINT(1)" reads as (1, 0). A scene file that says that is wrong, so every tuple between
// the innermost parentheses must hold exactly two numbers.
void requireCoordinatePairs(std::string_view text) {
  std::size_t pos = 0;
  while ((pos = text.find('(', pos)) != std::string_view::npos) {
    const std::size_t open = pos++;
    if (pos < text.size() && text[pos] == '(') continue;  // not innermost
    const std::size_t close = text.find(')', open);
    if (close == std::string_view::npos) throw WktError("unbalanced parentheses");
    std::string_view body = text.substr(open + 1, close - open - 1);
    std::size_t start = 0;
    int tuple = 0;
    while (start <= body.size()) {
      const std::size_t comma = std::min(body.find(',', start), body.size());
      const std::string_view item = body.substr(start, comma - start);
      int tokens = 0;
      bool inToken = false;
      for (char c : item) {
        const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
        if (!space && !inToken) ++tokens;
        inToken = !space;
      }
      if (tokens != 2) {
        throw WktError("coordinate " + std::to_string(tuple) + " has " + std::to_string(tokens) +
                       " numbers, expected 2 (x y) in '" + std::string(text) + "'");
      }
      ++tuple;
      start = comma + 1;
    }
    pos = close + 1;
  }
}

void requireFinite(const BgPoint& p, std::size_t index) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
    throw WktError("coordinate " + std::to_string(index) + " is not a finite number");
  }
}

template <typename Geometry>
Geometry readWkt(std::string_view text) {
  requireCoordinatePairs(text);
  Geometry g;
  try {
    bg::read_wkt(std::string(text), g);
  } catch (const bg::read_wkt_exception& e) {
    throw WktError(std::string("invalid WKT: ") + e.what());
  } catch (const std::exception& e) {  // boost::bad_lexical_cast for numbers out of range
    throw WktError("invalid WKT '" + std::string(text) + "': " + e.what());
  }
  return g;
}

}  // namespace

std::vector<geometry::Vec2> parseWktPolygonRing(std::string_view text) {
  const auto polygon = readWkt<BgPolygon>(text);
  if (!polygon.inners().empty()) throw WktError("polygons with holes are not supported");
  std::vector<geometry::Vec2> ring;
  ring.reserve(polygon.outer().size());
  for (const auto& p : polygon.outer()) {
    requireFinite(p, ring.size());
    ring.push_back({p.x(), p.y()});
  }
  if (ring.empty()) throw WktError("polygon has no coordinates");
  return ring;
}

geometry::Vec2 parseWktPoint(std::string_view text) {
  const auto point = readWkt<BgPoint>(text);
  requireFinite(point, 0);
  return {point.x(), point.y()};
}

}  // namespace camcov::scene
