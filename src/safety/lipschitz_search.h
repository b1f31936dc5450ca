#pragma once
// Certified searches over one time interval [0, h] for a function f whose slope never exceeds
// L in size (a Lipschitz constant): between two samples f(a), f(b) it stays within
// [(f(a) + f(b) − L·(b − a))/2, (f(a) + f(b) + L·(b − a))/2], so branch and bound can prove
// where f is not, without a grid fine enough to hope. (Piyavskii, "An algorithm for finding
// the absolute extremum of a function", USSR Comput. Math. 1972, in its simplest form.)
#include <functional>
#include <limits>

namespace camcov::safety {

struct Sampled {
  std::function<double(double)> f;  // at τ ∈ [0, h]
  double h = 0.0;
  double f0 = 0.0, f1 = 0.0;  // f(0), f(h), already known to the caller
  double lipschitz = 0.0;     // L ≥ |f'|
  // Optional: a lower bound of f on [a, b] known otherwise than from the slope (the
  // geometry of the motion), for functions whose L says little about how far they vary: a
  // distance to an object spinning at 2,000 rad/s changes fast but stays within its reach.
  std::function<double(double a, double b)> floor;
};

// The smallest value f takes on [0, h], as a value f attains within `tolerance` of the true
// minimum. Intervals that cannot go below `ceiling` are not searched: with a finite ceiling
// the result is exact only where it is below it. The work is bounded whatever L is: where the
// search runs out of `maxSamples`, it searches again with the floor as well (a fresh budget),
// pruning what neither bound lets fall below the best; out of that too, the result is a lower
// bound of the minimum instead (it may then be below zero for a distance). The floor is left
// out of the first search so that a search that never needed it samples as it always did.
// The most samples one minimum search takes by default: a step of a run needs a few hundred
// at most; an object turning at 1e9 rad/s would need about L·h / tolerance of them without a
// floor.
inline constexpr int kMaxMinimumSamples = 1 << 16;
double lipschitzMinimum(const Sampled& g, double tolerance,
                        double ceiling = std::numeric_limits<double>::infinity(),
                        int maxSamples = kMaxMinimumSamples);

// The earliest τ with f(τ) < level, or −1 when f is proven ≥ level on all of [0, h]. An
// interval still undecided at width h / 2^depth counts as below, as in timeBelow, so the
// answer may come a few such widths early where f is flatter than L, never late.
double firstBelow(const Sampled& g, double level, int depth);

// Measure of {τ ∈ [0, h] : f(τ) < level}, proven to within intervals of h / 2^depth: an
// interval still undecided at that width is counted whole, so the result never undercounts.
double timeBelow(const Sampled& g, double level, int depth = 12);

}  // namespace camcov::safety
