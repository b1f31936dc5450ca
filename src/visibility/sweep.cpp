#include "visibility/sweep.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geometry/same_bits.h"
#include "visibility/occlusion_culling.h"
#include "visibility/polar_edges.h"
#include "visibility/polar_sweep.h"
#include "visibility/tessellation.h"

namespace camcov::visibility {

using geometry::Vec2;

namespace {

// Spans of the current edge → visible intervals of target edges (Algorithm 1, lines 12–13),
// cut to the lens's range.
class TargetSink final : public SpanSink {
 public:
  TargetSink(const PolarEdges& edges, const scene::Lens& lens, std::vector<SeenInterval>& seen)
      : edges_(edges), lens_(lens), seen_(seen) {
    seen_.clear();
  }

  void span(std::uint32_t front, Vec2 from, Vec2 to, bool inFov) override {
    // Wedges (and kNone) are not pieces; an edge-on piece has no length to see.
    if (!inFov || front >= edges_.wedgeBase() || edges_.edgeOn(front)) return;
    const Occluders& occluders = edges_.occluders();
    const auto members = occluders.targetMembers(front);
    if (members.empty()) return;
    const double s0 = edges_.param(front, from), s1 = edges_.param(front, to);
    for (const Occluders::Member m : members) {
      const double t0 = occluders.t0(m.piece), dt = occluders.t1(m.piece) - t0;
      const double u0 = m.reversed ? 1.0 - s0 : s0, u1 = m.reversed ? 1.0 - s1 : s1;
      const std::uint32_t edge = occluders.globalEdge(m.piece);
      double lo = t0 + u0 * dt, hi = t0 + u1 * dt;
      if (lens_.limited()) {
        double near0 = 0.0, near1 = 0.0;
        if (!lens_.rangeOnSegment(edges_.viewpoint(), occluders.targetEdgeStart(edge),
                                  occluders.targetEdgeEnd(edge), near0, near1))
          continue;
        if (lo > hi) std::swap(lo, hi);
        lo = std::max(lo, near0);
        hi = std::min(hi, near1);
        if (!(lo < hi)) continue;  // appendSeen would take the ends in either order
      }
      appendSeen(seen_, edge, lo, hi);
    }
  }

 private:
  const PolarEdges& edges_;
  const scene::Lens& lens_;
  std::vector<SeenInterval>& seen_;
};

// Spans of the current edge → vertices of the visibility polygon; outside the field of view
// the polygon returns to the viewpoint.
class PolygonSink final : public SpanSink {
 public:
  PolygonSink(const PolarEdges& edges, geometry::Ring& out) : edges_(edges), out_(out) {
    out_.clear();
  }

  void span(std::uint32_t front, Vec2 from, Vec2 to, bool inFov) override {
    if (!inFov) {
      add(edges_.viewpoint());
    } else if (front != PolarEdges::kNone) {
      add(edges_.hit(front, from));
      add(edges_.hit(front, to));
    }
  }

  void finish() {
    if (out_.size() > 1 && out_.front() == out_.back()) out_.pop_back();
  }

 private:
  void add(Vec2 v) {
    if (out_.empty() || out_.back() != v) out_.push_back(v);
  }

  const PolarEdges& edges_;
  geometry::Ring& out_;
};

// A field-of-view polygon (counter-clockwise, star-shaped about `camera`) cut to the lens's
// range: what lies beyond becomes arcs of the range circle, drawn in steps of at most 2°.
void cutToRange(geometry::Ring& polygon, Vec2 camera, const scene::Lens& lens) {
  if (!lens.limited() || polygon.empty()) return;
  constexpr double kArcStep = std::numbers::pi / 90;
  const double r = lens.range;
  const auto angleOf = [&](Vec2 v) { return std::atan2(v.y - camera.y, v.x - camera.x); };
  geometry::Ring out;
  const auto add = [&](Vec2 v) {
    if (out.empty() || out.back() != v) out.push_back(v);
  };
  // Counter-clockwise along the circle, strictly between the two angles.
  const auto arc = [&](double from, double to) {
    double sweep = to - from;
    while (sweep < 0.0)
      sweep += 2.0 * std::numbers::pi;
    const int steps = static_cast<int>(std::ceil(sweep / kArcStep));
    for (int k = 1; k < steps; ++k)
      add(camera + geometry::unitVector(from + sweep * k / steps) * r);
  };
  bool leftDisc = false, entered = false;
  double leftAt = 0.0, firstEntry = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 u = polygon[i], v = polygon[(i + 1) % polygon.size()];
    double t0 = 0.0, t1 = 0.0;
    if (!lens.rangeOnSegment(camera, u, v, t0, t1)) continue;
    if (t0 > 0.0) {  // comes in from beyond the range
      const Vec2 entry = geometry::lerp(u, v, t0);
      if (leftDisc) {
        arc(leftAt, angleOf(entry));
      } else if (!entered) {
        firstEntry = angleOf(entry);
      }
      entered = true;
      leftDisc = false;
      add(entry);
    } else {
      add(u);
    }
    if (t1 < 1.0) {  // goes out beyond the range
      const Vec2 exit = geometry::lerp(u, v, t1);
      add(exit);
      leftDisc = true;
      leftAt = angleOf(exit);
    }
  }
  if (leftDisc && entered) arc(leftAt, firstEntry);
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  polygon = std::move(out);
}

// Records each ray of one camera's sweep (Sweep::trace).
class TraceObserver final : public SweepObserver {
 public:
  TraceObserver(const PolarEdges& edges, SweepTrace& out) : edges_(edges), out_(out) {}

  void start(std::uint32_t front, bool inFov) override {
    out_.frontBefore = traced(front);
    out_.inFovBefore = inFov;
  }

  void ray(std::span<const PolarEdges::Event> batch, std::uint32_t front, bool inFov) override {
    using E = PolarEdges;
    const TracedEdge frontAfter = traced(front);
    for (const E::Event& e : batch) {
      TracedEvent t;
      t.kind = kindOf(e.kind);
      t.ray = rays_;
      // A field-of-view event's own point lies far beyond the scene, where nothing is drawn.
      const Vec2 onRay = edges_.pointOf(e);
      t.hitAfter = edges_.hit(front, onRay);
      const bool fovRay = e.kind == E::EventKind::FovEnter || e.kind == E::EventKind::FovLeave;
      t.point = fovRay ? t.hitAfter : onRay;
      const Vec2 d = onRay - edges_.viewpoint();
      t.angle = std::atan2(d.y, d.x);
      if (t.angle < 0.0) t.angle += 2.0 * std::numbers::pi;
      t.inserted = static_cast<std::uint8_t>(
          std::popcount(static_cast<unsigned>(e.actions & (E::kInsertBefore | E::kInsertAfter))));
      t.removed = static_cast<std::uint8_t>(
          std::popcount(static_cast<unsigned>(e.actions & (E::kRemoveBefore | E::kRemoveAfter))));
      t.frontAfter = frontAfter;
      t.inFovAfter = inFov;
      out_.events.push_back(t);
    }
    ++rays_;
  }

 private:
  static TracedEvent::Kind kindOf(PolarEdges::EventKind kind) {
    switch (kind) {
      case PolarEdges::EventKind::Vertex:
        return TracedEvent::Kind::Vertex;
      case PolarEdges::EventKind::WedgeStart:
        return TracedEvent::Kind::WedgeStart;
      case PolarEdges::EventKind::WedgeEnd:
        return TracedEvent::Kind::WedgeEnd;
      case PolarEdges::EventKind::FovEnter:
        return TracedEvent::Kind::FovEnter;
      case PolarEdges::EventKind::FovLeave:
        break;
    }
    return TracedEvent::Kind::FovLeave;
  }

  TracedEdge traced(std::uint32_t id) const {
    TracedEdge t;
    if (id == PolarEdges::kNone) return t;
    if (id >= edges_.wedgeBase()) {
      t.kind = TracedEdge::Kind::Wedge;
      t.a = t.b = edges_.viewpoint();
      return t;
    }
    const Occluders& occluders = edges_.occluders();
    const Chain& chain = occluders.chainOf(id);
    t.kind = TracedEdge::Kind::Edge;
    t.piece = id;
    t.ring = chain.kind;
    t.owner = chain.owner;
    t.edge = occluders.ringEdge(id);
    t.a = occluders.vertices()[id];
    t.b = occluders.vertices()[occluders.next(id)];
    return t;
  }

  const PolarEdges& edges_;
  SweepTrace& out_;
  std::uint32_t rays_ = 0;
};

bool finite(Vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}

void checkCamera(const geometry::Pose& camera, const scene::Lens& lens) {
  if (!(lens.halfFov > 0.0 && lens.halfFov < std::numbers::pi)) {
    throw std::invalid_argument("visibility: field-of-view half-angle must lie in (0, pi), got " +
                                std::to_string(lens.halfFov));
  }
  // NaN fails too: it would otherwise read as an unlimited range.
  if (!(lens.range > 0.0)) {
    throw std::invalid_argument("visibility: sensing range must be positive, got " +
                                std::to_string(lens.range));
  }
  if (!finite(camera.position()) || !std::isfinite(camera.yaw)) {
    throw std::invalid_argument("visibility: camera pose must be finite");
  }
}

}  // namespace

// One camera's sweep as segments() last did it for a camera slot.
struct CameraMemo {
  std::uint64_t build = 0;  // Occluders::buildId(); 0: nothing kept
  geometry::Pose pose;
  scene::Lens lens;
  std::uint64_t lastUse = 0;
  std::vector<SeenInterval> seen;

  // Bit for bit: a pose that differs in the last bit is swept again, so a kept sweep is
  // exactly the one a new sweep would make.
  bool holds(std::uint64_t b, const geometry::Pose& p, const scene::Lens& l) const {
    return build == b && geometry::sameBits(pose, p) && scene::sameBits(lens, l);
  }
};

// A camera slot's kept sweeps.
using MemoSlot = std::array<CameraMemo, 6>;

namespace {

// The slot's sweep that holds this query, or null.
CameraMemo* heldIn(MemoSlot& slot, std::uint64_t build, const geometry::Pose& pose,
                   const scene::Lens& lens) {
  const auto memo = std::find_if(slot.begin(), slot.end(),
                                 [&](const CameraMemo& m) { return m.holds(build, pose, lens); });
  return memo == slot.end() ? nullptr : &*memo;
}

constexpr auto byLastUse = [](const CameraMemo& a, const CameraMemo& b) {
  return a.lastUse < b.lastUse;
};

// The slot's sweep to replace: the least recently used.
CameraMemo& leastRecent(MemoSlot& slot) {
  return *std::min_element(slot.begin(), slot.end(), byLastUse);
}

}  // namespace

struct Sweep::Impl {
  Culling culling;
  CullingCounts counts;
  OcclusionCulling occlusion;
  PolarEdges edges;
  PolarSweep sweep;
  Tessellation tessellation;
  // Per camera slot, its last six sweeps: an optimizer probing one camera's pose returns to
  // its current pose between probes, and leaves every other camera where it was. Six because
  // the paper method refines a goal (its pose, three probes and the step: five sweeps) between
  // the simulator's measure of the camera and its own local step from there, which then finds
  // the measured sweep still kept (on the 100-target crowd, 9 % fewer sweeps than with two).
  std::vector<MemoSlot> memos;
  std::uint64_t clock = 0;

  // What camera slot j at `pose` sees: a kept sweep, or a new one kept in place of the
  // slot's least recently used.
  std::span<const SeenInterval> seenBy(const Occluders& occluders, std::size_t j,
                                       const geometry::Pose& pose, const scene::Lens& lens) {
    if (memos.size() <= j) memos.resize(j + 1);
    auto& slot = memos[j];
    ++clock;
    if (CameraMemo* kept = heldIn(slot, occluders.buildId(), pose, lens)) {
      kept->lastUse = clock;
      ++counts.reused;
      return kept->seen;
    }
    CameraMemo& memo = leastRecent(slot);
    const FieldOfView fov{pose.yaw, lens.halfFov};
    TargetSink sink(edges, lens, memo.seen);
    sweepFrom(occluders, pose.position(), &fov, sink);
    memo.build = occluders.buildId();
    memo.pose = pose;
    memo.lens = lens;
    memo.lastUse = clock;
    return memo.seen;
  }

  // The sweep from `viewpoint` into `sink`; in a large scene only of the chains that
  // OcclusionCulling cannot rule out.
  void sweepFrom(const Occluders& occluders, Vec2 viewpoint, const FieldOfView* fov,
                 SpanSink& sink) {
    if (occluders.pieceCount() >= culling.fromPieces) {
      occlusion.run(occluders, viewpoint, fov, culling.cellsPerChain);
      edges.build(occluders, viewpoint, fov, occlusion.kept());
      ++counts.culled;
      counts.chainsLeftOut += occlusion.hiddenCount();
    } else {
      edges.build(occluders, viewpoint, fov);
      ++counts.whole;
    }
    sweep.run(edges, sink);
  }
};

Sweep::Sweep(Culling culling) : impl_(std::make_unique<Impl>()) {
  impl_->culling = culling;
}
Sweep::~Sweep() = default;
Sweep::Sweep(Sweep&&) noexcept = default;
Sweep& Sweep::operator=(Sweep&&) noexcept = default;

void Sweep::keepSweepsOf(const Sweep& other) {
  // Only each slot's latest: the others are of earlier instants, or probes, and copying six
  // seen lists a camera at every step would cost more than they save. This one's own sweeps
  // stay: those of the same arrangement (a world that did not change) hold still, the others
  // can never match a query again and go first.
  auto& memos = impl_->memos;
  memos.resize(std::max(memos.size(), other.impl_->memos.size()));
  impl_->clock = std::max(impl_->clock, other.impl_->clock) + 1;
  for (std::size_t j = 0; j < other.impl_->memos.size(); ++j) {
    const auto& theirs = other.impl_->memos[j];
    const CameraMemo& latest = *std::max_element(theirs.begin(), theirs.end(), byLastUse);
    if (latest.build == 0) continue;
    CameraMemo* mine = heldIn(memos[j], latest.build, latest.pose, latest.lens);
    if (mine == nullptr) {
      mine = &leastRecent(memos[j]);
      *mine = latest;  // its seen list into this one's buffer
    }
    mine->lastUse = impl_->clock;  // the last to go
  }
}

const CullingCounts& Sweep::counts() const {
  return impl_->counts;
}

std::span<const SeenInterval> Sweep::seenBy(const Occluders& occluders, std::size_t slot,
                                            const geometry::Pose& camera, const scene::Lens& lens) {
  if (slot >= scene::kMaxCameras) {
    throw std::invalid_argument("visibility: camera slot " + std::to_string(slot) + " beyond the " +
                                std::to_string(scene::kMaxCameras) + " of a mask");
  }
  checkCamera(camera, lens);
  return impl_->seenBy(occluders, slot, camera, lens);
}

void Sweep::segments(const Occluders& occluders, std::span<const geometry::Pose> cameras,
                     std::span<const scene::Lens> lenses, std::vector<Segment>& out) {
  if (cameras.size() > scene::kMaxCameras) {
    throw std::invalid_argument("visibility: at most " + std::to_string(scene::kMaxCameras) +
                                " cameras, got " + std::to_string(cameras.size()));
  }
  if (lenses.size() < cameras.size()) {
    throw std::invalid_argument("visibility: " + std::to_string(cameras.size()) + " cameras but " +
                                std::to_string(lenses.size()) + " lenses");
  }
  for (std::size_t j = 0; j < cameras.size(); ++j)
    checkCamera(cameras[j], lenses[j]);
  impl_->tessellation.clear();
  for (std::size_t j = 0; j < cameras.size(); ++j) {  // Algorithm 1, line 2
    impl_->tessellation.add(impl_->seenBy(occluders, j, cameras[j], lenses[j]),
                            static_cast<unsigned>(j));
  }
  impl_->tessellation.build(occluders, out);
}

void Sweep::segments(const Occluders& occluders, std::span<const geometry::Pose> cameras,
                     const scene::Lens& lens, std::vector<Segment>& out) {
  std::array<scene::Lens, scene::kMaxCameras> lenses;
  lenses.fill(lens);
  segments(occluders, cameras, lenses, out);
}

void Sweep::visibilityPolygon(const Occluders& occluders, Vec2 point, geometry::Ring& out) {
  if (!finite(point)) throw std::invalid_argument("visibility: viewpoint must be finite");
  PolygonSink sink(impl_->edges, out);
  impl_->sweepFrom(occluders, point, nullptr, sink);
  sink.finish();
}

void Sweep::fieldOfViewPolygon(const Occluders& occluders, const geometry::Pose& camera,
                               const scene::Lens& lens, geometry::Ring& out) {
  checkCamera(camera, lens);
  const FieldOfView fov{camera.yaw, lens.halfFov};
  PolygonSink sink(impl_->edges, out);
  impl_->sweepFrom(occluders, camera.position(), &fov, sink);
  sink.finish();
  cutToRange(out, camera.position(), lens);
}

void Sweep::trace(const Occluders& occluders, const geometry::Pose& camera, const scene::Lens& lens,
                  SweepTrace& out) {
  checkCamera(camera, lens);
  out.camera = camera;
  out.lens = lens;
  out.frontBefore = {};
  out.inFovBefore = false;
  out.events.clear();
  // The whole scene at once, every piece, so that every event is recorded.
  const FieldOfView fov{camera.yaw, lens.halfFov};
  impl_->edges.build(occluders, camera.position(), &fov, PolarEdges::Faces::All);
  TraceObserver observer(impl_->edges, out);
  PolygonSink sink(impl_->edges, out.fieldOfView);
  impl_->sweep.run(impl_->edges, sink, &observer);
  sink.finish();
  cutToRange(out.fieldOfView, camera.position(), lens);
  out.blind = impl_->edges.blind();
}

}  // namespace camcov::visibility
