#pragma once
// The polar sweep of one camera drawn for debugging a corner case (`camcov inspect --camera J
// -o debug.svg`): the scene at one instant, the camera and its field of view, the sweep's
// events numbered in the order it visits them (paper section IV-B, Algorithm 1), the edge in
// front after each, the segments S with their visibleBy sets, the camera's visibility
// polygons, and a table of the events beside the drawing. Labels are SVG text, so a browser
// can search the drawing for "e12" or "#7".
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "scene/scene.h"
#include "visibility/segment.h"
#include "visibility/sweep_trace.h"

namespace camcov::viz {

struct SweepDebug {
  std::string title;  // e.g. "static1 at t = 0 s"
  kinematics::World world;
  std::vector<geometry::Pose> cameras;        // all of them: the visibleBy sets name them
  unsigned camera = 0;                        // the one traced
  visibility::SweepTrace trace;               // its sweep and its field-of-view polygon
  geometry::Ring visibility;                  // what it would see with a 360° view
  std::vector<visibility::Segment> segments;  // S with visibleBy of all cameras
};

// InputError unless `file` ends in .svg (any case): lets a command reject a typo before it
// does any work.
void requireSvg(const std::filesystem::path& file);

// The world at `time`, S for all `cameras` and the trace of camera `camera`.
// std::invalid_argument if `camera` is not one of them; otherwise throws like Sweep.
SweepDebug buildSweepDebug(const scene::Scene& scene, double time,
                           std::span<const geometry::Pose> cameras, unsigned camera);

// The drawing and the table as one SVG document. Events are numbered from 1 ("e1"), edges by
// their Occluders piece id ("#7"), cameras from 0 as in visibleBy.
std::string sweepDebugSvg(const SweepDebug& debug);

}  // namespace camcov::viz
