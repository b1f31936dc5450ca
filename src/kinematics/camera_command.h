#pragma once
// What moves a camera: its velocity u_j = ṗ_j (paper section II, dynamics ṗ_j = u_j).
// Controllers produce it, the plan executor computes it, the safety layer and the simulator
// consume it; it lives here, below all of them.
#include "geometry/vec2.h"

namespace camcov::kinematics {

struct CameraCommand {
  geometry::Vec2 velocity;       // [ẋ, ẏ], m/s (saturated by the simulator to v_max)
  double angularVelocity = 0.0;  // γ̇, rad/s (saturated to γ̇_max)
};

}  // namespace camcov::kinematics
