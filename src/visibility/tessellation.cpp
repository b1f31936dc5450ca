#include "visibility/tessellation.h"

#include <algorithm>
#include <utility>

namespace camcov::visibility {

using geometry::Vec2;

void Tessellation::clear() {
  edgeOf_.clear();
  pending_.clear();
}

void appendSeen(std::vector<SeenInterval>& out, std::uint32_t globalEdge, double a, double b) {
  if (a > b) std::swap(a, b);
  const double lo = std::max(a, 0.0), hi = std::min(b, 1.0);
  if (hi > lo) out.push_back({globalEdge, lo, hi});
}

void Tessellation::add(std::span<const SeenInterval> seen, unsigned camera) {
  for (const SeenInterval& s : seen) {
    pending_.push_back({s.lo, camera, +1});
    pending_.push_back({s.hi, camera, -1});
    edgeOf_.push_back(s.edge);
    edgeOf_.push_back(s.edge);
  }
}

void Tessellation::build(const Occluders& occluders, std::vector<Segment>& out) {
  out.clear();
  // Bucket the marks by target edge (counting sort), then sort each edge's few marks by t.
  const std::uint32_t edges = occluders.targetEdgeCount();
  bucket_.assign(edges + 1, 0);
  for (const std::uint32_t e : edgeOf_)
    ++bucket_[e + 1];
  for (std::uint32_t e = 0; e < edges; ++e)
    bucket_[e + 1] += bucket_[e];
  marks_.resize(pending_.size());
  for (std::size_t i = 0; i < pending_.size(); ++i)
    marks_[bucket_[edgeOf_[i]]++] = pending_[i];
  // bucket_[e] now holds the end of edge e's marks, which is where edge e + 1's begin.

  for (std::uint32_t target = 0; target < occluders.targetCount(); ++target) {
    for (std::uint32_t g = occluders.targetEdgeOffset(target);
         g < occluders.targetEdgeOffset(target + 1); ++g) {
      const Vec2 a = occluders.targetEdgeStart(g), b = occluders.targetEdgeEnd(g);
      if (a == b) continue;  // a repeated vertex: no length to cover
      const auto point = [a, b](double t) { return pointAt(a, b, t); };
      const auto first = out.size();
      double cur = 0.0;
      scene::CameraSet mask;
      const auto emit = [&](double t) {
        if (out.size() > first && out.back().visibleBy == mask) {
          out.back().b = point(t);  // same cameras as the piece before: one segment
        } else {
          out.push_back(
              {point(cur), point(t), target, g - occluders.targetEdgeOffset(target), mask});
        }
        cur = t;
      };
      const auto begin = marks_.begin() + (g == 0 ? 0 : bucket_[g - 1]);
      const auto end = marks_.begin() + bucket_[g];
      std::sort(begin, end, [](const Mark& x, const Mark& y) { return x.t < y.t; });
      for (auto m = begin; m != end;) {
        if (m->t > cur) emit(m->t);
        // All marks at one t at once, so touching intervals of one camera do not split S.
        for (const double t = m->t; m != end && m->t == t; ++m) {
          open_[m->camera] += m->delta;
          if (open_[m->camera] > 0) {
            mask.insert(m->camera);
          } else {
            mask.erase(m->camera);
          }
        }
      }
      if (cur < 1.0) emit(1.0);
    }
  }
}

}  // namespace camcov::visibility
