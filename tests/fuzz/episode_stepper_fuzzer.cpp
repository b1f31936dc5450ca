// libFuzzer target: bytes -> episodes of the test scenes stepped by an EpisodeStepper, as
// camcov.env's vector environment steps them. The bytes choose the episodes (scene, length),
// the stepper's threads, each step's commands (NaN, infinities and huge values among them),
// the stride, the encoding's sizes (sometimes too small) and sometimes an episode given twice.
// Every call must either step or refuse with std::invalid_argument (bad arrays, an episode
// twice: then no episode moved) or std::logic_error (a finished episode: the others still
// step); the observations must be finite; and the threads must give what one thread gives, to
// the bit, on twin episodes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "environment/episode.h"
#include "environment/episode_batch.h"
#include "environment/observation_encoding.h"
#include "scene/scene_loader.h"

namespace {

using namespace camcov;

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "episode stepper fuzzer: %s\n", what.c_str());
  std::abort();
}

// The input as a stream of small numbers; past its end, zeros.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  unsigned byte() { return at_ < size_ ? data_[at_++] : 0u; }
  bool done() const { return at_ >= size_; }
  // A command component: mostly ordinary, sometimes not finite or far beyond any limit.
  double component() {
    switch (byte() % 8) {
      case 0:
        return std::numeric_limits<double>::quiet_NaN();
      case 1:
        return byte() % 2 ? std::numeric_limits<double>::infinity()
                          : -std::numeric_limits<double>::infinity();
      case 2:
        return byte() % 2 ? 1e300 : -1e300;
      default:
        return (static_cast<double>(byte()) - 127.5) / 25.0;
    }
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
};

const std::vector<std::shared_ptr<const scene::Scene>>& scenes() {
  static const auto loaded = [] {
    std::vector<std::shared_ptr<const scene::Scene>> out;
    for (const char* name : {"tiny_dynamic.json", "tiny_static.json"})
      out.push_back(std::make_shared<const scene::Scene>(
          scene::loadScene(std::string(CAMCOV_TEST_SCENES) + "/" + name)));
    return out;
  }();
  return loaded;
}

// Twin sets of episodes: `threaded` stepped by the fuzzed stepper, `alone` by one thread.
struct Twins {
  std::vector<std::unique_ptr<environment::Episode>> threaded, alone;
  std::vector<environment::Episode*> pointers(bool threads) const {
    std::vector<environment::Episode*> out;
    for (const auto& e : threads ? threaded : alone)
      out.push_back(e.get());
    return out;
  }
};

// One call on both sets; returns false once every call would refuse a finished episode.
bool stepBoth(Bytes& in, Twins& twins, environment::EpisodeStepper& stepper,
              environment::EpisodeStepper& single, const environment::EncodingSizes& fits,
              std::size_t maxCameras) {
  std::vector<environment::Episode*> threaded = twins.pointers(true), alone = twins.pointers(false);
  const bool twice = in.byte() % 16 == 0 && threaded.size() > 1;
  if (twice) threaded.back() = threaded.front();  // the same episode at two positions
  const std::size_t n = threaded.size();
  std::size_t stride = maxCameras + in.byte() % 2;
  if (in.byte() % 32 == 0) --stride;  // sometimes too narrow for the widest team
  environment::EncodingSizes sizes = fits;
  if (in.byte() % 32 == 0) sizes.vertices = fits.vertices - 1;  // too small for the scenes
  std::vector<scene::CameraCommand> commands(n * stride);
  for (auto& u : commands)
    u = {{in.component(), in.component()}, in.component()};
  std::vector<float> observations[2] = {std::vector<float>(n * sizes.size()),
                                        std::vector<float>(n * sizes.size())};
  std::vector<reward::RewardTerms> terms[2] = {std::vector<reward::RewardTerms>(n),
                                               std::vector<reward::RewardTerms>(n)};
  const auto call = [&](environment::EpisodeStepper& s, std::vector<environment::Episode*>& set,
                        int k) -> int {
    try {
      s.step(set, commands, stride, sizes, observations[k], terms[k]);
      return 0;
    } catch (const std::invalid_argument&) {
      return 1;
    } catch (const std::logic_error&) {
      return 2;
    }
  };
  std::vector<int> before;
  for (const auto* e : threaded)
    before.push_back(e->index());
  const int threadedOutcome = call(stepper, threaded, 0);
  const bool refusable = twice || stride < maxCameras || sizes.vertices < fits.vertices;
  if (threadedOutcome == 1) {
    if (!refusable) fail("a well-formed call was refused as invalid");
    for (std::size_t i = 0; i < n; ++i)
      if (threaded[i]->index() != before[i]) fail("a refused call moved an episode");
    return true;  // the twins did not move: nothing to compare
  }
  if (refusable) fail("a call with an episode twice or too small arrays was served");
  const int aloneOutcome = call(single, alone, 1);
  if (aloneOutcome != threadedOutcome) fail("threads and one thread ended the call differently");
  for (std::size_t i = 0; i < n; ++i) {
    if (twins.threaded[i]->index() != twins.alone[i]->index())
      fail("threads and one thread reached different instants");
  }
  if (threadedOutcome == 2) return false;
  if (std::memcmp(observations[0].data(), observations[1].data(),
                  observations[0].size() * sizeof(float)) != 0)
    fail("threads and one thread encoded different observations");
  for (const float v : observations[0])
    if (!std::isfinite(v)) fail("an observation holds a number that is not finite");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(terms[0][i].coverage >= 0.0 && terms[0][i].coverage <= 1.0))
      fail("coverage outside [0, 1]");
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const std::size_t count = 1 + in.byte() % 5;
  Twins twins;
  std::size_t maxCameras = 0;
  environment::EncodingSizes fits{0, 0, 0, 0};
  for (std::size_t i = 0; i < count; ++i) {
    const auto& scene = scenes()[in.byte() % scenes().size()];
    params::Parameters params;
    params.sim.duration = 0.1 * (1 + in.byte() % 8);  // 1 to 8 steps
    twins.threaded.push_back(std::make_unique<environment::Episode>(scene, params));
    twins.alone.push_back(std::make_unique<environment::Episode>(scene, params));
    const environment::EncodingSizes s = environment::EncodingSizes::of(*scene);
    fits = {std::max(fits.cameras, s.cameras), std::max(fits.targets, s.targets),
            std::max(fits.obstacles, s.obstacles), std::max(fits.vertices, s.vertices)};
    maxCameras = std::max(maxCameras, scene->cameras.size());
  }
  environment::EpisodeStepper stepper(1 + in.byte() % 4), single(1);
  for (int call = 0; call < 12 && !in.done(); ++call)
    if (!stepBoth(in, twins, stepper, single, fits, maxCameras)) break;
  return 0;
}
