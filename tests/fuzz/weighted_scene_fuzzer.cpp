// libFuzzer target: bytes -> a weighted scene -> weighted coverage. The bytes choose a target's
// shape (a jittered polygon), its edge weights (zeros, tiny and huge ones included), its front
// (weight and angle), how it moves, and the cameras' poses; the scene is written as a file's
// JSON and loaded, so the loader's checks come first. An accepted scene must give, at every
// instant tried: importance weights in [0, 1], weighted coverage finite and in [0, 1], the
// probes' incremental terms equal to evaluate()'s to the bit, and with every weight scaled by
// the same factor, the same weighted coverage (it is a ratio) up to the sums' rounding.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "kinematics/kinematics.h"
#include "reward/reward_model.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"

namespace {

using namespace camcov;

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "weighted scene fuzzer: %s\n", what.c_str());
  std::abort();
}

// The input as a stream of small numbers; past its end, zeros.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  unsigned byte() { return at_ < size_ ? data_[at_++] : 0u; }
  double unit() { return byte() / 255.0; }  // [0, 1]
  // A weight: often a plain one, sometimes 0, tiny, huge or beyond the limit.
  double weight() {
    switch (byte() % 8) {
      case 0:
        return 0.0;
      case 1:
        return 1e-9 * (1 + byte());
      case 2:
        return 1e6;
      case 3:
        return 1e6 * (1.0 + unit());  // refused when above the limit
      case 4:
        return -unit();  // refused when below 0
      default:
        return 0.1 * byte();
    }
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
};

std::string sceneText(Bytes& in) {
  const int n = 3 + static_cast<int>(in.byte() % 14);
  std::string shape = "POLYGON((";
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n, r = 0.2 + 1.8 * in.unit();
    shape += fmt::format("{}{} {}", i ? "," : "", r * std::cos(a), r * std::sin(a));
  }
  shape += "))";
  std::string keys;
  if (in.byte() % 4 != 0) {
    keys += ", \"edgeWeights\": [";
    const int count = in.byte() % 16 == 0 ? n - 1 : n;  // sometimes the wrong count
    for (int i = 0; i < count; ++i)
      keys += fmt::format("{}{}", i ? "," : "", in.weight());
    keys += "]";
  }
  if (in.byte() % 2 != 0) {
    keys += fmt::format(", \"frontWeight\": {}", in.weight());
    if (in.byte() % 2 != 0) keys += fmt::format(", \"frontAngle\": {}", 200.0 * in.unit());
  }
  const char* paths[] = {"\"path\": \"POINT(0 0)\"",
                         "\"path\": \"LINESTRING(-5 0,5 1)\", \"velocity\": 1.3",
                         ("\"path\": \"POLYGON((-4 -4,4 -4,4 4,-4 4))\", \"velocity\": 2, "
                          "\"angularVelocity\": 0.7")};
  const std::string path = paths[in.byte() % 3];
  std::string cameras;
  const int m = 1 + static_cast<int>(in.byte() % 4);
  for (int j = 0; j < m; ++j) {
    cameras += fmt::format(
        "{}{{\"pos\": \"POINT({} {})\", \"angle\": {}, \"maxVelocity\": 1, "
        "\"maxAngularVelocity\": 1}}",
        j ? "," : "", -9.0 + 18.0 * in.unit(), -9.0 + 18.0 * in.unit(), 360.0 * in.unit());
  }
  return fmt::format(
      R"j({{"boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))", "cameraFoV": {},
      "targets": [{{"shape": "{}", {}{}}}], "cameras": [{}]}})j",
      5.0 + 80.0 * in.unit(), shape, path, keys, cameras);
}

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void exercise(const scene::Scene& s) {
  const kinematics::Kinematics kinematics(s);
  std::vector<geometry::Pose> cameras;
  for (const auto& c : s.cameras)
    cameras.push_back(c.initial);
  reward::RewardModel afresh(params::RewardParams{}, scene::lenses(s));
  reward::RewardModel probing(params::RewardParams{}, scene::lenses(s));
  for (const double t : {0.0, 0.3, 2.0, 7.3, 40.0}) {
    kinematics::World world = kinematics.worldAt(t);
    double largest = 0.0;
    for (const auto& weights : world.targetEdgeWeights) {
      for (const double w : weights) {
        if (!(w >= 0.0 && w <= 1.0)) fail(fmt::format("weight {} outside [0, 1] at t = {}", w, t));
        largest = std::max(largest, w);
      }
    }
    if (!world.targetEdgeWeights.empty() && largest != 1.0 && largest != 0.0)
      fail(fmt::format("the largest weight at t = {} is {}, not 1", t, largest));
    afresh.setWorld(world);
    probing.setWorld(world);
    const reward::RewardTerms a = afresh.evaluate(cameras), b = probing.terms(cameras);
    if (!(a.weightedCoverage >= 0.0 && a.weightedCoverage <= 1.0 + 1e-12))
      fail(fmt::format("weighted coverage {} at t = {}", a.weightedCoverage, t));
    if (!sameBits(a.weightedCoverage, b.weightedCoverage) || !sameBits(a.reward, b.reward))
      fail(fmt::format("probe {} != evaluate {} at t = {}", b.weightedCoverage, a.weightedCoverage,
                       t));
    // Halved weights: the same ratio, to rounding.
    for (auto& weights : world.targetEdgeWeights) {
      for (double& w : weights)
        w *= 0.5;
    }
    afresh.setWorld(world);
    const double halved = afresh.evaluate(cameras).weightedCoverage;
    if (std::abs(halved - a.weightedCoverage) > 1e-12)
      fail(fmt::format("halving every weight moved weighted coverage {} to {}", a.weightedCoverage,
                       halved));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const std::string text = sceneText(in);
  scene::Scene s;
  try {
    s = scene::parseScene(text, "fuzz.json");
  } catch (const InputError&) {
    return 0;  // refused with a message
  }
  if (!s.isWeighted() && text.find("Weight") != std::string::npos) fail("weights lost on load");
  exercise(s);
  return 0;
}
