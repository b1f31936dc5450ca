// Visibility (S and visibleBy, eq. (1)) and the reward's terms (eq. (2)–(8)) for camera poses
// given as numpy arrays, at one instant: the services the built-in methods use.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <mutex>
#include <numbers>

#include "python/bindings.h"
#include "python/numpy_arrays.h"
#include "python/python_scene.h"
#include "reward/reward_model.h"
#include "scene/camera_keys.h"
#include "scene/scene_validation.h"

namespace camcov::python {
namespace {

// What a call leaves for its caller to convert: kept between calls, so that a large batch
// does not grow fresh memory every time.
struct Scratch {
  std::vector<visibility::Segment> segments;
  std::vector<std::int64_t> team;  // per segment, for many teams at once
  std::vector<reward::RewardTerms> terms;
};

// A RewardModel for one instant. Its buffers are reused between calls, so calls on one object
// take turns (the lock). The lock is only ever waited for without the GIL, so a thread that
// holds it can always take the GIL back; the sweeps run without the GIL, and objects in
// several threads sweep in parallel.
class Visibility {
 public:
  Visibility(const kinematics::World& world, std::vector<scene::Lens> lenses,
             const params::Parameters& params)
      : cameras_(lenses.size()), model_(params.reward, std::move(lenses)) {
    model_.setWorld(world);
  }

  // Evaluates the teams of `teamSize` poses each in `poses` (camera j with θ_j) without the
  // GIL, writing their terms, and their segments if `withSegments`, into the scratch. Returns
  // with the GIL and the lock held: the scratch is the caller's until it lets the lock go.
  std::unique_lock<std::mutex> evaluate(const std::vector<geometry::Pose>& poses,
                                        std::size_t teamSize, bool withSegments) {
    // Pose j is camera j, with θ_j: a team may be the first cameras only (as `camcov inspect
    // --cameras` takes fewer poses than cameras), never more poses than fields of view.
    if (teamSize > cameras_) {
      throw py::value_error(std::to_string(teamSize) + " poses per team, but " +
                            std::to_string(cameras_) +
                            " fields of view: pose j is camera j, with θ_j");
    }
    py::gil_scoped_release free;
    std::unique_lock lock(mutex_);
    scratch_.segments.clear();
    scratch_.team.clear();
    scratch_.terms.clear();
    // A team of no cameras is one (empty) team; otherwise the poses are teams of teamSize.
    const std::size_t teams = teamSize == 0 ? 1 : poses.size() / teamSize;
    for (std::size_t k = 0; k < teams; ++k) {
      scratch_.terms.push_back(model_.evaluate(std::span(poses).subspan(k * teamSize, teamSize)));
      if (!withSegments) continue;
      scratch_.segments.insert(scratch_.segments.end(), model_.segments().begin(),
                               model_.segments().end());
      scratch_.team.resize(scratch_.segments.size(), static_cast<std::int64_t>(k));
    }
    return lock;
  }
  const Scratch& scratch() const { return scratch_; }

  Array visibilityPolygon(geometry::Vec2 point) {
    geometry::Ring polygon;
    {
      py::gil_scoped_release free;
      const std::lock_guard lock(mutex_);
      model_.visibilityPolygon(point, polygon);
    }
    return ringToArray(polygon);
  }

 private:
  std::size_t cameras_;
  reward::RewardModel model_;
  Scratch scratch_;
  std::mutex mutex_;
};

// The keyword of a sensing row of the camera table for hand-made lenses: its key in
// snake_case, plural (sensingRange: sensing_ranges), one value per camera.
std::string lensKeyword(const scene::CameraKey& row) {
  std::string keyword;
  for (const char* c = row.name; *c; ++c) {
    if (std::isupper(static_cast<unsigned char>(*c))) keyword += '_';
    keyword += static_cast<char>(std::tolower(static_cast<unsigned char>(*c)));
  }
  return keyword + "s";
}

// The sensing rows hand-made lenses take by keyword: all but θ, which `cameras` gives.
bool byKeyword(const scene::CameraKey& row) {
  return row.kind == scene::CameraKeyKind::sensing && row.id != scene::CameraKeyId::cameraFoV;
}

std::string lensKeywords() {
  std::string names;
  for (const scene::CameraKey& row : scene::kCameraKeys)
    if (byKeyword(row)) names += (names.empty() ? "" : ", ") + lensKeyword(row);
  return names;
}

// Lenses given by hand: one half-angle θ_j per camera and, optionally, per sensing key of the
// camera table one value each in the scene file's units (sensing_ranges: metres; the value of a
// camera without the property, e.g. inf, leaves it off).
std::vector<scene::Lens> lensesFromArrays(const py::handle& halfFovs, const py::kwargs& keys) {
  const Array thetas = Array::ensure(halfFovs);
  if (!thetas || thetas.ndim() != 1 || thetas.shape(0) == 0)
    throw py::value_error(
        "cameras: expected a camcov.Scene or one half-angle (radians) per camera");
  const auto count = static_cast<std::size_t>(thetas.shape(0));
  // The sweep keeps which cameras see a segment as a scene::CameraSet.
  if (count > scene::kMaxCameras) {
    throw py::value_error(
        fmt::format("cameras: {} cameras; at most {}", count, scene::kMaxCameras));
  }
  std::vector<scene::CameraSpec> cameras;
  for (const double theta : valuesFromArray(thetas, count, "cameras")) {
    if (!(theta > 0.0 && theta < std::numbers::pi)) {
      throw py::value_error(fmt::format("cameras: θ_{} = {} rad: a half-angle must lie in (0, π)",
                                        cameras.size(), theta));
    }
    cameras.push_back(scene::cameraWithoutOptions());
    cameras.back().lens.halfFov = theta;
  }
  for (const auto& [key, values] : keys) {
    const auto keyword = key.cast<std::string>();
    const auto row = std::find_if(
        scene::kCameraKeys.begin(), scene::kCameraKeys.end(),
        [&](const scene::CameraKey& r) { return byKeyword(r) && lensKeyword(r) == keyword; });
    if (row == scene::kCameraKeys.end()) {
      throw py::type_error(fmt::format("Visibility: unexpected keyword {}; a lens takes {}",
                                       keyword, lensKeywords()));
    }
    const Array a = Array::ensure(values);
    if (!a || a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != count) {
      throw py::value_error(
          fmt::format("{}: expected {} values, one per camera ({})", keyword, count, row->unit));
    }
    for (std::size_t j = 0; j < count; ++j) {
      const double v = a.data()[j];
      if (v == row->absent) continue;
      if (const auto problem = row->problem(v))
        throw py::value_error(fmt::format("{}: camera {}: {}", keyword, j, *problem));
      row->set(cameras[j], row->fromFile(v));
    }
  }
  std::vector<scene::Lens> lenses;
  for (const scene::CameraSpec& c : cameras)
    lenses.push_back(c.lens);
  return lenses;
}

std::unique_ptr<Visibility> makeVisibility(const kinematics::World& world,
                                           const py::handle& cameras, const py::handle& values,
                                           const py::kwargs& keys) {
  if (py::isinstance<PythonScene>(cameras)) {
    if (!keys.empty()) {
      throw py::value_error(fmt::format("{}: a scene's cameras bring their own lenses",
                                        py::str(keys.begin()->first).cast<std::string>()));
    }
    return std::make_unique<Visibility>(
        world, scene::lenses(cameras.cast<const PythonScene&>().scene), parametersFrom(values));
  }
  return std::make_unique<Visibility>(world, lensesFromArrays(cameras, keys),
                                      parametersFrom(values));
}

// The terms of every team as arrays (N,).
py::dict termsToArrays(std::span<const reward::RewardTerms> terms) {
  const auto n = static_cast<py::ssize_t>(terms.size());
  Array coverage(n), weightedCoverage(n), utilization(n), repulsion(n), reward(n);
  for (py::ssize_t k = 0; k < n; ++k) {
    coverage.mutable_at(k) = terms[k].coverage;
    weightedCoverage.mutable_at(k) = terms[k].weightedCoverage;
    utilization.mutable_at(k) = terms[k].utilization;
    repulsion.mutable_at(k) = terms[k].repulsion;
    reward.mutable_at(k) = terms[k].reward;
  }
  py::dict d;
  d["coverage"] = coverage;
  d["weightedCoverage"] = weightedCoverage;
  d["utilization"] = utilization;
  d["repulsion"] = repulsion;
  d["reward"] = reward;
  return d;
}

}  // namespace

void bindVisibility(py::module_& m) {
  py::class_<Visibility>(m, "Visibility",
                         "Visibility and reward at one instant for a team of cameras: a scene's "
                         "(each camera's lens: half-angle θ_j and sensing range) or lenses given "
                         "by hand.")
      .def(py::init(&makeVisibility), py::arg("world"), py::arg("cameras"),
           py::arg("params") = py::none(),
           "Visibility(world, cameras, params=None, **lens): the world (a camcov.World); the "
           "cameras' lenses: a camcov.Scene (its cameras', sensing ranges included), or one "
           "half-angle θ_j in radians per camera, with one array per further sensing key of a "
           "scene's cameras in the file's units (sensing_ranges: metres, inf or leave out: "
           "unlimited; image_widths: pixels, 0: no image model); and parameters "
           "({'reward.lambda1': ...}, as camcov.parameters takes them) for the reward's "
           "weights.")
      .def(
          "segments",
          [](Visibility& v, const py::handle& poses) {
            const auto team = posesFromArray(poses, "poses");
            const auto lock = v.evaluate(team, team.size(), true);
            return segmentsToDict(v.scratch().segments, team.size());
          },
          py::arg("poses"),
          "S for poses (M, 3): every target edge split where visibility changes, as arrays a, "
          "b (S, 2), target, edge (S,), visible_by (S,) with bit j for camera j (uint64; Python "
          "integers "
          "for a team of more than 64).")
      .def(
          "terms",
          [](Visibility& v, const py::handle& poses) {
            const auto team = posesFromArray(poses, "poses");
            const auto lock = v.evaluate(team, team.size(), false);
            return termsToDict(v.scratch().terms.front());
          },
          py::arg("poses"), "coverage, utilization, repulsion and reward (eq. (3)–(8)).")
      .def(
          "segments_each",
          [](Visibility& v, const py::handle& teams) {
            std::size_t m = 0;
            const auto poses = teamsFromArray(teams, m);
            const auto lock = v.evaluate(poses, m, true);
            return segmentsToDict(v.scratch().segments, m, v.scratch().team);
          },
          py::arg("teams"),
          "segments() of many teams in one call: (N, M, 3), or (N, 3) for N single cameras "
          "(camera 0's θ). Every team's arrays one after the other, with `team` saying whose.")
      .def(
          "terms_each",
          [](Visibility& v, const py::handle& teams) {
            std::size_t m = 0;
            const auto poses = teamsFromArray(teams, m);
            const auto lock = v.evaluate(poses, m, false);
            return termsToArrays(v.scratch().terms);
          },
          py::arg("teams"),
          "terms() of many teams in one call, as arrays (N,): (N, M, 3), or (N, 3) for N "
          "single cameras (camera 0's θ).")
      .def(
          "visibility_polygon",
          [](Visibility& v, const py::handle& point) {
            const auto p = valuesFromArray(point, 2, "point", scene::kMaxCoordinate);
            return v.visibilityPolygon({p[0], p[1]});
          },
          py::arg("point"), "The region seen from a point in every direction (Algorithm 2).");
}

}  // namespace camcov::python
