#pragma once
// Exact nearest neighbours for the PRM* roadmap (paper section V-C) in sub-linear time, with no
// random numbers. OMPL's exhaustive search measures every milestone for every new
// one, O(n²) for a roadmap; GNAT is sub-linear but picks its pivots from OMPL's global
// generator, which would make roadmaps depend on what else ran in the process.
//
// The elements are bucketed by their position in a uniform grid of square cells (side h),
// held densely over the range of cells that hold elements; a query visits the cells ring by
// ring outwards from its own. The distance is OMPL's SE(2) distance, ‖Δxy‖ + ½|Δγ|, worked
// out here from the poses kept beside the elements with OMPL's own operations in its order
// (so to the bit what SE2StateSpace::distance returns, without its virtual calls and the
// jumps to each state); it is at least the planar distance ‖Δxy‖, so no element of a cell
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

namespace camcov::planners {

template <typename T>
class GridNearestNeighbors final : public ompl::NearestNeighbors<T> {
 public:
  // Where an element lies: its SE(2) pose, yaw in OMPL's [-π, π).
  using PoseFn = std::function<geometry::Pose(const T&)>;

  // `cell`: the side h of a cell, m (> 0); about a handful of elements per cell is best.
  // `expected`: where most elements will lie (the cells over it are laid out at once; an
  // element outside it widens the grid).
  GridNearestNeighbors(double cell, geometry::Box expected, PoseFn pose)
      : cell_(cell), pose_(std::move(pose)) {
    layOut(keyOf(expected.min), keyOf(expected.max));
  }

  bool reportsSortedResults() const override { return true; }
  void clear() override {
    for (auto& cell : cells_)
      cell.clear();
    all_.clear();
    next_ = 0;
  }
  void add(const T& data) override {
    const geometry::Pose p = pose_(data);
    const Key k = keyOf(p.position());
    if (k.x < lo_.x || k.x > hi_.x || k.y < lo_.y || k.y > hi_.y) {
      layOut({std::min(lo_.x, k.x), std::min(lo_.y, k.y)},
             {std::max(hi_.x, k.x), std::max(hi_.y, k.y)});
    }
    cellAt(k).push_back({p, data, next_++});
    all_.push_back(data);
  }
  bool remove(const T& data) override {
    const Key k = keyOf(pose_(data).position());
    if (k.x < lo_.x || k.x > hi_.x || k.y < lo_.y || k.y > hi_.y) return false;
    auto& cell = cellAt(k);
    const auto found =
        std::find_if(cell.begin(), cell.end(), [&](const Entry& e) { return e.data == data; });
    if (found == cell.end()) return false;
    cell.erase(found);
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
    for (std::int64_t ring = 0;; ++ring) {
      // Every cell of this ring and beyond lies at least (ring − 1)·h away in the plane.
      if (found_.size() >= k && beyond(ring, kthBest(k))) break;
      if (!visitRing(centre, ring, [&](const Entry& e) { consider(p, e, k); })) break;
    }
    finish(k, nbh);
  }
  void nearestR(const T& data, double radius, std::vector<T>& nbh) const override {
    nbh.clear();
    found_.clear();
    const geometry::Pose p = pose_(data);
    const Key centre = keyOf(p.position());
    for (std::int64_t ring = 0; !beyond(ring, radius); ++ring) {
      const bool more = visitRing(centre, ring, [&](const Entry& e) {
        const double d = se2Distance(p, e.pose);
        if (d <= radius) found_.push_back({d, e.order, e.data});
      });
      if (!more) break;
    }
    finish(found_.size(), nbh);
  }
  std::size_t size() const override { return all_.size(); }
  void list(std::vector<T>& data) const override { data = all_; }

  // OMPL's SE2StateSpace::distance: its compound space sums each component's distance times
  // its weight (1 for R², ½ for SO(2)) from 0; R²'s is the root of 0 + Δx² + Δy², SO(2)'s
  // |Δγ| or 2π − |Δγ| past π. The same operations in the same order give the same bits
  // (the build does not fuse multiply-adds).
  static double se2Distance(const geometry::Pose& a, const geometry::Pose& b) {
    const double dx = a.x - b.x, dy = a.y - b.y;
    double squares = 0.0;
    squares += dx * dx;
    squares += dy * dy;
    const double turn = std::fabs(a.yaw - b.yaw);
    const double so2 = turn > std::numbers::pi ? 2.0 * std::numbers::pi - turn : turn;
    double distance = 0.0;
    distance += 1.0 * std::sqrt(squares);
    distance += 0.5 * so2;
    return distance;
  }

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
  std::vector<Entry>& cellAt(Key k) { return cells_[indexOf(k.x, k.y)]; }
  // Cells for keys lo..hi, the elements kept in theirs.
  void layOut(Key lo, Key hi) {
    std::vector<std::vector<Entry>> old = std::move(cells_);
    const Key oldLo = lo_, oldHi = hi_;
    lo_ = lo;
    hi_ = hi;
    cells_.assign(static_cast<std::size_t>((hi_.x - lo_.x + 1) * (hi_.y - lo_.y + 1)), {});
    for (std::int64_t y = oldLo.y; !old.empty() && y <= oldHi.y; ++y) {
      for (std::int64_t x = oldLo.x; x <= oldHi.x; ++x) {
        cells_[indexOf(x, y)] = std::move(
            old[static_cast<std::size_t>((y - oldLo.y) * (oldHi.x - oldLo.x + 1) + (x - oldLo.x))]);
      }
    }
  }
  // Every point of the cells `ring` cells away from the query's (Chebyshev) lies farther than
  // `distance` in the plane, so farther by the SE(2) distance too: the slack keeps the
  // rounding of that distance from mattering.
  bool beyond(std::int64_t ring, double distance) const {
    return static_cast<double>(ring - 1) * cell_ > distance * (1.0 + 1e-9);
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
    for (std::int64_t y = centre.y - ring + 1; y <= centre.y + ring - 1; ++y) {
      visitRow(y, centre.x - ring, centre.x - ring);
      visitRow(y, centre.x + ring, centre.x + ring);
    }
    return true;
  }
  // Keeps the k best seen so far as a max-heap on (distance, order).
  void consider(const geometry::Pose& p, const Entry& e, std::size_t k) const {
    const Found f{se2Distance(p, e.pose), e.order, e.data};
    if (found_.size() < k) {
      found_.push_back(f);
      std::push_heap(found_.begin(), found_.end());
    } else if (f < found_.front()) {
      std::pop_heap(found_.begin(), found_.end());
      found_.back() = f;
      std::push_heap(found_.begin(), found_.end());
    }
  }
  double kthBest(std::size_t k) const {
    return found_.size() < k ? std::numeric_limits<double>::infinity() : found_.front().distance;
  }
  void finish(std::size_t k, std::vector<T>& nbh) const {
    std::sort(found_.begin(), found_.end());
    for (std::size_t i = 0; i < found_.size() && i < k; ++i)
      nbh.push_back(found_[i].data);
  }

  double cell_;
  PoseFn pose_;
  std::vector<std::vector<Entry>> cells_;  // row by row over lo_..hi_
  std::vector<T> all_;                     // in the order added, as Linear lists them
  std::uint64_t next_ = 0;
  Key lo_, hi_;  // the range of cells laid out
  mutable std::vector<Found> found_;
};

}  // namespace camcov::planners
