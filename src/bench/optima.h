#pragma once
// The offline optimum of every scene of a batch that holds still
// (batch/scene_optimum.h), in <results>/optimum/<scene>.json, for the report to set each
// method's final coverage against it.
#include <cstdint>

#include "bench/output_batch.h"
#include "records/batch_folder.h"

namespace camcov::bench {

// Searches, on `workers` threads, the scenes of `manifest` that hold still and have no
// current optimum file (the same scene, parameters and budget), with `budget` reward evaluations
// each. A scene that cannot be read or searched is reported and skipped: the runs are the results,
// the optimum a reference.
OutputBatch writeBenchOptima(const records::BatchFolder& folder,
                             const records::BatchManifest& manifest, std::int64_t budget,
                             unsigned workers, BenchObserver& observer);

}  // namespace camcov::bench
