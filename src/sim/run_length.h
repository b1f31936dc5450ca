#pragma once
// How long a run of a scene lasts (SPEC section 3's run length): the parameters' sim.duration,
// unless the scene brings its own duration (an imported recording's window: nothing is
// recorded past it) and the caller did not ask for one: `durationGiven` (`--duration`), or a
// sim.duration other than the default 30 s (`--set`, a parameter file, Python's params). One
// rule for `camcov run`, the batch, and Python's runs and environments.
//
// A run's record holds every step (every camera's pose and goal: about 3 KB a step for five
// cameras, 12 KB for 30) and its explorer page draws every one, in memory before they reach a
// file. So a run has more than 0 s and at most kMaxSteps steps: 100,000, 2.8 hours at the
// default dt = 0.1 s, about 300 MB of record for five cameras; longer is refused (InputError)
// before anything runs, rather than exhausting the machine's memory and disk.
#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "params/parameters.h"
#include "util/input_error.h"
#include "util/readable_number.h"

namespace camcov::sim {

inline constexpr double kMaxSteps = 100000;

inline params::Parameters withRunLength(params::Parameters p, std::optional<double> sceneDuration,
                                        bool durationGiven) {
  if (sceneDuration && !durationGiven && p.sim.duration == params::Parameters{}.sim.duration)
    p.sim.duration = *sceneDuration;
  // The simulator's count of steps; judged and shown as that whole number, so a message never
  // shows a count on the limit as beyond it.
  const double steps = std::round(p.sim.duration / p.sim.dt);
  if (!(steps >= 1)) {
    throw InputError(
        fmt::format("a run of {} s is shorter than one step of dt = {} s: it would "
                    "average nothing (--duration, sim.duration)",
                    p.sim.duration, p.sim.dt));
  }
  if (steps > kMaxSteps) {
    throw InputError(fmt::format(
        "a run of {} s at dt = {} s would record {} steps; at most {} are recorded (every "
        "camera's pose at each step is kept in memory): shorten the run or lengthen dt",
        readableNumber(p.sim.duration), readableNumber(p.sim.dt), readableNumber(steps),
        readableNumber(kMaxSteps)));
  }
  return p;
}

}  // namespace camcov::sim
