#include "scene/wkt.h"

#include <gtest/gtest.h>

#include <string>

namespace camcov::scene {
namespace {

TEST(ParseWktPolygonRing, ReadsOpenAndClosedRingsAsWritten) {
  EXPECT_EQ(parseWktPolygonRing("POLYGON((-2 -1,2 1,2 -1))").size(), 3u);
  EXPECT_EQ(parseWktPolygonRing("POLYGON((-2 -1,2 1,2 -1,-2 -1))").size(), 3u);
  const auto path = parseWktPolygonRing("POLYGON((0 5, 0 -5))");
  ASSERT_EQ(path.size(), 2u);
  EXPECT_EQ(path[1], (geometry::Vec2{0, -5}));
  EXPECT_EQ(parseWktPolygonRing("POLYGON((0 0))").size(), 1u);
}

TEST(ParseWktPolygonRing, RejectsWhatBoostWouldSilentlyAccept) {
  EXPECT_THROW(parseWktPolygonRing("POLYGON((0 0, 1 0 1 1))"), WktError);  // missing comma
  EXPECT_THROW(parseWktPolygonRing("POLYGON((0, 1 0, 1 1))"), WktError);   // lone number
  EXPECT_THROW(parseWktPoint("POINT(1)"), WktError);
}

TEST(ParseWktPolygonRing, RejectsHolesNonFiniteAndGarbage) {
  EXPECT_THROW(parseWktPolygonRing("POLYGON((0 0,4 0,4 4),(1 1,2 1,2 2))"), WktError);
  EXPECT_THROW(parseWktPolygonRing("POLYGON((0 0,nan 0,1 1))"), WktError);
  EXPECT_THROW(parseWktPolygonRing("POLYGON((0 0,1e400 0,1 1))"), WktError);
  EXPECT_THROW(parseWktPolygonRing("POLYGON((0 0,1 0,1 1)) junk"), WktError);
  EXPECT_THROW(parseWktPolygonRing("POINT(1 2)"), WktError);
  EXPECT_THROW(parseWktPolygonRing(""), WktError);
}

TEST(ParseWktPoint, ReadsCoordinates) {
  EXPECT_EQ(parseWktPoint("POINT(25 -17)"), (geometry::Vec2{25, -17}));
  EXPECT_EQ(parseWktPoint("POINT (1.5 2e1)"), (geometry::Vec2{1.5, 20}));
}

TEST(ParseWktLineString, ReadsPointsAsWrittenRepeatsIncluded) {
  const auto line = parseWktLineString("LINESTRING(3 11, 17 11,17 11)");
  ASSERT_EQ(line.size(), 3u);
  EXPECT_EQ(line[1], (geometry::Vec2{17, 11}));
  EXPECT_EQ(parseWktLineString("linestring (1 2)").size(), 1u);
  EXPECT_THROW(parseWktLineString("LINESTRING(1 2 3)"), WktError);
  EXPECT_THROW(parseWktLineString("LINESTRING(1 nan)"), WktError);
}

// What a person wrote, and what to write instead, whatever went wrong.
std::string problemOf(std::vector<geometry::Vec2> (*parse)(std::string_view),
                      std::string_view text) {
  try {
    parse(text);
  } catch (const WktError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(WktErrors, NameTheFormToWriteAndQuoteTheTextOnce) {
  EXPECT_EQ(problemOf(parseWktPolygonRing, "POINT(9 5)"),
            "invalid WKT 'POINT(9 5)': a POINT where a POLYGON is read; "
            "write POLYGON((x1 y1, x2 y2, x3 y3, ...))");
  EXPECT_EQ(problemOf(parseWktPolygonRing, "POLYGON((0 0,1 0,1 1)"),
            "invalid WKT 'POLYGON((0 0,1 0,1 1)': Expected ')'; "
            "write POLYGON((x1 y1, x2 y2, x3 y3, ...))");
  EXPECT_EQ(problemOf(parseWktLineString, "LINESTRING(0 0,1 0"),
            "invalid WKT 'LINESTRING(0 0,1 0': unbalanced parentheses; "
            "write LINESTRING(x1 y1, x2 y2, ...)");
  EXPECT_EQ(problemOf(parseWktLineString, "  3 4"),
            "invalid WKT '  3 4': no geometry type; write LINESTRING(x1 y1, x2 y2, ...)");
  // Boost's own problems keep their words but lose the quote it appends (with a stray ').
  const std::string boost = problemOf(parseWktPolygonRing, "POLYGON((0 0,1 0,1 1)) junk");
  EXPECT_EQ(boost.rfind("invalid WKT 'POLYGON((0 0,1 0,1 1)) junk': ", 0), 0u) << boost;
  EXPECT_NE(boost.find("; write POLYGON(("), std::string::npos) << boost;
  EXPECT_EQ(boost.find("''"), std::string::npos) << boost;
  EXPECT_EQ(boost.find(" in ("), std::string::npos) << boost;
}

TEST(WktKeyword, IsTheLeadingWordUpperCased) {
  EXPECT_EQ(wktKeyword("  linestring(1 2,3 4)"), "LINESTRING");
  EXPECT_EQ(wktKeyword("POINT (1 2)"), "POINT");
  EXPECT_EQ(wktKeyword("(1 2)"), "");
}

}  // namespace
}  // namespace camcov::scene
