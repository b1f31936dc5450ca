#pragma once
// The options `camcov bench` and `camcov merge` share: what is made after the runs
// (bench/finish_bench.h owns their meaning and defaults).
#include <CLI/CLI.hpp>

#include "bench/finish_bench.h"

namespace camcov::cli {

void addBenchOutputOptions(CLI::App& cmd, bench::BenchOutputOptions& options);

}  // namespace camcov::cli
