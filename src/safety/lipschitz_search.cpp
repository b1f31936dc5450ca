#include "safety/lipschitz_search.h"

#include <algorithm>
#include <vector>

namespace camcov::safety {
namespace {

struct Interval {
  double a, b, fa, fb;
  int depth;
};

// Deep enough that a 0.1 s step is resolved to 1e-16 s: a bound on work, never reached
// when the tolerance is sane.
constexpr int kMaxDepth = 60;

// One branch and bound; `withFloor`: intervals are bounded below by the floor too.
double searchMinimum(const Sampled& g, double tolerance, double ceiling, int maxSamples,
                     bool withFloor, bool& exhausted) {
  auto lowerBound = [&](const Interval& i) {
    const double slope = 0.5 * (i.fa + i.fb - g.lipschitz * (i.b - i.a));
    return withFloor ? std::max(slope, g.floor(i.a, i.b)) : slope;
  };
  double best = std::min(g.f0, g.f1);
  std::vector<Interval> stack{{0.0, g.h, g.f0, g.f1, 0}};
  for (int samples = 0; !stack.empty(); ++samples) {
    if (samples == maxSamples) {
      // Out of budget (a slope so steep that only ever finer intervals could decide): what
      // is left can be no lower than its intervals' lower bounds, so the answer stays a
      // lower bound of the minimum.
      for (const Interval& i : stack)
        best = std::min(best, lowerBound(i));
      exhausted = true;
      return best;
    }
    const Interval i = stack.back();
    stack.pop_back();
    // Nothing here can beat the best by more than the tolerance, or reach below the ceiling.
    if (lowerBound(i) >= std::min(best - tolerance, ceiling) || i.depth >= kMaxDepth) continue;
    const double m = 0.5 * (i.a + i.b);
    const double fm = g.f(m);
    best = std::min(best, fm);
    stack.push_back({m, i.b, fm, i.fb, i.depth + 1});
    stack.push_back({i.a, m, i.fa, fm, i.depth + 1});
  }
  exhausted = false;
  return best;
}

}  // namespace

double lipschitzMinimum(const Sampled& g, double tolerance, double ceiling, int maxSamples) {
  bool exhausted = false;
  const double slopeOnly = searchMinimum(g, tolerance, ceiling, maxSamples, false, exhausted);
  if (!exhausted || !g.floor) return slopeOnly;
  return searchMinimum(g, tolerance, ceiling, maxSamples, true, exhausted);
}

double firstBelow(const Sampled& g, double level, int depth) {
  // Left-first: the left half of an interval is searched before its right half.
  std::vector<Interval> stack{{0.0, g.h, g.f0, g.f1, 0}};
  while (!stack.empty()) {
    const Interval i = stack.back();
    stack.pop_back();
    if (i.fa < level) return i.a;
    if (0.5 * (i.fa + i.fb - g.lipschitz * (i.b - i.a)) >= level) continue;
    if (i.depth >= depth) return i.a;  // undecided at the finest width: counted as below
    const double m = 0.5 * (i.a + i.b);
    const double fm = g.f(m);
    stack.push_back({m, i.b, fm, i.fb, i.depth + 1});
    stack.push_back({i.a, m, i.fa, fm, i.depth + 1});
  }
  return -1.0;
}

double timeBelow(const Sampled& g, double level, int depth) {
  double total = 0.0;
  std::vector<Interval> stack{{0.0, g.h, g.f0, g.f1, 0}};
  while (!stack.empty()) {
    const Interval i = stack.back();
    stack.pop_back();
    const double width = i.b - i.a;
    const double spread = 0.5 * g.lipschitz * width;
    const double mean = 0.5 * (i.fa + i.fb);
    if (mean - spread >= level) continue;  // proven at or above the level throughout
    if (mean + spread < level || i.depth >= depth) {
      total += width;  // proven below throughout, or undecided at the finest width
      continue;
    }
    const double m = 0.5 * (i.a + i.b);
    const double fm = g.f(m);
    stack.push_back({i.a, m, i.fa, fm, i.depth + 1});
    stack.push_back({m, i.b, fm, i.fb, i.depth + 1});
  }
  return total;
}

}  // namespace camcov::safety
