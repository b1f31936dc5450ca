#pragma once
// How long a run of a scene lasts (SPEC section 3's run length): the parameters' sim.duration,
// unless the scene brings its own duration (an imported recording's window: nothing is
// recorded past it) and the caller did not ask for one: `durationGiven` (`--duration`), or a
// sim.duration other than the default 30 s (`--set`, a parameter file, Python's params). One
// rule for `camcov run`, the batch, and Python's runs and environments.
#include <optional>

#include "params/parameters.h"

namespace camcov::sim {

inline params::Parameters withRunLength(params::Parameters p, std::optional<double> sceneDuration,
                                        bool durationGiven) {
  if (sceneDuration && !durationGiven && p.sim.duration == params::Parameters{}.sim.duration)
    p.sim.duration = *sceneDuration;
  return p;
}

}  // namespace camcov::sim
