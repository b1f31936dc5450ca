#pragma once
// A batch before it runs (SPEC section 7): the scene files, read and validated up front (a
// typo fails in a second, not after an hour) and only once (a job runs the plan's reading
// while the file is unchanged: batch/run_job.h), the jobs (scene × method × seed, scenes in
// natural order), this shard's share of them, and the folder's check that it holds no
// results made with other parameters.
#include <cstdint>
#include <string>
#include <vector>

#include "batch/batch_runner.h"
#include "records/batch_folder.h"

namespace camcov::batch {

// Limits that keep a batch's plan within memory: seeds per scene and method, and jobs in all
// (a million jobs are days of runs; their plan is about a gigabyte).
inline constexpr std::uint64_t kMaxSeeds = 100000;
inline constexpr std::uint64_t kMaxJobs = 1000000;

// Part `index` (0-based) of `count`: the jobs i with i mod count == index.
struct Shard {
  std::size_t index = 0;
  std::size_t count = 1;
};
// "K/N", 1-based as users write it; "" is the whole batch. InputError otherwise.
Shard parseShard(const std::string& text);

struct BatchRequest {
  std::vector<std::string> scenes;   // scene files, or folders (their *.json, natural order)
  std::vector<std::string> methods;  // names in the table of methods or in extraMethods
  std::uint64_t seeds = 1;           // 1..seeds per scene and method
  params::Parameters parameters;
  Shard shard;
  std::vector<std::string> command;  // how it was asked for, for batch.json
  // Methods the caller brings for this batch (Python's controllers), found before the table's;
  // they must outlive the batch's run.
  std::span<const control::Method> extraMethods;
  // The caller set sim.duration (`--duration`): it holds for every scene. Otherwise a scene
  // with a duration of its own runs for that long (sim/run_length.h).
  bool durationGiven = false;
};

struct BatchPlan {
  records::BatchManifest manifest;
  std::vector<BatchJob> jobs;  // this shard's, in batch order
  std::size_t totalJobs = 0;   // of all shards
};

// InputError for no, unknown or repeated methods, seeds outside 1..kMaxSeeds, more than
// kMaxJobs jobs, missing or invalid scene files.
BatchPlan planBatch(const BatchRequest& request, const std::string& toolVersion);

// The methods of `now` whose results in a folder of `previous` were made by other code (or by
// code whose identity was not recorded).
std::vector<std::string> methodsMadeByOtherCode(const records::BatchManifest& previous,
                                                const records::BatchManifest& now);

// Gets `folder` ready for `plan`: refuses (InputError) a folder whose results were made with
// other parameters or by other code of a method unless `force` (which removes that method's
// results, to run them again), removes what a killed run left half-written, and writes the
// manifest (keeping the identities of methods the folder holds and this batch leaves alone).
void prepareFolder(const records::BatchFolder& folder, records::BatchManifest& manifest,
                   bool force);

}  // namespace camcov::batch
