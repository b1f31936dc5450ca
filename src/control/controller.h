#pragma once
// The controller side of the simulation loop (SPEC section 3): at each step it sees only the
// present — the world now and the cameras' poses now — and answers with camera velocities
// u_j = ṗ_j (paper section II). The simulator saturates and integrates them.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "reward/metrics.h"
#include "reward/reward_model.h"
#include "scene/camera.h"
#include "visibility/segment.h"

namespace camcov::control {

// What a camera knows of a teammate under limited knowledge: the latest news of it, from its own
// message or passed on by another camera: where it was at `sentAt` and the goal it was heading
// for then, if any.
struct HeardTeammate {
  double sentAt = 0.0;  // s
  geometry::Pose pose;
  std::optional<geometry::Pose> goal;
};

// What one camera knows on its own under limited knowledge (docs/method.md, "What a camera
// knows"): the world as it saw it or was told, and its teammates as last heard.
struct OwnKnowledge {
  kinematics::World world;
  // By camera index; none for itself and for teammates it never heard.
  std::vector<std::optional<HeardTeammate>> teammates;
};

// What a method sees at step t. Its cameras' limits and fields of view are the scene's
// (scene::CameraSpec), given when the controller is made (methods.h), with the parameters and
// the seed of its own random generator.
struct Observation {
  double time = 0.0;  // t, s
  const kinematics::World& world;
  std::span<const geometry::Pose> cameras;
  // S(t) for `cameras` (eq. (1): every target edge, split where visibility changes, with
  // visibleBy) and the reward's terms, as the simulator measured them at t: shared so that
  // a method need not sweep again to know what is seen now. Empty where nobody measured.
  std::span<const visibility::Segment> seen = {};
  reward::RewardTerms terms = {};
  // The simulator's own model at t, which measured `seen`: a method's RewardModel takes its
  // instant from it (RewardModel::setInstant) instead of building the occluders again, and
  // keeps its sweeps. Null where nobody measured.
  const reward::RewardModel* measured = nullptr;
  // Under limited knowledge, what each camera knows on its own, by camera index, for a
  // decentralized method (`world` is the union of these worlds). Empty with full knowledge:
  // there every camera's own world is `world` and it knows its teammates' poses as they are.
  std::span<const OwnKnowledge> own = {};
};

// Sets `model` to the observation's instant: the simulator's, shared, where it measured; else
// made from the world.
inline void takeInstant(reward::RewardModel& model, const Observation& observation) {
  if (observation.measured != nullptr) {
    model.setInstant(*observation.measured);
  } else {
    model.setWorld(observation.world);
  }
}

// Something worth a line in the results. The kinds the simulator and the built-in methods
// raise, their names and which get marks, are control::EventKind (event_kind.h); a method of
// one's own may name kinds of its own.
struct ControlEvent {
  double time = 0.0;
  std::string kind;
  int camera = -1;                   // -1: the whole team
  std::string detail;                // human-readable
  std::vector<geometry::Pose> path;  // the planned path, for "plan" events
  // Machine-readable, for programs (the report) to act on instead of parsing `detail`: a
  // global optimization's decision (kDecisionReplan, …), a contact's cause
  // ("outpaced", "cornered", "within-delta"); empty where the kind says all.
  std::string reason;
};

class Controller {
 public:
  virtual ~Controller() = default;
  // Fills one command per camera.
  virtual void control(const Observation& observation,
                       std::span<scene::CameraCommand> commands) = 0;
  // The goal camera j is heading for, if it follows a plan (drawn in frames).
  virtual std::optional<geometry::Pose> goal(std::size_t camera) const = 0;
  // Moves the events since the last call into `out`.
  virtual void takeEvents(std::vector<ControlEvent>& out) = 0;
};

}  // namespace camcov::control
