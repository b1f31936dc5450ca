#pragma once
// A parameter study written as --set: an assignment whose value is a list, KEY=V1,V2,..., is
// swept (no parameter's value holds a comma). The settings are the product of the lists, the
// first swept key varying slowest, numbered as scripts/slurm_sweep.sh numbers them, and each is
// named KEY=V_KEY=V by its swept keys only, the folder `camcov bench` writes it to (the name the
// Slurm script gives it, so the two make the same study).
#include <cstddef>
#include <string>
#include <vector>

namespace camcov::params {

struct SweepSetting {
  std::vector<std::string> assignments;  // every --set, in the order given, one value each
  std::string name;                      // "comms.range=10"; empty where nothing is swept
};

// The most settings one study may have: each is a whole batch.
inline constexpr std::size_t kMaxSweepSettings = 1000;

// One setting (named "") when no value lists several. InputError for an empty value in a list
// ("k=5,,10", "k=5,"), a key swept twice or swept and also set alone, or more than
// kMaxSweepSettings settings. Assignments are otherwise passed on as given (applyAssignment
// checks keys and values).
std::vector<SweepSetting> expandSweep(const std::vector<std::string>& assignments);

}  // namespace camcov::params
