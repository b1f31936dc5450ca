#pragma once
// Repulsion, eq. (6), of a team whose cameras move a few at a time — the optimizers' probes.
// repulsion() measures every camera against every object and every other camera,
// O(M·N + M²) per call, although a probe moves one camera and changes only its own terms.
//
// repulsion() is an exact fixed-point sum of its terms (fixed_point_sum.h), so the sum can be
// kept: per camera its terms against the objects, per pair of cameras theirs, and their
// total. A call measures again the terms of the cameras whose pose changed and puts them in
// place of the old ones. The result is repulsion()'s to the bit
// (tests/reward/incremental_terms_test.cpp).
//
// Cost of a call where c cameras moved: O(c·(N + M)).
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "reward/fixed_point_sum.h"

namespace camcov::reward {

class IncrementalRepulsion {
 public:
  // Forget every kept term: the instant changed.
  void reset();
  // repulsion(world, boxes, cameras, d2), with `world`, `boxes` and d2 those of every call
  // since the last reset().
  double evaluate(const kinematics::World& world, std::span<const geometry::Box> boxes,
                  std::span<const geometry::Pose> cameras, double d2);
  // Repulsion of the last evaluate()'s cameras without camera j: its terms taken out of the
  // exact sum, so the same to the bit as repulsion() of the others.
  double without(std::size_t j) const;

 private:
  using Units = FixedPointSum::Units;
  struct Camera {
    geometry::Pose pose;
    Units objects = 0;  // its terms against every object
  };
  // The term of cameras i < j.
  Units& pair(std::size_t i, std::size_t j) { return pairs_[j * (j - 1) / 2 + i]; }
  Units pair(std::size_t i, std::size_t j) const { return pairs_[j * (j - 1) / 2 + i]; }
  void remove(std::size_t j);
  void place(const kinematics::World& world, std::span<const geometry::Box> boxes, std::size_t j,
             const geometry::Pose& pose, double d2);

  std::vector<Camera> cameras_;
  std::vector<Units> pairs_;
  FixedPointSum total_;
  std::vector<double> terms_;
};

}  // namespace camcov::reward
