#pragma once
// The colours and legend of everything camcov draws of a scene: frames and videos (Cairo),
// the sweep debugger, and the run explorer in the browser (reports/explorer), so a camera, a
// seen edge or a plan looks the same in all of them. Plain data: no Cairo here.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace camcov::viz {

struct Rgb {
  double r, g, b;
};

// Green and red differ in lightness as well as hue, so the two stay apart for readers with
// red-green colour blindness; the views are amber, which clashes with neither nor with blue.
inline constexpr Rgb kPage{0.925, 0.929, 0.937};  // outside the boundary, and the panel
inline constexpr Rgb kFloor{1.0, 1.0, 1.0};       // free space inside the boundary
inline constexpr Rgb kWall{0.42, 0.45, 0.50};
inline constexpr Rgb kObstacle{0.22, 0.24, 0.28};
inline constexpr Rgb kTarget{0.78, 0.79, 0.81};
inline constexpr Rgb kSeen{0.09, 0.60, 0.26};
inline constexpr Rgb kUnseen{0.87, 0.18, 0.16};
// Seen by too few pixels (the scene's resolution): amber, between seen and unseen.
inline constexpr Rgb kUnresolved{0.96, 0.62, 0.07};
inline constexpr Rgb kView{0.96, 0.65, 0.14};
inline constexpr Rgb kCamera{0.13, 0.15, 0.19};
inline constexpr Rgb kPlan{0.15, 0.42, 0.82};
inline constexpr Rgb kText{0.13, 0.15, 0.19};
inline constexpr Rgb kMutedText{0.38, 0.41, 0.46};
inline constexpr Rgb kObjectPath{0.45, 0.48, 0.53};
inline constexpr Rgb kPitchLine{0.74, 0.77, 0.80};  // a football pitch's markings
inline constexpr double kViewAlpha = 0.28;          // views are translucent: overlaps look darker

// The opacity of each view of a team of `cameras`: the palette's up to five, lighter for a
// larger team, so that where every view overlaps the floor still shows through at 17 % (eight
// cameras' views at 28 % each buried a football pitch in amber). Frames and the explorer.
double viewAlphaFor(std::size_t cameras);

// A target edge by how many cameras see it: none red, one green, more in darker greens (the
// frames draw seen and unseen; the explorer tells the counts apart).
Rgb seenByColour(int cameras);
// "#rrggbb", for CSS and SVG.
std::string cssColour(Rgb c);
// The inverse: a scene object's own colour; nullopt for anything but "#rrggbb".
std::optional<Rgb> rgbFromHex(std::string_view hex);

// The legend's entries, in the order the frames list them.
// Importance: a weighted scene's frames only (the width of a target's edges); Unresolved: the
// frames of a scene that asks a resolution only.
enum class Legend {
  Seen,
  Unseen,
  Target,
  Obstacle,
  Camera,
  Plan,
  ObjectPath,
  Importance,
  Unresolved
};
inline constexpr Legend kLegendEntries[] = {Legend::Seen,      Legend::Unseen, Legend::Target,
                                            Legend::Obstacle,  Legend::Camera, Legend::Plan,
                                            Legend::ObjectPath};

// A weighted scene's target edges are drawn as wide as they are important: weight w (in
// [0, 1], World::targetEdgeWeights) times this factor of the plain width, from 0.4 (nothing)
// to 1.6 (the most important). The explorer draws them the same.
inline double importanceWidthFactor(double weight) {
  return 0.4 + 1.2 * weight;
}

constexpr const char* legendText(Legend entry) {
  switch (entry) {
    case Legend::Seen:
      return "target boundary seen";
    case Legend::Unseen:
      return "target boundary unseen";
    case Legend::Target:
      return "target";
    case Legend::Obstacle:
      return "obstacle";
    case Legend::Camera:
      return "camera and what it sees";
    case Legend::Plan:
      return "planned path and goal";
    case Legend::ObjectPath:
      return "object path and speed";
    case Legend::Importance:
      return "wider edge: more important";
    case Legend::Unresolved:
      return "seen, not resolved";
  }
  return "";
}

}  // namespace camcov::viz
