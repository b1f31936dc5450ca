#pragma once
// The run explorer pages of a batch: per scene one page, <results>/explore/<scene>.html, that
// replays the chosen run of every method side by side (records/video_choice.h picks them as it
// picks the videos: by default the median seed), for the report to link.
#include <span>

#include "bench/output_batch.h"
#include "records/batch_folder.h"
#include "records/video_choice.h"

namespace camcov::bench {

// Writes one page per scene of `runs`. A page that cannot be made (its scene file has moved,
// say) is reported and skipped: the runs are the results, a page only shows them.
OutputBatch writeBenchExplorers(const records::BatchFolder& folder,
                                std::span<const records::VideoRun> runs, BenchObserver& observer);

}  // namespace camcov::bench
