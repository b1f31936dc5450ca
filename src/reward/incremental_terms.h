#pragma once
// Coverage, eq. (3), and utilization, eq. (5), of a team whose cameras move a few at a time —
// the optimizers' probes. Made from S, they cost a sweep per camera, the cut of
// every target edge and a sum over all of S on every call, although a probe moves one camera
// and changes only what that camera sees.
//
// Both terms are sums that split by what changes (metrics.h says how they are taken):
//  - utilization: per camera, the angles of the runs it sees — its own sweep alone decides
//    them, so they are kept with the camera and summed over the cameras, O(M);
//  - vis(S): per target edge, the length of the union of every camera's intervals on it —
//    kept per edge in a fixed-point sum, which a changed edge updates exactly, O(1); and the
//    same with each run's length times its edge's importance weight.
// A call sweeps the cameras whose pose or θ changed (Sweep keeps their last sweeps), takes
// their angles, and measures again the union of the edges where their intervals changed. The
// terms are those of reward::coverage() and reward::utilization() on S, to the bit
// (tests/reward/incremental_terms_test.cpp).
//
// A probe moves a camera a little: most edges it sees whole, before and after, and a camera
// turned in place sees the same runs from the same point. So an edge whose intervals of the
// moved camera are bit for bit the ones it had keeps its union (the same terms would give the
// same sum), and a run seen again from the same position keeps its angle (the same atan2).
//
// Cost of a call where c cameras moved: their sweeps, O(k log k) for the k intervals they
// see before and after, the union of the edges where those differ, and O(M).
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "reward/fixed_point_sum.h"
#include "scene/camera.h"
#include "visibility/occluders.h"
#include "visibility/segment.h"
#include "visibility/sweep.h"

namespace camcov::reward {

class IncrementalTerms {
 public:
  struct Terms {
    double coverage = 0.0;
    double weightedCoverage = 0.0;
    double utilization = 0.0;
  };
  // The targets' edges at the instant: their perimeter, and where weighted, each global edge's
  // weight (Occluders numbering) and their weighted perimeter (weightedPerimeter()).
  struct Lengths {
    double perimeter = 0.0;
    std::span<const double> weights;  // empty: every edge 1
    double weightedPerimeter = 0.0;
  };

  // The terms of `cameras` (camera j with lens lenses[j]) at the instant of `occluders`.
  // `sweep` answers the sweeps; a new arrangement (Occluders::buildId()) starts afresh.
  Terms evaluate(const visibility::Occluders& occluders, visibility::Sweep& sweep,
                 std::span<const geometry::Pose> cameras, std::span<const scene::Lens> lenses,
                 const Lengths& lengths);

  // Of the last evaluate()'s cameras without camera `camera` (what stays while an optimizer
  // probes that camera's poses): each target edge's length the others see, unweighted, into
  // `seen` (global numbering), and eq. (5)'s sum of their angles as utilizationOf() weighs
  // them, Σ_{i≠camera} (θ_0/θ_i)·angles_i.
  void seenWithout(const visibility::Occluders& occluders, std::uint32_t camera,
                   std::vector<double>& seen) const;
  double anglesWithout(std::uint32_t camera) const;

 private:
  // A run of one camera's intervals on an edge (as S joins its consecutive seen pieces), with
  // the angle it subtends at the camera.
  struct Run {
    std::uint32_t edge;
    double lo, hi, angle;
  };
  struct Camera {
    geometry::Pose pose;
    scene::Lens lens;
    std::vector<visibility::SeenInterval> seen;  // by edge and along it
    std::vector<Run> runs;                       // of `seen`, in its order
    double angles = 0.0;                         // Σ of the runs' angles, in their order
  };
  struct Interval {
    std::uint32_t camera;
    double lo, hi;
  };
  struct Edge {
    std::vector<Interval> seenBy;       // every camera's intervals on this edge
    FixedPointSum::Units length = 0;    // of their union
    FixedPointSum::Units weighted = 0;  // the same, each run's length times the edge's weight
    bool dirty = false;
  };
  struct UnionLength {
    FixedPointSum::Units plain = 0, weighted = 0;
  };

  void reset(const visibility::Occluders& occluders);
  // Camera `camera` (its pose and lens already set) now sees `seen`; `samePlace`: from the
  // position of its kept runs.
  void see(const visibility::Occluders& occluders, std::uint32_t camera,
           std::span<const visibility::SeenInterval> seen, bool samePlace);
  // The runs of nextSeen_ into nextRuns_, and their angle sum.
  double takeRuns(const visibility::Occluders& occluders, const Camera& c, bool samePlace);
  void leave(std::uint32_t camera);
  void markDirty(std::uint32_t edge);
  // The union of the edge's intervals, leaving out those of camera `leftOut` (kNoCamera: none).
  static constexpr std::uint32_t kNoCamera = std::numeric_limits<std::uint32_t>::max();
  UnionLength unionLength(const visibility::Occluders& occluders, std::uint32_t edge,
                          std::span<const double> weights, std::uint32_t leftOut) const;

  std::uint64_t build_ = 0;  // Occluders::buildId() of what is kept; 0: nothing
  std::vector<Camera> cameras_;
  std::vector<Edge> edges_;
  std::vector<std::uint32_t> dirty_;
  FixedPointSum visible_;   // vis(S): Σ over edges of their union's length
  FixedPointSum weighted_;  // the same weighted
  std::vector<double> angles_;
  std::vector<visibility::SeenInterval> nextSeen_;  // see()'s buffers
  std::vector<Run> nextRuns_;
};

}  // namespace camcov::reward
