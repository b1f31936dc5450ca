#pragma once
// One run in memory: what it was (metadata) and what happened (every step, every event).
// The recorder side fills it from the simulator's steps; writers and readers turn it into
// files. Only the simulator's types are used here, never the simulator itself (running a run
// is the batch stage's job: batch/run_job.h), so a reader of results links no algorithm.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "control/controller.h"
#include "params/parameters.h"
#include "sim/simulator.h"

namespace camcov::records {

struct RunMetadata {
  std::string scene;            // scene name (file stem)
  std::string sceneFile;        // as given on the command line
  std::uint64_t sceneHash = 0;  // scene::SceneFile::hash: a changed file is a new job
  std::string method;           // a name in the table of methods (control/methods.h)
  std::uint64_t seed = 0;
  params::Parameters parameters;
  std::string toolVersion;
};

struct StepRow {
  double time = 0.0;
  reward::RewardTerms terms;
  double resolutionCoverage = 0.0;  // sim::StepRecord's: a scene with a resolution only
  double minObjectDistance = 0.0;   // at the sample
  double minCameraDistance = 0.0;
  double minObjectDistanceInStep = 0.0;  // over the step that ended here, continuous time
  double minCameraDistanceInStep = 0.0;
  double avoidableContactTime = 0.0;  // s closer than δ in that step, by the layer's verdict
  double unavoidableContactTime = 0.0;
  int targetsPresent = -1;  // recorded tracks only (scene::Scene::hasPresenceWindows); else −1
  std::vector<geometry::Pose> cameras;
  std::vector<std::optional<geometry::Pose>> goals;
  std::vector<sim::Hearing> heard;  // under limited knowledge: who heard whom at this step
};

struct RunRecord {
  RunMetadata metadata;
  sim::RunSummary summary;
  std::vector<StepRow> steps;
  std::vector<control::ControlEvent> events;
};

// Collects the simulator's steps into a RunRecord.
class RunRecorder final : public sim::Recorder {
 public:
  explicit RunRecorder(RunRecord& record) : record_(record) {}
  void step(const sim::StepRecord& step) override;

 private:
  RunRecord& record_;
};

}  // namespace camcov::records
