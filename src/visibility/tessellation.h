#pragma once
// update(S) and update(visibleBy(·)) — Algorithm 1, lines 12–13 and 16 (paper section IV-B).
// Internal to the visibility stage.
//
// Each camera's sweep reports the parameter intervals of target edges it sees (SeenInterval);
// the Sweep keeps them per camera, so a camera that did not move is not swept again.
// Each camera's sweep reports the parameter intervals of target edges it sees. Instead of
// re-splitting S after every camera (the paper's line 16), the intervals of all cameras are
// collected and every target edge is cut once at all their endpoints: the same S, in
// O(k log k) for k intervals. Neighbouring pieces seen by the same cameras are merged, and
// the unseen rest of every edge is kept with an empty mask, so each target's segments add
// up to its perimeter.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "scene/camera.h"
#include "visibility/occluders.h"
#include "visibility/segment.h"

namespace camcov::visibility {

// Appends to `out` what a sweep found of target edge `globalEdge`, between parameters t = a and
// b in either order: clipped to the edge, and nothing if it has no length (seen edge-on, or
// only at a point).
void appendSeen(std::vector<SeenInterval>& out, std::uint32_t globalEdge, double a, double b);

class Tessellation {
 public:
  void clear();
  // Camera `camera` (< scene::kMaxCameras) sees each of `seen`.
  void add(std::span<const SeenInterval> seen, unsigned camera);
  // Writes S, ordered by target, edge, and along the edge.
  void build(const Occluders& occluders, std::vector<Segment>& out);

 private:
  struct Mark {
    double t;
    std::uint32_t camera;
    int delta;  // +1 where a camera's interval opens, −1 where it closes
  };
  std::vector<std::uint32_t> edgeOf_;           // per interval, for the bucket sort
  std::vector<Mark> pending_;                   // in arrival order
  std::vector<std::uint32_t> bucket_;           // first mark of each target edge
  std::vector<Mark> marks_;                     // bucketed by edge
  std::array<int, scene::kMaxCameras> open_{};  // per camera
};

}  // namespace camcov::visibility
