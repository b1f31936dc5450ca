#pragma once
// Exact nearest neighbours for the PRM* roadmap (paper section V-C) in sub-linear time, with no
// random numbers. OMPL's exhaustive search measures every milestone for every new
// one, O(n²) for a roadmap; GNAT is sub-linear but picks its pivots from OMPL's global
// generator, which would make roadmaps depend on what else ran in the process.
//
// The elements are bucketed by their position in a uniform grid of square cells (side h);
// a query visits the cells ring by ring outwards from its own. The distance is the caller's
// (OMPL's SE(2) distance, ‖Δxy‖ + ½|Δγ|), which is at least the planar distance ‖Δxy‖; so
// no element of a cell farther than the k-th best (or than the radius) can qualify, and the
// search stops there. Results are those of NearestNeighborsLinear, sorted by distance, ties
// in the order the elements were added (Linear leaves ties to std::partial_sort: with
// distances of random poses they do not occur).
#include <ompl/datastructures/NearestNeighbors.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "geometry/vec2.h"

namespace camcov::planners {

template <typename T>
class GridNearestNeighbors final : public ompl::NearestNeighbors<T> {
 public:
  using PositionFn = std::function<geometry::Vec2(const T&)>;

  // `cell`: the side h of a cell, m (> 0); about a handful of elements per cell is best.
  // `position`: where an element lies in the plane (the distance function's ‖Δxy‖ part).
  GridNearestNeighbors(double cell, PositionFn position)
      : cell_(cell), position_(std::move(position)) {}

  bool reportsSortedResults() const override { return true; }
  void clear() override {
    cells_.clear();
    all_.clear();
    next_ = 0;
  }
  void add(const T& data) override {
    const Key k = keyOf(position_(data));
    cells_[pack(k)].push_back({data, next_++});
    all_.push_back(data);
    lo_ = all_.size() == 1 ? k : Key{std::min(lo_.x, k.x), std::min(lo_.y, k.y)};
    hi_ = all_.size() == 1 ? k : Key{std::max(hi_.x, k.x), std::max(hi_.y, k.y)};
  }
  bool remove(const T& data) override {
    const auto it = cells_.find(pack(keyOf(position_(data))));
    if (it == cells_.end()) return false;
    auto& cell = it->second;
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
    const geometry::Vec2 p = position_(data);
    const Key centre = keyOf(p);
    for (std::int64_t ring = 0;; ++ring) {
      // Every cell of this ring and beyond lies at least (ring − 1)·h away in the plane.
      if (found_.size() >= k && beyond(ring, kthBest(k))) break;
      if (!visitRing(centre, ring, [&](const Entry& e) { consider(data, e, k); })) break;
    }
    finish(k, nbh);
  }
  void nearestR(const T& data, double radius, std::vector<T>& nbh) const override {
    nbh.clear();
    found_.clear();
    const geometry::Vec2 p = position_(data);
    const Key centre = keyOf(p);
    for (std::int64_t ring = 0; !beyond(ring, radius); ++ring) {
      const bool more = visitRing(centre, ring, [&](const Entry& e) {
        const double d = this->distFun_(data, e.data);
        if (d <= radius) found_.push_back({d, e.order, e.data});
      });
      if (!more) break;
    }
    finish(found_.size(), nbh);
  }
  std::size_t size() const override { return all_.size(); }
  void list(std::vector<T>& data) const override { data = all_; }

 private:
  struct Key {
    std::int64_t x = 0, y = 0;
  };
  struct Entry {
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
  static std::uint64_t pack(Key k) {
    return (static_cast<std::uint64_t>(k.x) << 32) ^ static_cast<std::uint32_t>(k.y);
  }
  // Every point of the cells `ring` cells away from the query's (Chebyshev) lies farther than
  // `distance` in the plane, so farther by the caller's distance too: the slack keeps the
  // rounding of that distance from mattering.
  bool beyond(std::int64_t ring, double distance) const {
    return static_cast<double>(ring - 1) * cell_ > distance * (1.0 + 1e-9);
  }
  // The cells `ring` cells away from `centre`; false once the rings inside it hold every cell
  // that holds elements (nothing farther can be found).
  template <typename F>
  bool visitRing(Key centre, std::int64_t ring, F&& f) const {
    const std::int64_t inside = ring - 1;
    if (ring > 0 && centre.x - inside <= lo_.x && centre.x + inside >= hi_.x &&
        centre.y - inside <= lo_.y && centre.y + inside >= hi_.y) {
      return false;
    }
    const auto visit = [&](std::int64_t x, std::int64_t y) {
      if (x < lo_.x || x > hi_.x || y < lo_.y || y > hi_.y) return;
      const auto it = cells_.find(pack({x, y}));
      if (it == cells_.end()) return;
      for (const Entry& e : it->second)
        f(e);
    };
    if (ring == 0) {
      visit(centre.x, centre.y);
      return true;
    }
    for (std::int64_t d = -ring; d <= ring; ++d) {
      visit(centre.x + d, centre.y - ring);
      visit(centre.x + d, centre.y + ring);
    }
    for (std::int64_t d = -ring + 1; d <= ring - 1; ++d) {
      visit(centre.x - ring, centre.y + d);
      visit(centre.x + ring, centre.y + d);
    }
    return true;
  }
  // Keeps the k best seen so far as a max-heap on (distance, order).
  void consider(const T& data, const Entry& e, std::size_t k) const {
    const Found f{this->distFun_(data, e.data), e.order, e.data};
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
  PositionFn position_;
  std::unordered_map<std::uint64_t, std::vector<Entry>> cells_;
  std::vector<T> all_;  // in the order added, as Linear lists them
  std::uint64_t next_ = 0;
  Key lo_, hi_;  // the range of cells holding elements
  mutable std::vector<Found> found_;
};

}  // namespace camcov::planners
