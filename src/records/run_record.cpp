#include "records/run_record.h"

#include <utility>

namespace camcov::records {

void RunRecorder::step(const sim::StepRecord& step) {
  StepRow row;
  row.time = step.time;
  row.terms = step.terms;
  row.resolutionCoverage = step.resolutionCoverage;
  row.minObjectDistance = step.minObjectDistance;
  row.minCameraDistance = step.minCameraDistance;
  row.minObjectDistanceInStep = step.minObjectDistanceInStep;
  row.minCameraDistanceInStep = step.minCameraDistanceInStep;
  row.avoidableContactTime = step.avoidableContactTime;
  row.unavoidableContactTime = step.unavoidableContactTime;
  row.targetsPresent = step.targetsPresent;
  row.cameras.assign(step.cameras.begin(), step.cameras.end());
  row.goals.assign(step.goals.begin(), step.goals.end());
  row.heard.assign(step.heard.begin(), step.heard.end());
  record_.steps.push_back(std::move(row));
  record_.events.insert(record_.events.end(), step.events.begin(), step.events.end());
}

}  // namespace camcov::records
