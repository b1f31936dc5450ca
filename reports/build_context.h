#pragma once
// The only things in a report that the results folder does not determine: when and where the
// report was built. Kept apart so everything else is a pure function of the folder (and tests
// can pass a fixed context to compare bytes).
#include <string>

namespace camcov::reports {

struct BuildContext {
  std::string date;  // UTC, "2025-01-31 14:05 UTC"
  std::string hostname;
  std::string cpuModel;  // "model name" of /proc/cpuinfo, empty if unknown
  unsigned cores = 0;    // hardware threads
};

BuildContext currentBuildContext();
// "host — CPU model, N hardware threads", for a report's header.
std::string machineDescription(const BuildContext& context);

}  // namespace camcov::reports
