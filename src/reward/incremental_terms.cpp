#include "reward/incremental_terms.h"

#include <algorithm>

#include "geometry/same_bits.h"
#include "reward/metrics.h"

namespace camcov::reward {

namespace {

// Calls f(edge, lo, hi) for each run of the intervals of `sorted` (by edge, then lo) that
// `keep` keeps: the union of the intervals of one edge that overlap or touch — as S joins its
// consecutive seen pieces.
template <typename Interval, typename EdgeOf, typename Keep, typename F>
void forEachRun(std::span<const Interval> sorted, EdgeOf edgeOf, Keep keep, F&& f) {
  std::size_t i = 0;
  const auto skipLeftOut = [&] {
    while (i < sorted.size() && !keep(sorted[i]))
      ++i;
  };
  for (skipLeftOut(); i < sorted.size();) {
    const auto edge = edgeOf(sorted[i]);
    const double lo = sorted[i].lo;
    double hi = sorted[i].hi;
    for (++i, skipLeftOut(); i < sorted.size() && edgeOf(sorted[i]) == edge && sorted[i].lo <= hi;
         ++i, skipLeftOut())
      hi = std::max(hi, sorted[i].hi);
    f(edge, lo, hi);
  }
}

constexpr auto keepAll = [](const auto&) { return true; };

// A closure, not a function, so that the sorts below inline it.
constexpr auto byEdge = [](const visibility::SeenInterval& a, const visibility::SeenInterval& b) {
  return a.edge != b.edge ? a.edge < b.edge : a.lo < b.lo;
};

// Sorts a sweep's intervals by edge and along it. The sweep reports them counter-clockwise
// around the camera, which along a counter-clockwise ring is mostly by falling edge and
// wraps round once: a many-sided target's thousands of intervals are put in order by a
// reversal and a rotation instead of a sort.
void sortByEdge(std::vector<visibility::SeenInterval>& seen) {
  const auto sorted = [&seen] { return std::is_sorted(seen.begin(), seen.end(), byEdge); };
  if (sorted()) return;
  std::reverse(seen.begin(), seen.end());
  const auto descent = std::is_sorted_until(seen.begin(), seen.end(), byEdge);
  if (std::is_sorted(descent, seen.end(), byEdge) &&
      (descent == seen.end() || !byEdge(seen.front(), seen.back()))) {
    std::rotate(seen.begin(), descent, seen.end());
    if (sorted()) return;
  }
  std::sort(seen.begin(), seen.end(), byEdge);
}

}  // namespace

IncrementalTerms::Terms IncrementalTerms::evaluate(const visibility::Occluders& occluders,
                                                   visibility::Sweep& sweep,
                                                   std::span<const geometry::Pose> cameras,
                                                   std::span<const scene::Lens> lenses,
                                                   const Lengths& lengths) {
  if (occluders.buildId() != build_) reset(occluders);
  const std::size_t kept = cameras_.size();
  for (std::size_t j = cameras.size(); j < kept; ++j)
    leave(static_cast<std::uint32_t>(j));
  cameras_.resize(cameras.size());
  for (std::size_t j = 0; j < cameras.size(); ++j) {
    Camera& c = cameras_[j];
    if (j < kept && geometry::sameBits(c.pose, cameras[j]) && scene::sameBits(c.lens, lenses[j])) {
      continue;
    }
    const auto seen = sweep.seenBy(occluders, j, cameras[j], lenses[j]);
    const bool samePlace = j < kept && geometry::sameBits(c.pose.position(), cameras[j].position());
    c.pose = cameras[j];
    c.lens = lenses[j];
    see(occluders, static_cast<std::uint32_t>(j), seen, samePlace);
  }
  for (const std::uint32_t e : dirty_) {
    Edge& edge = edges_[e];
    visible_.subtract(edge.length);
    weighted_.subtract(edge.weighted);
    const UnionLength now = unionLength(occluders, e, lengths.weights, kNoCamera);
    edge.length = now.plain;
    edge.weighted = now.weighted;
    visible_.add(edge.length);
    weighted_.add(edge.weighted);
    edge.dirty = false;
  }
  dirty_.clear();

  angles_.clear();
  for (const Camera& c : cameras_)
    angles_.push_back(c.angles);
  Terms t;
  t.coverage = coverageOf(visible_.value(), lengths.perimeter);
  t.weightedCoverage = lengths.weights.empty()
                           ? t.coverage
                           : coverageOf(weighted_.value(), lengths.weightedPerimeter);
  t.utilization = utilizationOf(angles_, lenses);
  return t;
}

void IncrementalTerms::reset(const visibility::Occluders& occluders) {
  build_ = occluders.buildId();
  cameras_.clear();
  dirty_.clear();
  visible_ = {};
  weighted_ = {};
  edges_.resize(occluders.targetEdgeCount());
  for (Edge& e : edges_) {
    e.seenBy.clear();  // keeps its buffer
    e.length = e.weighted = 0;
    e.dirty = false;
  }
}

void IncrementalTerms::see(const visibility::Occluders& occluders, std::uint32_t camera,
                           std::span<const visibility::SeenInterval> seen, bool samePlace) {
  Camera& c = cameras_[camera];
  nextSeen_.assign(seen.begin(), seen.end());
  sortByEdge(nextSeen_);
  const double angles = takeRuns(occluders, c, samePlace);
  // Edge by edge, the camera's intervals before and after (both by edge): where they differ,
  // the old ones out of the edge's list, the new ones in, and its union measured again.
  const std::vector<visibility::SeenInterval>& before = c.seen;
  const auto sameInterval = [](const visibility::SeenInterval& a,
                               const visibility::SeenInterval& b) {
    return geometry::sameBits(a.lo, b.lo) && geometry::sameBits(a.hi, b.hi);
  };
  std::size_t i = 0, k = 0;
  while (i < before.size() || k < nextSeen_.size()) {
    const std::uint32_t edge = k == nextSeen_.size() ? before[i].edge
                               : i == before.size()  ? nextSeen_[k].edge
                                                     : std::min(before[i].edge, nextSeen_[k].edge);
    std::size_t i1 = i, k1 = k;
    while (i1 < before.size() && before[i1].edge == edge)
      ++i1;
    while (k1 < nextSeen_.size() && nextSeen_[k1].edge == edge)
      ++k1;
    if (!std::equal(before.begin() + i, before.begin() + i1, nextSeen_.begin() + k,
                    nextSeen_.begin() + k1, sameInterval)) {
      auto& seenBy = edges_[edge].seenBy;  // kept by lo, for unionLength()
      if (i1 > i)
        std::erase_if(seenBy, [camera](const Interval& in) { return in.camera == camera; });
      for (std::size_t n = k; n < k1; ++n) {
        const auto at = std::upper_bound(seenBy.begin(), seenBy.end(), nextSeen_[n].lo,
                                         [](double lo, const Interval& in) { return lo < in.lo; });
        seenBy.insert(at, {camera, nextSeen_[n].lo, nextSeen_[n].hi});
      }
      markDirty(edge);
    }
    i = i1;
    k = k1;
  }
  c.seen.swap(nextSeen_);
  c.runs.swap(nextRuns_);
  c.angles = angles;
}

double IncrementalTerms::takeRuns(const visibility::Occluders& occluders, const Camera& c,
                                  bool samePlace) {
  // In the order of S, as utilization() adds them.
  nextRuns_.clear();
  double angles = 0.0;
  const geometry::Vec2 p = c.pose.position();
  std::size_t old = 0;  // the first kept run not before this one
  forEachRun(
      std::span<const visibility::SeenInterval>(nextSeen_),
      [](const visibility::SeenInterval& s) { return s.edge; }, keepAll,
      [&](std::uint32_t edge, double lo, double hi) {
        const geometry::Vec2 a = occluders.targetEdgeStart(edge), b = occluders.targetEdgeEnd(edge);
        if (a == b) return;  // a repeated vertex: S has no segment there
        const auto& kept = c.runs;
        while (old < kept.size() &&
               (kept[old].edge < edge || (kept[old].edge == edge && kept[old].lo < lo)))
          ++old;
        const bool again = samePlace && old < kept.size() && kept[old].edge == edge &&
                           geometry::sameBits(kept[old].lo, lo) &&
                           geometry::sameBits(kept[old].hi, hi);
        const double angle =
            again ? kept[old].angle
                  : subtendedAngle(visibility::pointAt(a, b, lo), visibility::pointAt(a, b, hi), p);
        nextRuns_.push_back({edge, lo, hi, angle});
        angles += angle;
      });
  return angles;
}

void IncrementalTerms::leave(std::uint32_t camera) {
  for (const visibility::SeenInterval& s : cameras_[camera].seen) {
    std::erase_if(edges_[s.edge].seenBy,
                  [camera](const Interval& i) { return i.camera == camera; });
    markDirty(s.edge);
  }
  cameras_[camera].seen.clear();
  cameras_[camera].runs.clear();
  cameras_[camera].angles = 0.0;
}

void IncrementalTerms::markDirty(std::uint32_t edge) {
  if (edges_[edge].dirty) return;
  edges_[edge].dirty = true;
  dirty_.push_back(edge);
}

void IncrementalTerms::seenWithout(const visibility::Occluders& occluders, std::uint32_t camera,
                                   std::vector<double>& seen) const {
  seen.assign(edges_.size(), 0.0);
  for (std::uint32_t e = 0; e < edges_.size(); ++e) {
    if (edges_[e].seenBy.empty()) continue;
    FixedPointSum length;
    length.add(unionLength(occluders, e, {}, camera).plain);
    seen[e] = length.value();
  }
}

double IncrementalTerms::anglesWithout(std::uint32_t camera) const {
  double weighted = 0.0;
  for (std::uint32_t i = 0; i < cameras_.size(); ++i) {
    if (i != camera)
      weighted += utilizationWeight(cameras_[0].lens, cameras_[i].lens) * cameras_[i].angles;
  }
  return weighted;
}

IncrementalTerms::UnionLength IncrementalTerms::unionLength(const visibility::Occluders& occluders,
                                                            std::uint32_t edge,
                                                            std::span<const double> weights,
                                                            std::uint32_t leftOut) const {
  const geometry::Vec2 a = occluders.targetEdgeStart(edge), b = occluders.targetEdgeEnd(edge);
  if (a == b) return {};  // a repeated vertex: S has no segment there
  const auto& seenBy = edges_[edge].seenBy;
  const double w = weights.empty() ? 1.0 : weights[edge];
  UnionLength total;
  // Run by run, as weightedVisibleLength() adds S's runs.
  forEachRun(
      std::span<const Interval>(seenBy), [](const Interval&) { return 0; },
      [leftOut](const Interval& in) { return in.camera != leftOut; },
      [&](int, double lo, double hi) {
        const double length =
            geometry::distance(visibility::pointAt(a, b, lo), visibility::pointAt(a, b, hi));
        total.plain += FixedPointSum::units(length);
        if (!weights.empty()) total.weighted += FixedPointSum::units(w * length);
      });
  return total;
}

}  // namespace camcov::reward
