#include "reward/incremental_repulsion.h"

#include "geometry/same_bits.h"
#include "reward/metrics.h"

namespace camcov::reward {

void IncrementalRepulsion::reset() {
  cameras_.clear();
  pairs_.clear();
  total_ = {};
}

double IncrementalRepulsion::evaluate(const kinematics::World& world,
                                      std::span<const geometry::Box> boxes,
                                      std::span<const geometry::Pose> cameras, double d2) {
  while (cameras_.size() > cameras.size())
    remove(cameras_.size() - 1);
  for (std::size_t j = 0; j < cameras.size(); ++j) {
    if (j < cameras_.size() && geometry::sameBits(cameras_[j].pose, cameras[j])) continue;
    if (j < cameras_.size()) remove(j);
    place(world, boxes, j, cameras[j], d2);
  }
  return total_.value();
}

double IncrementalRepulsion::without(std::size_t j) const {
  FixedPointSum rest = total_;
  rest.subtract(cameras_[j].objects);
  for (std::size_t i = 0; i < cameras_.size(); ++i) {
    if (i != j) rest.subtract(i < j ? pair(i, j) : pair(j, i));
  }
  return rest.value();
}

void IncrementalRepulsion::remove(std::size_t j) {
  total_.subtract(cameras_[j].objects);
  cameras_[j].objects = 0;
  for (std::size_t i = 0; i < cameras_.size(); ++i) {
    if (i == j) continue;
    Units& term = i < j ? pair(i, j) : pair(j, i);
    total_.subtract(term);
    term = 0;
  }
  if (j + 1 == cameras_.size()) {
    cameras_.pop_back();
    const std::size_t m = cameras_.size();
    pairs_.resize(m == 0 ? 0 : m * (m - 1) / 2);
  }
}

void IncrementalRepulsion::place(const kinematics::World& world,
                                 std::span<const geometry::Box> boxes, std::size_t j,
                                 const geometry::Pose& pose, double d2) {
  if (j == cameras_.size()) {
    cameras_.push_back({});
    pairs_.resize(cameras_.size() * (cameras_.size() - 1) / 2, 0);
  }
  Camera& c = cameras_[j];
  c.pose = pose;
  c.objects = 0;
  for (const double term : objectTerms(world, boxes, pose.position(), d2, terms_))
    c.objects += FixedPointSum::units(term);
  total_.add(c.objects);
  for (std::size_t i = 0; i < cameras_.size(); ++i) {
    if (i == j) continue;
    // Cameras not placed yet in this call are placed after, and add their pairs then.
    const geometry::Vec2 other = cameras_[i].pose.position(), p = pose.position();
    Units& term = i < j ? pair(i, j) : pair(j, i);
    // In repulsion()'s argument order: the camera of the lower index first.
    term = FixedPointSum::units(i < j ? pairTerm(other, p, d2) : pairTerm(p, other, d2));
    total_.add(term);
  }
}

}  // namespace camcov::reward
