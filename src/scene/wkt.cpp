#include "scene/wkt.h"

// Boost 1.74's WKT reader trips GCC 12's -Wmaybe-uninitialized inside its own ring appender
// (a false positive in a header we do not own); this file holds nothing else to hide.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/linestring.hpp>
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
using BgLineString = bg::model::linestring<BgPoint>;

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
                       " numbers, expected 2 (x y)");
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

// Boost's own problem without the text it appends (a quote of the input, with a stray quote
// in one of its two forms): the caller quotes the input once, itself.
std::string boostProblem(const std::string& what, const std::string& text) {
  const std::string quoted = text.substr(0, 100);
  for (const std::string& tail : {"' in (" + quoted + ")", " in '" + quoted + "'"}) {
    if (what.size() >= tail.size() && what.ends_with(tail)) {
      std::string problem = what.substr(0, what.size() - tail.size());
      if (const auto at = problem.rfind(" at '"); at != std::string::npos) problem.resize(at);
      return problem;
    }
  }
  return what;
}

// Reads `text` as `keyword` (Boost's reader for `Geometry`); any problem is a WktError that
// quotes the text and names the form to write.
template <typename Geometry, typename Convert>
auto readWkt(std::string_view text, std::string_view keyword, std::string_view form,
             Convert&& convert) {
  const std::string quoted(text);
  try {
    const std::string found = wktKeyword(text);
    if (found != keyword) {
      throw WktError(found.empty()
                         ? std::string("no geometry type")
                         : "a " + found + " where a " + std::string(keyword) + " is read");
    }
    requireCoordinatePairs(text);
    Geometry g;
    try {
      bg::read_wkt(quoted, g);
    } catch (const bg::read_wkt_exception& e) {
      throw WktError(boostProblem(e.what(), quoted));
    } catch (const std::exception& e) {  // boost::bad_lexical_cast for numbers out of range
      throw WktError(e.what());
    }
    return convert(g);
  } catch (const WktError& e) {
    throw WktError("invalid WKT '" + quoted + "': " + e.what() + "; write " + std::string(form));
  }
}

}  // namespace

std::string wktKeyword(std::string_view text) {
  std::string word;
  std::size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])))
    ++i;
  for (; i < text.size() && std::isalpha(static_cast<unsigned char>(text[i])); ++i)
    word += static_cast<char>(std::toupper(static_cast<unsigned char>(text[i])));
  return word;
}

std::vector<geometry::Vec2> parseWktPolygonRing(std::string_view text) {
  return readWkt<BgPolygon>(text, "POLYGON", kPolygonForm, [](const BgPolygon& polygon) {
    if (!polygon.inners().empty()) throw WktError("polygons with holes are not supported");
    std::vector<geometry::Vec2> ring;
    ring.reserve(polygon.outer().size());
    for (const auto& p : polygon.outer()) {
      requireFinite(p, ring.size());
      ring.push_back({p.x(), p.y()});
    }
    if (ring.empty()) throw WktError("polygon has no coordinates");
    return ring;
  });
}

geometry::Vec2 parseWktPoint(std::string_view text) {
  return readWkt<BgPoint>(text, "POINT", kPointForm, [](const BgPoint& point) {
    requireFinite(point, 0);
    return geometry::Vec2{point.x(), point.y()};
  });
}

std::vector<geometry::Vec2> parseWktLineString(std::string_view text) {
  return readWkt<BgLineString>(text, "LINESTRING", kLineStringForm, [](const BgLineString& line) {
    std::vector<geometry::Vec2> points;
    points.reserve(line.size());
    for (const auto& p : line) {
      requireFinite(p, points.size());
      points.push_back({p.x(), p.y()});
    }
    if (points.empty()) throw WktError("linestring has no coordinates");
    return points;
  });
}

}  // namespace camcov::scene
