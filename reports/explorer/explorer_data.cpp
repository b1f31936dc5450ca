#include "reports/explorer/explorer_data.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "control/event_kind.h"
#include "reports/explorer/packed_stream.h"
#include "reports/method_style.h"
#include "reward/metrics.h"
#include "scene/pitch_markings.h"
#include "util/input_error.h"
#include "util/readable_number.h"
#include "visibility/unseen_reason.h"
#include "viz/palette.h"
#include "viz/run_replay.h"

namespace camcov::reports::explorer {
namespace {

using geometry::Vec2;

std::int64_t quantize(double value, double unitsPerMetre) {
  return std::llround(value * unitsPerMetre);
}

// Writes a ring (or path) of points as differences from the previous one, the first from
// `origin` (all in quantized units).
void putPoints(PackedStream& out, std::span<const Vec2> points, double units, Vec2 origin) {
  out.putUnsigned(points.size());
  std::int64_t x = quantize(origin.x, units), y = quantize(origin.y, units);
  for (const Vec2 p : points) {
    const std::int64_t qx = quantize(p.x, units), qy = quantize(p.y, units);
    out.putSigned(qx - x);
    out.putSigned(qy - y);
    x = qx;
    y = qy;
  }
}

// One run's steps, packed. Keeps what the differences are taken from.
class StepPacker {
 public:
  explicit StepPacker(const scene::Scene& scene)
      : lenses_(scene::lenses(scene)),
        targetCount_(scene.targets.size()),
        objects_(scene.targets.size() + scene.obstacles.size()),
        poses_(scene.cameras.size(), {0, 0, 0}),
        goals_(scene.cameras.size()),
        resolved_(scene.resolution.has_value()) {}

  void put(const viz::Frame& frame, PackedStream& out) {
    putObjects(frame.world, out);
    for (std::size_t j = 0; j < frame.cameras.size(); ++j)
      putCamera(frame, j, out);
    putSegments(frame, out);
    if (resolved_) putPieces(frame.world, frame.unresolved, out);
  }

 private:
  // Targets then obstacles: how many are present, then each one's scene index and vertices.
  void putObjects(const kinematics::World& world, PackedStream& out) {
    const std::size_t targets = targetCount_;
    const auto put = [&](const std::vector<geometry::Ring>& rings, auto idOf, std::size_t offset) {
      out.putUnsigned(rings.size());
      for (std::size_t r = 0; r < rings.size(); ++r) {
        const geometry::Ring& ring = rings[r];
        const std::uint32_t id = idOf(world, r);
        out.putUnsigned(id);
        std::vector<std::int64_t>& previous = objects_[offset + id];
        out.putUnsigned(ring.size());
        const bool same = previous.size() == 2 * ring.size();
        std::int64_t x = 0, y = 0;
        std::vector<std::int64_t> now;
        now.reserve(2 * ring.size());
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const std::int64_t qx = quantize(ring[i].x, kMillimetres);
          const std::int64_t qy = quantize(ring[i].y, kMillimetres);
          out.putSigned(qx - (same ? previous[2 * i] : x));
          out.putSigned(qy - (same ? previous[2 * i + 1] : y));
          x = qx;
          y = qy;
          now.push_back(qx);
          now.push_back(qy);
        }
        previous = std::move(now);
      }
    };
    put(world.targets, kinematics::targetId, 0);
    put(world.obstacles, kinematics::obstacleId, targets);
  }

  void putCamera(const viz::Frame& frame, std::size_t j, PackedStream& out) {
    const viz::CameraView& c = frame.cameras[j];
    const std::array<std::int64_t, 3> pose{quantize(c.pose.x, kMillimetres),
                                           quantize(c.pose.y, kMillimetres),
                                           quantize(c.pose.yaw, kYawUnits)};
    for (std::size_t k = 0; k < 3; ++k)
      out.putSigned(pose[k] - poses_[j][k]);
    poses_[j] = pose;

    if (!c.goal) {
      out.putUnsigned(0);
      goals_[j].reset();
    } else {
      const std::array<std::int64_t, 3> goal{quantize(c.goal->x, kMillimetres),
                                             quantize(c.goal->y, kMillimetres),
                                             quantize(c.goal->yaw, kYawUnits)};
      if (goals_[j] == goal) {
        out.putUnsigned(1);
      } else {
        out.putUnsigned(2);
        for (const std::int64_t v : goal)
          out.putSigned(v);
        goals_[j] = goal;
      }
    }
    putPoints(out, c.plan, kMillimetres, c.pose.position());
    // From the origin: the page knows the camera only to the millimetre, which may round to
    // another centimetre than the camera itself.
    putPoints(out, c.view, kCentimetres, {0.0, 0.0});

    // The nearest object and camera, for the camera's details.
    const Vec2 p = c.pose.position();
    double nearest = std::numeric_limits<double>::infinity();
    std::uint64_t which = 0;  // 0 none, 1 + 2·id a target, 2 + 2·id an obstacle
    for (std::size_t r = 0; r < frame.world.targets.size(); ++r) {
      if (const double d = geometry::distanceToPolygon(frame.world.targets[r], p); d < nearest) {
        nearest = d;
        which = 1 + 2 * std::uint64_t{kinematics::targetId(frame.world, r)};
      }
    }
    for (std::size_t r = 0; r < frame.world.obstacles.size(); ++r) {
      if (const double d = geometry::distanceToPolygon(frame.world.obstacles[r], p); d < nearest) {
        nearest = d;
        which = 2 + 2 * std::uint64_t{kinematics::obstacleId(frame.world, r)};
      }
    }
    out.putUnsigned(which == 0 ? 0 : static_cast<std::uint64_t>(quantize(nearest, kMillimetres)));
    out.putUnsigned(which);
    double nearestCamera = std::numeric_limits<double>::infinity();
    std::size_t other = 0;
    for (std::size_t i = 0; i < frame.cameras.size(); ++i) {
      const double d = geometry::distance(p, frame.cameras[i].pose.position());
      if (i != j && d < nearestCamera) {
        nearestCamera = d;
        other = i + 1;
      }
    }
    out.putUnsigned(other);
    out.putUnsigned(other == 0 ? 0
                               : static_cast<std::uint64_t>(quantize(nearestCamera, kMillimetres)));

    // Its own terms of eq. (3) and (5): what the reward would count for it alone.
    team_.clear();
    for (const viz::CameraView& view : frame.cameras)
      team_.push_back(view.pose);
    const reward::RewardTerms own =
        reward::termsAlone(frame.world, frame.segments, team_, lenses_, j, params::RewardParams{});
    out.putUnsigned(static_cast<std::uint64_t>(std::llround(own.coverage * kTermUnits)));
    out.putUnsigned(static_cast<std::uint64_t>(std::llround(own.utilization * kTermUnits)));
  }

  // A piece of a target's edge: the target's scene index, the edge, and where the piece starts
  // and ends along it.
  static void putPiece(const kinematics::World& world, const visibility::Segment& s,
                       PackedStream& out) {
    const geometry::Ring& ring = world.targets[s.target];
    const Vec2 a = ring[s.edge], b = ring[(s.edge + 1) % ring.size()];
    const double edge = geometry::distance(a, b);
    const auto along = [&](Vec2 point) {
      return static_cast<std::uint64_t>(
          std::llround(std::clamp(geometry::distance(a, point) / edge, 0.0, 1.0) * kAlongEdge));
    };
    out.putUnsigned(kinematics::targetId(world, s.target));
    out.putUnsigned(s.edge);
    out.putUnsigned(along(s.a));
    out.putUnsigned(along(s.b));
  }

  // The seen boundary no camera resolves (viz::Frame::unresolved).
  static void putPieces(const kinematics::World& world, std::span<const visibility::Segment> pieces,
                        PackedStream& out) {
    out.putUnsigned(pieces.size());
    for (const visibility::Segment& s : pieces)
      putPiece(world, s, out);
  }

  void putSegments(const viz::Frame& frame, PackedStream& out) {
    out.putUnsigned(frame.segments.size());
    for (const visibility::Segment& s : frame.segments) {
      putPiece(frame.world, s, out);
      out.putBits(s.visibleBy);
      // A weighted scene's (run.weighted): the edge's importance, in thousandths.
      if (!frame.world.targetEdgeWeights.empty()) {
        out.putUnsigned(static_cast<std::uint64_t>(
            std::llround(frame.world.targetEdgeWeights[s.target][s.edge] * kWeightUnits)));
      }
      for (std::size_t j = 0; j < frame.cameras.size(); ++j) {
        if (s.visibleBy.contains(j)) continue;
        visibility::UnseenReason r =
            visibility::whyUnseen(frame.world, frame.cameras[j].pose, lenses_[j], s);
        if (r.blocker.kind == visibility::ObjectRef::Kind::Target)
          r.blocker.index = kinematics::targetId(frame.world, r.blocker.index);
        if (r.blocker.kind == visibility::ObjectRef::Kind::Obstacle)
          r.blocker.index = kinematics::obstacleId(frame.world, r.blocker.index);
        out.putUnsigned(static_cast<std::uint64_t>(r.kind) +
                        8 * (static_cast<std::uint64_t>(r.blocker.kind) +
                             4 * static_cast<std::uint64_t>(r.blocker.index)));
      }
    }
  }

  std::vector<scene::Lens> lenses_;
  std::vector<geometry::Pose> team_;  // the step's camera poses, reused
  std::size_t targetCount_ = 0;
  std::vector<std::vector<std::int64_t>> objects_;  // by scene index: vertices the last time
  std::vector<std::array<std::int64_t, 3>> poses_;
  std::vector<std::optional<std::array<std::int64_t, 3>>> goals_;
  bool resolved_ = false;  // the scene asks a resolution: each step ends with the unresolved
};

// Every mark an event may get: its glyph and its legend's words.
nlohmann::json marksJson() {
  nlohmann::json marks = nlohmann::json::object();
  for (const control::EventMarkInfo& m : control::eventMarks())
    marks[std::string(m.name)] = {{"glyph", m.glyph}, {"label", m.label}};
  return marks;
}

nlohmann::json ringJson(std::span<const Vec2> ring) {
  nlohmann::json out = nlohmann::json::array();
  for (const Vec2 p : ring)
    out.push_back({static_cast<double>(quantize(p.x, kMillimetres)) / kMillimetres,
                   static_cast<double>(quantize(p.y, kMillimetres)) / kMillimetres});
  return out;
}

// A football pitch's lines, drawn as the frames draw them.
nlohmann::json markingsJson(const scene::Scene& scene) {
  nlohmann::json out = nlohmann::json::array();
  if (!scene.pitch) return out;
  for (const auto& line : scene::pitchMarkings(*scene.pitch))
    out.push_back(ringJson(line));
  return out;
}

// Each object's own colour (a team's), "" for the palette's.

nlohmann::json colours(const std::vector<scene::MovingObject>& objects) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& o : objects)
    out.push_back(o.color);
  return out;
}

// The loops moving objects travel, as the frames draw them (dashed), with their speeds.
nlohmann::json objectPathsJson(const scene::Scene& scene) {
  viz::FrameBuilder builder(scene);
  viz::Frame frame;
  std::vector<geometry::Pose> initial;
  for (const auto& c : scene.cameras)
    initial.push_back(c.initial);
  builder.build(0.0, initial, frame);
  nlohmann::json out = nlohmann::json::array();
  for (const viz::ObjectPath& path : frame.paths) {
    if (path.waypoints.size() < 2) continue;
    out.push_back({{"loop", ringJson(path.waypoints)}, {"speed", path.speedLabel()}});
  }
  return out;
}

// `packedBefore`: bytes the page's earlier runs packed, at most `maxPacked` with this run's.
nlohmann::json runJson(const records::RunRecord& run, const scene::Scene& scene,
                       std::size_t& packedBefore, std::size_t maxPacked) {
  viz::RunReplay replay(run, scene);
  nlohmann::json series = {{"time", nlohmann::json::array()},
                           {"coverage", nlohmann::json::array()},
                           {"utilization", nlohmann::json::array()},
                           {"reward", nlohmann::json::array()}};
  const bool weighted = scene.isWeighted();
  if (weighted) series["weightedCoverage"] = nlohmann::json::array();
  const bool resolved = scene.resolution.has_value();
  if (resolved) series["resolutionCoverage"] = nlohmann::json::array();
  // Recorded tracks: how many targets are present at each step; where nobody is, the coverage
  // terms are 0 by definition, and the timeline leaves a gap rather than draw a plunge.
  const bool presence =
      std::any_of(run.steps.begin(), run.steps.end(),
                  [](const records::StepRow& s) { return s.targetsPresent >= 0; });
  if (presence) series["targetsPresent"] = nlohmann::json::array();
  // Under limited knowledge: who heard whom at each step, [from, to] pairs.
  if (run.summary.messages) series["heard"] = nlohmann::json::array();
  for (const auto& step : run.steps) {
    if (run.summary.messages) {
      nlohmann::json pairs = nlohmann::json::array();
      for (const sim::Hearing& h : step.heard)
        pairs.push_back({h.from, h.to});
      series["heard"].push_back(std::move(pairs));
    }
    series["time"].push_back(step.time);
    if (presence) series["targetsPresent"].push_back(step.targetsPresent);
    series["coverage"].push_back(step.terms.coverage);
    if (weighted) series["weightedCoverage"].push_back(step.terms.weightedCoverage);
    if (resolved) series["resolutionCoverage"].push_back(step.resolutionCoverage);
    series["utilization"].push_back(step.terms.utilization);
    series["reward"].push_back(step.terms.reward);
  }
  nlohmann::json cameras = nlohmann::json::array();
  for (const auto& c : scene.cameras)
    cameras.push_back(scene::describeCamera(c));
  nlohmann::json events = nlohmann::json::array();
  for (const auto& e : run.events) {
    // The mark by the one rule of control/event_kind.h, so the timeline marks what the
    // report's plots mark.
    events.push_back({{"time", e.time},
                      {"kind", e.kind},
                      {"camera", e.camera},
                      {"detail", e.detail},
                      {"reason", e.reason},
                      {"mark", control::markInfo(control::markOf(e)).name}});
  }
  PackedStream packed;
  StepPacker packer(scene);
  viz::Frame frame;
  for (std::size_t k = 0; k < run.steps.size(); ++k) {
    replay.build(k, frame);
    packer.put(frame, packed);
    if (packedBefore + packed.size() > maxPacked) {
      throw InputError(fmt::format(
          "an explorer page holds at most {} MiB of packed steps (the run of {}, seed {} "
          "reached it at step {} of {}): a page that large does not load; explore fewer runs "
          "at once, or runs with fewer steps (--duration) or cameras",
          readableNumber(static_cast<double>(maxPacked) / (1 << 20)), run.metadata.method,
          run.metadata.seed, k + 1, run.steps.size()));
    }
  }
  packedBefore += packed.size();
  const MethodStyle style = methodStyle(run.metadata.method);
  return {{"method", run.metadata.method},
          {"label", fmt::format("{} · seed {}", style.label, run.metadata.seed)},
          {"color", style.color},
          {"seed", run.metadata.seed},
          {"dt", run.metadata.parameters.sim.dt},
          {"series", series},
          {"cameras", cameras},
          {"viewAlpha", viz::viewAlphaFor(scene.cameras.size())},
          {"weighted", weighted},
          {"resolved", resolved},
          {"targets", scene.targets.size()},
          {"obstacles", scene.obstacles.size()},
          {"events", events},
          {"steps", packed.base64()}};
}

// visibility::unseenPhrase of every UnseenKind, by its number (the packed reason's low bits).
nlohmann::json unseenPhrases() {
  using visibility::UnseenKind;
  nlohmann::json out = nlohmann::json::array();
  for (const UnseenKind kind :
       {UnseenKind::InSight, UnseenKind::OutsideBoundary, UnseenKind::InsideObject,
        UnseenKind::BehindItsTarget, UnseenKind::OutsideFieldOfView, UnseenKind::Blocked}) {
    if (out.size() != static_cast<std::size_t>(kind))
      throw std::logic_error("unseenPhrases: UnseenKind is not numbered in order");
    out.push_back(visibility::unseenPhrase(kind));
  }
  return out;
}

}  // namespace

nlohmann::json paletteJson() {
  nlohmann::json legend = nlohmann::json::array();
  for (const viz::Legend entry : viz::kLegendEntries)
    legend.push_back(viz::legendText(entry));
  return {{"page", viz::cssColour(viz::kPage)},
          {"floor", viz::cssColour(viz::kFloor)},
          {"wall", viz::cssColour(viz::kWall)},
          {"obstacle", viz::cssColour(viz::kObstacle)},
          {"target", viz::cssColour(viz::kTarget)},
          {"seenBy",
           {viz::cssColour(viz::seenByColour(0)), viz::cssColour(viz::seenByColour(1)),
            viz::cssColour(viz::seenByColour(2)), viz::cssColour(viz::seenByColour(3))}},
          {"view", viz::cssColour(viz::kView)},
          {"viewAlpha", viz::kViewAlpha},
          // importanceWidthFactor(w) = widthAtZero + widthPerWeight · w
          {"widthAtZero", viz::importanceWidthFactor(0.0)},
          {"widthPerWeight", viz::importanceWidthFactor(1.0) - viz::importanceWidthFactor(0.0)},
          {"importance", viz::legendText(viz::Legend::Importance)},
          {"unresolved", viz::cssColour(viz::kUnresolved)},
          {"unresolvedText", viz::legendText(viz::Legend::Unresolved)},
          {"unseen", unseenPhrases()},
          {"camera", viz::cssColour(viz::kCamera)},
          {"plan", viz::cssColour(viz::kPlan)},
          {"objectPath", viz::cssColour(viz::kObjectPath)},
          {"pitchLine", viz::cssColour(viz::kPitchLine)},
          {"text", viz::cssColour(viz::kText)},
          {"mutedText", viz::cssColour(viz::kMutedText)},
          {"legend", legend}};
}

nlohmann::json explorerData(std::span<const records::RunRecord> runs, const scene::Scene& scene,
                            std::size_t maxPacked) {
  nlohmann::json out = {
      {"format", kExplorerFormat},
      {"scene",
       {{"name", scene.name},
        {"boundary", ringJson(scene.boundary)},
        {"paths", objectPathsJson(scene)},
        {"markings", markingsJson(scene)},
        {"colors",
         {{"targets", colours(scene.targets)}, {"obstacles", colours(scene.obstacles)}}}}},
      {"palette", paletteJson()},
      {"marks", marksJson()},
      {"units",
       {{"millimetres", kMillimetres},
        {"terms", kTermUnits},
        {"centimetres", kCentimetres},
        {"yaw", kYawUnits},
        {"alongEdge", kAlongEdge},
        {"weight", kWeightUnits}}},
      {"runs", nlohmann::json::array()}};
  std::size_t packed = 0;  // bytes of steps, over the runs so far
  for (const records::RunRecord& run : runs) {
    const records::RunMetadata& first = runs.front().metadata;
    if (run.metadata.scene != first.scene || run.metadata.sceneHash != first.sceneHash) {
      throw InputError(fmt::format(
          "the runs are not of one scene: {} (method {}, seed {}) and {} (method {}, seed {}); "
          "the explorer shows runs of one scene side by side",
          first.scene, first.method, first.seed, run.metadata.scene, run.metadata.method,
          run.metadata.seed));
    }
    out["runs"].push_back(runJson(run, scene, packed, maxPacked));
  }
  return out;
}

}  // namespace camcov::reports::explorer
