#pragma once
// The data the run explorer embeds: one or more recorded runs of one scene, with
// everything the page draws at every step already computed here, by the same code as the
// frames (viz::RunReplay: the world, S with visibleBy, each camera's view, plan and goal) —
// the page decodes and draws, it never decides geometry. Per step it adds, for each segment of
// S and each camera that does not see it, why not (visibility/unseen_reason.h), and each
// camera's nearest object and camera.
//
// The document (JSON, format "camcov-explorer/1"): the scene's name, boundary and the loops
// its objects travel (with their speeds), the
// palette and legend (viz/palette.h), and per run its method, seed, colour, the recorded
// series (time, coverage, utilization, reward; weighted and resolution coverage where the
// scene asks them; targetsPresent on recorded tracks), the cameras' limits, the events, and the
// steps as one packed stream (packed_stream.h, base64). Per step, in order:
//   objects    targets, then obstacles: how many are present (recorded tracks come and go),
//              then each one's scene index, vertex count n and n (x, y) in mm — differences
//              from the same object's vertices the last time it was drawn when n is unchanged,
//              else from the previous vertex (the first from 0)
//   cameras    per camera: x, y in mm and yaw in 1e-4 rad, differences from one step before;
//              goal: 0 none, 1 as before, 2 then x, y, yaw; plan: n, then the points in mm as
//              differences from the previous (the first from the camera); view: n, then the
//              points in cm likewise but the first from 0; nearest object: distance in mm, object
//              (0 none, 1 + 2i target i, 2 + 2i obstacle i); nearest camera: 1 + index (0
//              none), distance mm; its own coverage and utilization terms (eq. 3, 5) × 10^6
//   segments   count, then per segment: target (scene index), edge, where it starts and ends
//              along the edge (fractions × 10^6), visibleBy, and for each camera not in it the
//              reason: kind + 8 · (blocker kind + 4 · blocker's scene index)
//              (visibility::UnseenKind, ObjectRef)
//   unresolved a scene with a resolution only: count, then per piece of seen boundary no
//              camera resolves (viz::Frame::unresolved) target, edge, start and end as above
// Millimetres keep the drawing and the numbers exact to what a user can see; views, which are
// only filled, are kept to centimetres. A 30 s run of dynamic9 packs into about 0.3 MB.
#include <cstddef>
#include <span>

#include <nlohmann/json.hpp>

#include "records/run_record.h"
#include "scene/scene.h"

namespace camcov::reports::explorer {

inline constexpr const char* kExplorerFormat = "camcov-explorer/1";
inline constexpr double kMillimetres = 1000.0;  // per m, for objects, cameras, plans
inline constexpr double kCentimetres = 100.0;   // per m, for views
inline constexpr double kYawUnits = 1e4;        // per rad
inline constexpr double kAlongEdge = 1e6;       // per edge length
inline constexpr double kTermUnits = 1e6;       // per unit of a reward term
inline constexpr double kWeightUnits = 1e3;     // per unit of an edge's importance weight

// The most packed step data one page holds, bytes over all its runs: 128 MiB in the page as
// base64. Writing a page holds a few copies of it in memory and a browser must load it whole:
// a 100,000-step run of three cameras (scenes/dynamic_loops_speeds.json) packs into 44 MB,
// and a page of two of them (89 MB packed, 118 MB of page) took 0.78 GB to write, so about
// 0.9 GB at the limit. Past it the page is refused as it is packed, before the copies are made.
inline constexpr std::size_t kMaxPackedSteps = std::size_t{96} << 20;

// Throws InputError when the runs are not of one scene (name and file hash), a run does not
// fit the scene (viz::RunReplay's checks) or the runs' steps pack into more than
// `maxPacked` bytes.
nlohmann::json explorerData(std::span<const records::RunRecord> runs, const scene::Scene& scene,
                            std::size_t maxPacked = kMaxPackedSteps);

// The frames' palette and wordings for a page's script (viz/palette.h): colours, the width of
// weighted edges, the legend, and why an edge is unseen (visibility::unseenPhrase by
// UnseenKind). The explorer's and the playground's.
nlohmann::json paletteJson();

}  // namespace camcov::reports::explorer
