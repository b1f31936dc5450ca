#pragma once
// A whole bench as one stage: plan the jobs, prepare (or resume) the results folder, run the
// jobs on every core, then make what finish_bench.h makes. `camcov bench` and camcov.bench are
// thin callers of runBench, `camcov merge` of mergeBench: one sequence, one set of options
// and defaults, the same lines said to their observers.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "bench/bench_observer.h"
#include "bench/finish_bench.h"
#include "control/methods.h"
#include "params/parameters.h"
#include "records/batch_summary.h"

namespace camcov::bench {

struct BenchRequest {
  std::vector<std::string> scenes{"scenes"};  // scene files, or folders of them
  std::vector<std::string> methods = control::defaultMethods();
  std::uint64_t seeds = 5;  // 1..seeds per scene and method
  double duration = -1.0;   // simulated seconds per run; < 0: the parameters' sim.duration
  params::Parameters parameters;
  std::string shard;  // "K/N": only part K of N of the jobs; empty: all
  unsigned jobs = 0;  // worker threads; 0: every core
  std::string out = "bench-results";
  bool force = false;  // run again jobs made with other parameters or by other code
  BenchOutputOptions outputs;
  std::vector<std::string> command;  // what started the bench, for batch.json and the report
  // Methods the caller brings (Python controllers), beside the table's; they outlive the call.
  std::span<const control::Method> extraMethods;
};

struct BenchResult {
  std::size_t jobs = 0;        // planned in this sitting (a shard: its part)
  std::size_t failedJobs = 0;  // of those
  bool shard = false;          // only a part ran: no summary until `camcov merge`
  records::BatchSummary summary;
};

// InputError (nothing run, and no folder left behind that this call made) for a bad request:
// unknown methods, a bad shard, --videos, --explorer or --reference, a folder made by other
// parameters or code (unless `force`).
BenchResult runBench(const BenchRequest& request, BenchObserver& observer);

// Combines the results folders `inputs` into `out` (it may be one of them), then finishes the
// bench there. A failure leaves no `out` this call made.
BenchResult mergeBench(const std::vector<std::string>& inputs, const std::string& out,
                       const BenchOutputOptions& outputs, const std::vector<std::string>& command,
                       BenchObserver& observer);

}  // namespace camcov::bench
