#pragma once
// The learned method's policy: one small MLP whose parameters all cameras share, trained by
// scripts/train_learned.py and embedded at build time from src/control/learned_policy.json
// (no file is read at run time). It maps one camera's observation — the encoding the learning
// environments give an agent (observation_encoding.h), normalized by the training's running
// mean and deviation — to the mean of its action: vx, vy and yaw rate over the camera's limits.
#include <array>
#include <span>
#include <string_view>
#include <vector>

#include "control/observation_encoding.h"

namespace camcov::control {

class LearnedPolicy {
 public:
  // Reads the policy from its JSON text (the format train_learned.py writes);
  // std::invalid_argument for a text that is not one.
  explicit LearnedPolicy(std::string_view json);
  // The policy built into this program.
  static const LearnedPolicy& builtIn();

  // What each observation holds: the view, the target slots and the padding it was trained on.
  const EncodingSizes& sizes() const { return sizes_; }
  View view() const { return view_; }

  // The action's mean for one observation (sizes().size() floats), clipped to [-1, 1].
  std::array<double, 3> act(std::span<const float> observation) const;

 private:
  struct Layer {
    std::size_t inputs = 0;
    std::vector<double> weights;  // row-major, outputs × inputs
    std::vector<double> bias;
  };
  EncodingSizes sizes_;
  View view_ = View::own;
  std::vector<double> mean_, deviation_;  // the observation's normalization
  double clip_ = 10.0;                    // normalized values are clipped to ±clip_
  std::vector<Layer> layers_;             // tanh between them, the last linear
};

}  // namespace camcov::control
