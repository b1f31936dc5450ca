#pragma once
// Conversions between camcov's values and Python's (numpy arrays, dicts): rings as (n, 2) arrays of
// x, y, poses as (M, 3) arrays of x, y, yaw (radians), both float64 and C-contiguous.
#include <pybind11/numpy.h>

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "reward/metrics.h"
#include "visibility/segment.h"

namespace camcov::python {

namespace py = pybind11;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

Array ringToArray(const geometry::Ring& ring);
py::list ringsToList(const std::vector<geometry::Ring>& rings);
Array posesToArray(std::span<const geometry::Pose> poses);
// The name of a value's type, as Python's messages give it ("list", "NoneType").
std::string typeName(const py::handle& value);
// A Python number (or anything float() takes without parsing text) as a double; TypeError
// naming `what` and the type otherwise.
double numberFrom(const py::handle& value, const char* what);
// An (M, 3) array-like (list of lists too) of any numbers, e.g. velocities; ValueError naming
// `what` for another shape.
std::vector<geometry::Pose> rowsFromArray(const py::handle& rows, const char* what);
// ValueError naming `what` and the row unless every pose is one a scene could hold (x, y
// within ±1e9 m, yaw within ±1e6°, as pose files; scene/scene_validation.h).
void requireScenePoses(std::span<const geometry::Pose> poses, const char* what);
// rowsFromArray, for poses: ValueError naming `what` and the row unless every pose is one a scene
// could hold (x, y within ±1e9 m, yaw within ±1e6°, as pose files; scene/scene_validation.h).
std::vector<geometry::Pose> posesFromArray(const py::handle& poses, const char* what);
// Camera teams: an (N, M, 3) array-like is N teams of M poses; an (N, 3) one is N teams of one
// camera. Returns the poses team after team and sets `teamSize` to M. ValueError otherwise, or
// for a pose no scene could hold.
std::vector<geometry::Pose> teamsFromArray(const py::handle& teams, std::size_t& teamSize);
// An (n,) array-like of floats; ValueError naming `what` unless it has `count` entries, each
// finite and within ±`limit`.
std::vector<double> valuesFromArray(const py::handle& values, std::size_t count, const char* what,
                                    double limit = 1e9);
// S of a team of `cameras` as a dict of arrays: a, b (S, 2); target, edge (S,) int64;
// visible_by (S,), bit j for camera j: uint64 for up to 64 cameras, else Python integers (an
// object array); and, when `team` is given, team (S,) int64: which team each segment belongs to.
py::dict segmentsToDict(std::span<const visibility::Segment> segments, std::size_t cameras,
                        std::span<const std::int64_t> team = {});
// A JSON value (a run's summary, the parameters) as Python's json module would read it.
py::object jsonToPython(const nlohmann::json& value);
// The reward's terms: coverage, utilization, repulsion, reward.
py::dict termsToDict(const reward::RewardTerms& terms);

}  // namespace camcov::python
