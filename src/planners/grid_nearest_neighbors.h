#pragma once
// Exact nearest neighbours for the PRM* roadmap (paper section V-C) in sub-linear time, with no
// random numbers. OMPL's exhaustive search measures every milestone for every new
// one, O(n²) for a roadmap; GNAT is sub-linear but picks its pivots from OMPL's global
// generator, which would make roadmaps depend on what else ran in the process.
//
// The elements are bucketed by their position in a uniform grid of square cells (side h),
// laid out densely over the box where they are expected; a query visits the cells ring by ring
// outwards from its own. The few elements outside that box are kept aside and measured by
// every query, so one far away never makes the grid large. The distance is OMPL's SE(2) distance,
// ‖Δxy‖ + ½|Δγ| (se2_distance.h), from the poses kept beside the elements (so without the jumps
// to each state); it is at least the planar distance ‖Δxy‖, so no element of a cell
// farther than the k-th best (or than the radius) can qualify, and the search stops there.
// Results are those of NearestNeighborsLinear, sorted by distance, ties in the order the
// elements were added (Linear leaves ties to std::partial_sort: with distances of random
// poses they do not occur).
#include <ompl/datastructures/NearestNeighbors.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "planners/se2_distance.h"

namespace camcov::planners {

template <typename T>
class GridNearestNeighbors final : public ompl::NearestNeighbors<T> {
 public:
  // Where an element lies: its SE(2) pose, yaw in OMPL's [-π, π).
  using PoseFn = std::function<geometry::Pose(const T&)>;

  // `cell`: the side h of a cell, m (> 0); about a handful of elements per cell is best.
  // `expected`: where the elements will lie (finite), over which the cells are laid out.
  GridNearestNeighbors(double cell, const geometry::Box& expected, PoseFn pose)
      : cell_(cell), pose_(std::move(pose)), lo_(keyOf(expected.min)), hi_(keyOf(expected.max)) {
    cells_.resize(static_cast<std::size_t>((hi_.x - lo_.x + 1) * (hi_.y - lo_.y + 1)));
  }

  bool reportsSortedResults() const override { return true; }
  void clear() override {
    for (auto& cell : cells_)
      cell.clear();
    outside_.clear();
    all_.clear();
    next_ = 0;
  }
  void add(const T& data) override {
    const geometry::Pose p = pose_(data);
    bucketOf(keyOf(p.position())).push_back({p, data, next_++});
    all_.push_back(data);
  }
  bool remove(const T& data) override {
    auto& bucket = bucketOf(keyOf(pose_(data).position()));
    const auto found =
        std::find_if(bucket.begin(), bucket.end(), [&](const Entry& e) { return e.data == data; });
    if (found == bucket.end()) return false;
    bucket.erase(found);
    all_.erase(std::find(all_.begin(), all_.end(), data));
    return true;
  }
  T nearest(const T& data) const override {
    std::vector<T> one;
    nearestK(data, 1, one);
    if (one.empty()) throw ompl::Exception("No elements found in nearest neighbors data structure");
    return one.front();
  }
  void nearestK(const T& data, std::size_t k, std::vector<T>& nbh) const override {
    nbh.clear();
    if (k == 0 || all_.empty()) return;
    found_.clear();
    const geometry::Pose p = pose_(data);
    const Key centre = keyOf(p.position());
    reachSquared_ = std::numeric_limits<double>::infinity();
    for (const Entry& e : outside_)
      consider(p, e, k);
    for (std::int64_t ring = firstRing(centre);; ++ring) {
      // Every cell of this ring and beyond lies at least (ring − 1)·h away in the plane.
      if (found_.size() >= k && beyond(ring, kthBest(k))) break;
      if (!visitRing(centre, ring, [&](const Entry& e) { consider(p, e, k); })) break;
    }
    if (found_.size() < k) std::sort(found_.begin(), found_.end());  // fewer than k in all
    take(k, nbh);
  }
  void nearestR(const T& data, double radius, std::vector<T>& nbh) const override {
    nbh.clear();
    found_.clear();
    const geometry::Pose p = pose_(data);
    const Key centre = keyOf(p.position());
    const auto within = [&](const Entry& e) {
      const double d = se2Distance(p, e.pose);
      if (d <= radius) found_.push_back({d, e.order, e.data});
    };
    for (const Entry& e : outside_)
      within(e);
    for (std::int64_t ring = firstRing(centre); !beyond(ring, radius); ++ring) {
      if (!visitRing(centre, ring, within)) break;
    }
    std::sort(found_.begin(), found_.end());
    take(found_.size(), nbh);
  }
  std::size_t size() const override { return all_.size(); }
  void list(std::vector<T>& data) const override { data = all_; }

 private:
  struct Key {
    std::int64_t x = 0, y = 0;
  };
  struct Entry {
    geometry::Pose pose;
    T data;
    std::uint64_t order;  // when it was added: breaks ties
  };
  struct Found {
    double distance;
    std::uint64_t order;
    T data;
    bool operator<(const Found& o) const {
      return distance != o.distance ? distance < o.distance : order < o.order;
    }
  };

  Key keyOf(geometry::Vec2 p) const {
    return {static_cast<std::int64_t>(std::floor(p.x / cell_)),
            static_cast<std::int64_t>(std::floor(p.y / cell_))};
  }
  std::size_t indexOf(std::int64_t x, std::int64_t y) const {
    return static_cast<std::size_t>((y - lo_.y) * (hi_.x - lo_.x + 1) + (x - lo_.x));
  }
  // The cell of key k, or the elements kept aside if k lies off the grid.
  std::vector<Entry>& bucketOf(Key k) {
    const bool onGrid = k.x >= lo_.x && k.x <= hi_.x && k.y >= lo_.y && k.y <= hi_.y;
    return onGrid ? cells_[indexOf(k.x, k.y)] : outside_;
  }
  // Every point of the cells `ring` cells away from the query's (Chebyshev) lies farther than
  // `distance` in the plane, so farther by the SE(2) distance too: the slack keeps the
  // rounding of that distance from mattering.
  bool beyond(std::int64_t ring, double distance) const {
    return static_cast<double>(ring - 1) * cell_ > distance * (1.0 + 1e-9);
  }
  // The first ring around `centre` that holds a cell of the grid (0 if it lies on the grid):
  // the rings inside it hold nothing, and a query far off the grid starts there.
  std::int64_t firstRing(Key centre) const {
    return std::max<std::int64_t>(
        {0, lo_.x - centre.x, centre.x - hi_.x, lo_.y - centre.y, centre.y - hi_.y});
  }
  // The cells `ring` cells away from `centre`; false once the rings inside it hold every cell
  // of the grid (nothing farther can be found).
  template <typename F>
  bool visitRing(Key centre, std::int64_t ring, F&& f) const {
    const std::int64_t inside = ring - 1;
    if (ring > 0 && centre.x - inside <= lo_.x && centre.x + inside >= hi_.x &&
        centre.y - inside <= lo_.y && centre.y + inside >= hi_.y) {
      return false;
    }
    const auto visitRow = [&](std::int64_t y, std::int64_t x0, std::int64_t x1) {
      if (y < lo_.y || y > hi_.y) return;
      x0 = std::max(x0, lo_.x);
      x1 = std::min(x1, hi_.x);
      for (std::int64_t x = x0; x <= x1; ++x) {
        for (const Entry& e : cells_[indexOf(x, y)])
          f(e);
      }
    };
    if (ring == 0) {
      visitRow(centre.y, centre.x, centre.x);
      return true;
    }
    visitRow(centre.y - ring, centre.x - ring, centre.x + ring);
    visitRow(centre.y + ring, centre.x - ring, centre.x + ring);
    for (std::int64_t y = std::max(centre.y - ring + 1, lo_.y);
         y <= std::min(centre.y + ring - 1, hi_.y); ++y) {
      visitRow(y, centre.x - ring, centre.x - ring);
      visitRow(y, centre.x + ring, centre.x + ring);
    }
    return true;
  }
  // Keeps the k best seen so far: the first k as met, sorted on (distance, order) once there
  // are k (one sort costs less than placing each in turn); then one that beats the k-th moves
  // in from the end. (A heap's sift and the sort at the end cost a third more: their
  // comparisons go either way, a scan from the end mostly one way.) Once there are k, one
  // farther in the plane than the k-th is passed over before its SE(2) distance is taken: that
  // distance is at least the planar one (reachSquared_ carries the slack of beyond()).
  void consider(const geometry::Pose& p, const Entry& e, std::size_t k) const {
    std::size_t at = found_.size();
    if (at < k) {
      // The first k in the order met, sorted once there are k.
      found_.push_back({se2Distance(p, e.pose), e.order, e.data});
      if (found_.size() < k) return;
      std::sort(found_.begin(), found_.end());
    } else {
      const double dx = p.x - e.pose.x, dy = p.y - e.pose.y;
      if (dx * dx + dy * dy > reachSquared_) return;
      const Found f{se2Distance(p, e.pose), e.order, e.data};
      if (!(f < found_.back())) return;
      for (--at; at > 0 && f < found_[at - 1]; --at)
        found_[at] = found_[at - 1];
      found_[at] = f;
    }
    const double reach = found_.back().distance * (1.0 + 1e-9);
    reachSquared_ = reach * reach;
  }
  double kthBest(std::size_t k) const {
    return found_.size() < k ? std::numeric_limits<double>::infinity() : found_.back().distance;
  }
  // The first k of found_, which is sorted.
  void take(std::size_t k, std::vector<T>& nbh) const {
    for (std::size_t i = 0; i < found_.size() && i < k; ++i)
      nbh.push_back(found_[i].data);
  }

  double cell_;
  PoseFn pose_;
  Key lo_, hi_;                            // the range of cells laid out
  std::vector<std::vector<Entry>> cells_;  // row by row over lo_..hi_
  std::vector<Entry> outside_;             // the elements off the grid
  std::vector<T> all_;                     // in the order added, as Linear lists them
  std::uint64_t next_ = 0;
  mutable std::vector<Found> found_;
  mutable double reachSquared_ = 0.0;  // nearestK's: (k-th best · (1 + 1e-9))², ∞ until k found
};

}  // namespace camcov::planners
