#pragma once
// The videos of a batch: the chosen runs (results/video_choice.h) replayed into
// <results>/videos/<run stem>.mp4 for the report to embed.
#include <span>

#include "records/batch_folder.h"
#include "records/video_choice.h"

namespace camcov::cli {

struct VideoBatch {
  std::size_t written = 0;
  std::size_t upToDate = 0;  // already there and newer than their run
  std::size_t failed = 0;    // each one explained on stderr
};

// Writes the missing or outdated videos on `workers` threads. A video that cannot be made
// (its scene file has moved, say) is reported and skipped: the runs are the results, a video
// only shows one.
VideoBatch writeBenchVideos(const records::BatchFolder& folder,
                            std::span<const records::VideoRun> runs, unsigned workers);

}  // namespace camcov::cli
