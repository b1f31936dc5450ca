#pragma once
// Large synthetic scenes, seeded, for measuring how camcov scales: N targets, each
// a V-gon on its own short loop, and M cameras, at random places in a rectangular field. The
// result is a scene file's content in the published format (SPEC section 2), so it goes
// through the loader like any other file. Decisions:
//  - a target's shape is a V-gon inscribed in an ellipse, stretched so that its bounding box
//    is exactly targetLength × targetWidth about its reference point (V = 4: the axis-aligned
//    rectangle), the same for every target;
//  - a target's loop is a square of side loopSize about a random centre at a random
//    orientation, run counter-clockwise at targetSpeed, without rotating the shape; its
//    region, the disc about the loop's centre that holds every place the shape reaches, lies
//    `clearance` inside the field and overlaps no other target's region: targets never pass
//    through each other;
//  - cameras stand at random positions at least `clearance` from every target region, from
//    the boundary and from each other, at a random yaw;
//  - placement is rejection sampling, at most 1,000 tries per target and per camera: a field
//    too crowded to hold them is an InputError saying so, never a hang;
//  - targets and cameras draw from their own streams forked from the seed, so the same seed
//    with another number of cameras keeps the same targets;
//  - positions and loops are kept to the millimetre, shapes to the micrometre and yaws to
//    0.01°: the files stay readable and last-bit differences between maths libraries vanish.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace camcov::scene {

struct GeneratorOptions {
  int targets = 10;                // N, 1 to 10,000 (a scene needs a target)
  int cameras = 4;                 // M, 1 to kMaxCameras
  int vertices = 4;                // V per target, 3 to 100,000; 4 gives rectangles
  double fieldWidth = 30.0;        // m along x; the boundary is this rectangle centred at 0
  double fieldHeight = 30.0;       // m along y (the published scenes: 30 × 30)
  double targetLength = 1.0;       // m, the shape's bounding box along x, > 0
  double targetWidth = 1.0;        // m, along y, > 0
  double loopSize = 2.0;           // m, side of each target's square loop, >= 0; 0: static
  double targetSpeed = 1.0;        // m/s along the loop, > 0
  double cameraSpeed = 2.0;        // v_max, m/s, > 0 (the published scenes' value)
  double cameraTurnRate = 1.0;     // γ̇_max, rad/s, > 0 (the published scenes' value)
  double cameraHalfFovDeg = 30.0;  // θ, degrees, in (0, 180) (the published scenes' value)
  double clearance = 1.0;          // m, >= 0: cameras from targets, boundary and each other
  std::uint64_t seed = 1;
  std::string description;  // the scene's description; empty: one saying what was generated
};

// The scene file's content; the same options give the same JSON, to the byte. InputError for
// an option out of range, targets too small for their number of vertices (edges under 10 µm),
// or a field too small or too crowded to place every target and camera.
nlohmann::json generateScene(const GeneratorOptions& options);

}  // namespace camcov::scene
