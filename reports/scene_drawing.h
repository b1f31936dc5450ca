#pragma once
// The paper's Fig. 3 for one scene as geometry in SVG pixels, before it is written as SVG
// (scene_gallery.h): what is drawn, and where each label went. Kept apart from the markup so
// that a test can check the labels against the very shapes the thumbnail draws.
//
// Labels are placed by labels::LabelPlacer, clear of each other, the boundary, objects, paths
// and cameras. Cameras come first (their labels carry the most), each by the longest of its
// labels that finds room: "cam 2 · 1 m/s · 0.5 rad/s · 225°" on one line or on two, else
// "cam 2", always within 24 px of its camera (farther, it reads as nobody's); moving objects
// then get their speeds. What finds no room is listed in `leftOut` for the caption.
#include <string>
#include <string_view>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::reports {

inline constexpr const char* kTargetColor = "#b2322d";
inline constexpr const char* kObstacleColor = "#3a3f47";
inline constexpr const char* kPathColor = "#1f6fd1";
inline constexpr const char* kViewColor = "#f5a623";
inline constexpr const char* kCameraColor = "#21262f";

struct DrawnObject {
  std::vector<geometry::Vec2> ring;  // px
  bool isTarget = false;
};

struct DrawnCamera {
  geometry::Vec2 at;                          // px, the body's centre
  geometry::Vec2 head;                        // px, the end of the heading line
  std::vector<geometry::Vec2> wedge;          // px, the field of view (a direction, not a range)
  static constexpr double kBodyRadius = 3.6;  // px
};

struct DrawnLabel {
  std::vector<std::string> lines;  // one, or two for a camera's label where one is too wide
  std::string_view color;
  geometry::Box box;  // px, what the text covers: line i's baseline sits kAscent font sizes
                      // below the top of its own row of lineHeight()
  geometry::Vec2 of;  // px, the point it labels (a camera, an object's centre): the text is
                      // anchored at the box's side nearest it, so a browser's font narrower
                      // than the estimate leaves its spare room away from what it labels

  std::string text() const;  // the lines joined by " · "
};

struct SceneDrawing {
  static constexpr double kFont = 11.0;      // px
  static constexpr double kAscent = 0.8;     // of the font size, above the baseline
  static constexpr double kDescent = 0.25;   // below it
  static constexpr double kDotRadius = 2.2;  // px, a path's start
  static constexpr double lineHeight() { return (kAscent + kDescent) * kFont; }

  double width = 0.0;  // px
  double height = 0.0;
  std::vector<geometry::Vec2> boundary;            // px, a closed line
  std::vector<DrawnObject> objects;                // obstacles, then targets, present at t = 0
  std::vector<std::vector<geometry::Vec2>> paths;  // px, closed loops of moving objects
  std::vector<geometry::Vec2> pathStarts;          // px, one dot per path
  std::vector<DrawnCamera> cameras;
  std::vector<DrawnLabel> labels;
  std::vector<std::string> leftOut;  // "cam 4 · 1 m/s · 0.5 rad/s · 225°", "target 2 · 1 m/s"
};

// The scene at t = 0 in at most about maxSize × maxSize px.
SceneDrawing drawScene(const scene::Scene& scene, double maxSize = 340.0);

// A heading in whole degrees in [0, 360), counter-clockwise from +x: -135° reads 225°.
int headingDegrees(double yaw);

}  // namespace camcov::reports
