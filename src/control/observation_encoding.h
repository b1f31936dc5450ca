#pragma once
// A present instant (what a controller observes) as a fixed-size array of floats, for learning
// libraries whose observations have one shape whatever the scene. The layout (docs/python.md
// repeats it):
//
//   [0, 4)              t / duration, and the team's coverage, utilization and reward at t
//                       (eq. (3), (5), (8))
//   per camera slot     10 floats: present, x, y, cos γ, sin γ, then each observed row of
//                       the camera table (scene/camera_keys.h) in its order — v_max / L, γ̇_max,
//                       θ, r / L (0: no sensing range) — then the share of the target boundary
//                       this camera sees (its own coverage term); cameraColumns() names them
//   per target slot     5 + 2·V floats: present, the share of its boundary that is seen, its
//                       centroid x, y, its vertex count / V, then V vertices x, y (zeros past
//                       its count)
//   per obstacle slot   2 + 2·V floats: present, its vertex count / V, V vertices x, y
//
// Positions are in the room's frame: (p − c) / L, c the centre of the boundary's bounding
// box and L half its longer side, so the room spans [−1, 1] along its longer side. With
// TargetSlots::byIndex, slot i of targets is the scene's target i: a recorded person absent
// at t leaves the slot's present flag 0 and the rest zero. With TargetSlots::nearest, the
// slots hold the targets present at t, nearest first (the distance from a target's centroid
// to the nearest camera of the view), as many as fit: a crowd whose people come and go is
// observed in a size of the caller's choosing. Obstacle slot i is the scene's obstacle i.
// Slots beyond what is there are zero. A camera's own view (View::own) keeps its own slot
// first and its teammates after it in their order, shows no obstacle, and only the targets
// it sees some of, with the share it sees; a camera's known view (View::known) keeps the team
// view's layout with its own slot first, of the world as it believes it (View below).
//
// Every float lies within observationBounds(): a value past its field's bound (an object
// more than a half-side outside the room's box, a sensing range longer than the room, a
// repulsion beyond kRewardBound) is clamped to it, so that learning libraries get the finite
// box they expect.
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "control/controller.h"
#include "params/parameters.h"
#include "reward/metrics.h"
#include "scene/camera_keys.h"
#include "scene/scene.h"

namespace camcov::control {

enum class TargetSlots { byIndex, nearest };

// What an encoding pads to: at least the counts of every scene it will encode (targets: any
// number with TargetSlots::nearest, which keeps the nearest that fit).
struct EncodingSizes {
  std::size_t cameras = 0;
  std::size_t targets = 0;
  std::size_t obstacles = 0;
  std::size_t vertices = 0;  // V: of the largest target or obstacle ring
  TargetSlots targetSlots = TargetSlots::byIndex;

  static constexpr std::size_t kGlobal = 4;
  // A camera slot: its flag and pose, the camera table's observed rows, its coverage term.
  static constexpr std::size_t kCameraPoseColumns = 5;
  static constexpr std::size_t kPerCamera =
      kCameraPoseColumns + scene::observedCameraKeyCount() + 1;
  std::size_t perTarget() const { return 5 + 2 * vertices; }
  std::size_t perObstacle() const { return 2 + 2 * vertices; }
  std::size_t size() const {
    return kGlobal + cameras * kPerCamera + targets * perTarget() + obstacles * perObstacle();
  }
  // At most scene::kMaxCameras cameras and kMaxCount of each other count, so that size()
  // cannot overflow: std::invalid_argument naming the count otherwise.
  static constexpr std::size_t kMaxCount = 1000000;
  void check() const;
  // The smallest sizes that hold `scene` at every instant (deformations keep their vertex
  // counts; a recorded person's disc is its shape).
  static EncodingSizes of(const scene::Scene& scene);
};

// Whose instant the floats describe. team: the world the methods read (under limited
// knowledge, what the team knows together) and every camera in its order. own: what one camera
// sees now — its slot first, its teammates after it, no obstacle, only the targets it sees some
// of, with the share it sees. known: what one camera knows — with full knowledge the team view
// with its slot first; under limited knowledge its belief (docs/method.md, "What a camera
// knows"): the world as it saw it or was told, its teammates where it last heard of them
// (team_belief.h), and S and the terms measured in that world, laid out as the team view with
// its slot first.
enum class View { team, own, known };
// The view of a name: "team", "own" or "known"; std::invalid_argument naming them otherwise.
View viewNamed(std::string_view name);

// std::invalid_argument naming the scene's counts unless `sizes` hold `scene` in `view` (the
// own view shows no obstacle, so it needs no obstacle slots and no room for their rings).
void requireFits(const scene::Scene& scene, const EncodingSizes& sizes, View view = View::team);

// The fields' bounds: positions (room frame) within ±kPositionBound, lengths over L (v_max,
// sensing range) within [0, kLengthBound], yaw rates within [0, kRateBound] rad/s, the reward
// within ±kRewardBound; shares, flags, cos and sin, t / duration within their natural ranges.
inline constexpr float kPositionBound = 2.0f;
inline constexpr float kLengthBound = 4.0f;
inline constexpr float kRateBound = 10.0f;
inline constexpr float kRewardBound = 10.0f;

// The names of a camera slot's kPerCamera columns: "present", "x", "y", "cos yaw", "sin yaw",
// the observed camera table keys ("maxVelocity", …), "coverage".
std::vector<std::string> cameraColumns();

// Writes every float's lowest and highest value into `low` and `high` (each sizes.size()).
void observationBounds(const EncodingSizes& sizes, std::span<float> low, std::span<float> high);

// Writes the instant `observation` of a run of `scene` under `params` into `out` (size
// sizes.size()); `camera` is the camera whose view it is for View::own and View::known. One
// encoding for the learning environments (environment::encodeObservation, the episode's
// instant) and for a method that reads it (the learned controller), so both observe the same
// floats.
// std::invalid_argument if the scene does not fit.
void encodeObservation(const scene::Scene& scene, const params::Parameters& params,
                       const Observation& observation, const EncodingSizes& sizes, View view,
                       std::size_t camera, std::span<float> out);

}  // namespace camcov::control
