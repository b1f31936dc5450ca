#pragma once
// The videos of a batch: the chosen runs (results/video_choice.h) replayed into
// <results>/videos/<run stem>.mp4 for the report to embed.
#include <span>

#include "bench/output_batch.h"
#include "records/batch_folder.h"
#include "records/video_choice.h"

namespace camcov::bench {

// Writes the missing or outdated videos on `workers` threads. A video that cannot be made
// (its scene file has moved, say) is reported and skipped: the runs are the results, a video
// only shows one.
// Progress goes to `observer` as a stretch of its own.
OutputBatch writeBenchVideos(const records::BatchFolder& folder,
                             std::span<const records::VideoRun> runs, unsigned workers,
                             BenchObserver& observer);

}  // namespace camcov::bench
