#include "scene/wkt.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace camcov::scene
