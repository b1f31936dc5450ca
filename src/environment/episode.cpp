#include "environment/episode.h"

#include <stdexcept>

namespace camcov::environment {
namespace {

// An episode keeps no records: its caller reads each instant as it comes.
class NoRecords final : public sim::Recorder {
 public:
  void step(const sim::StepRecord&) override {}
};

}  // namespace

Episode::Episode(std::shared_ptr<const scene::Scene> scene, const params::Parameters& params)
    : scene_(std::move(scene)),
      params_(params),
      simulation_(std::make_unique<sim::Simulation>(*scene_, params_)),
      noGoals_(scene_->cameras.size()) {}

Episode::~Episode() = default;

void Episode::step(std::span<const scene::CameraCommand> commands) {
  if (finished()) throw std::logic_error("Episode::step: the episode is finished");
  NoRecords none;
  simulation_->command(commands);
  simulation_->advance(noGoals_, none);
}

void Episode::close() {
  if (!simulation_->atLastInstant()) return;
  NoRecords none;
  simulation_->advance(noGoals_, none);
}

sim::RunSummary Episode::summary() const {
  return simulation_->summary();
}

}  // namespace camcov::environment
