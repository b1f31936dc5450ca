#include "control/learned_policy.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace camcov::control {

// The text of src/control/learned_policy.json, generated into the build by CMake.
extern const std::string_view kLearnedPolicyJson;

namespace {

std::vector<double> numbers(const nlohmann::json& array, std::size_t size, const char* what) {
  if (!array.is_array() || array.size() != size) {
    throw std::invalid_argument(std::string("learned policy: ") + what + " must hold " +
                                std::to_string(size) + " numbers");
  }
  return array.get<std::vector<double>>();
}

}  // namespace

LearnedPolicy::LearnedPolicy(std::string_view text) {
  const nlohmann::json policy = nlohmann::json::parse(text);
  const nlohmann::json& o = policy.at("observation");
  const auto s = o.at("sizes").get<std::vector<std::size_t>>();
  if (s.size() != 4) throw std::invalid_argument("learned policy: sizes must hold 4 counts");
  const std::string targets = o.at("targets").get<std::string>();
  sizes_ = {s[0], s[1], s[2], s[3],
            targets == "nearest" ? TargetSlots::nearest : TargetSlots::byIndex};
  sizes_.check();
  view_ = viewNamed(o.at("view").get<std::string>());
  mean_ = numbers(o.at("mean"), sizes_.size(), "observation.mean");
  deviation_ = numbers(o.at("std"), sizes_.size(), "observation.std");
  clip_ = o.at("clip").get<double>();
  std::size_t inputs = sizes_.size();
  for (const nlohmann::json& l : policy.at("layers")) {
    const auto& rows = l.at("weight");
    Layer layer{inputs, {}, numbers(l.at("bias"), rows.size(), "a layer's bias")};
    for (const auto& row : rows) {
      const std::vector<double> r = numbers(row, inputs, "a layer's weight row");
      layer.weights.insert(layer.weights.end(), r.begin(), r.end());
    }
    inputs = layer.bias.size();
    layers_.push_back(std::move(layer));
  }
  if (layers_.empty() || inputs != 3)
    throw std::invalid_argument("learned policy: the last layer must give 3 numbers");
}

const LearnedPolicy& LearnedPolicy::builtIn() {
  static const LearnedPolicy policy(kLearnedPolicyJson);
  return policy;
}

std::array<double, 3> LearnedPolicy::act(std::span<const float> observation) const {
  std::vector<double> x(observation.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = std::clamp((observation[i] - mean_[i]) / deviation_[i], -clip_, clip_);
  for (std::size_t k = 0; k < layers_.size(); ++k) {
    const Layer& layer = layers_[k];
    std::vector<double> y(layer.bias);
    for (std::size_t r = 0; r < y.size(); ++r) {
      const double* w = layer.weights.data() + r * layer.inputs;
      for (std::size_t c = 0; c < layer.inputs; ++c)
        y[r] += w[c] * x[c];
      if (k + 1 < layers_.size()) y[r] = std::tanh(y[r]);
    }
    x = std::move(y);
  }
  return {std::clamp(x[0], -1.0, 1.0), std::clamp(x[1], -1.0, 1.0), std::clamp(x[2], -1.0, 1.0)};
}

}  // namespace camcov::control
