#include "python/numpy_arrays.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "scene/scene_validation.h"
#include "util/readable_number.h"

namespace camcov::python {

Array ringToArray(const geometry::Ring& ring) {
  Array out({static_cast<py::ssize_t>(ring.size()), py::ssize_t{2}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    a(i, 0) = ring[i].x;
    a(i, 1) = ring[i].y;
  }
  return out;
}

py::list ringsToList(const std::vector<geometry::Ring>& rings) {
  py::list out;
  for (const auto& ring : rings)
    out.append(ringToArray(ring));
  return out;
}

Array posesToArray(std::span<const geometry::Pose> poses) {
  Array out({static_cast<py::ssize_t>(poses.size()), py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t j = 0; j < poses.size(); ++j) {
    a(j, 0) = poses[j].x;
    a(j, 1) = poses[j].y;
    a(j, 2) = poses[j].yaw;
  }
  return out;
}

void requireScenePoses(std::span<const geometry::Pose> poses, const char* what) {
  const double maxYaw = geometry::degToRad(scene::kMaxYawDegrees);
  for (std::size_t j = 0; j < poses.size(); ++j) {
    const geometry::Pose& p = poses[j];
    const auto within = [](double v, double limit) {
      return std::isfinite(v) && std::abs(v) <= limit;
    };
    if (!within(p.x, scene::kMaxCoordinate) || !within(p.y, scene::kMaxCoordinate) ||
        !within(p.yaw, maxYaw)) {
      throw py::value_error(fmt::format(
          "{}: row {} ({}, {}, {}): x and y must be finite and within ±{} m, yaw within ±{} rad "
          "({}°)",
          what, j, readableNumber(p.x), readableNumber(p.y), readableNumber(p.yaw),
          readableNumber(scene::kMaxCoordinate), readableNumber(maxYaw),
          readableNumber(scene::kMaxYawDegrees)));
    }
  }
}

std::vector<geometry::Pose> posesFromArray(const py::handle& poses, const char* what) {
  std::vector<geometry::Pose> out = rowsFromArray(poses, what);
  requireScenePoses(out, what);
  return out;
}

std::string typeName(const py::handle& value) {
  return py::str(py::type::of(value).attr("__name__"));
}

double numberFrom(const py::handle& value, const char* what) {
  const double number = PyFloat_AsDouble(value.ptr());
  if (number == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    throw py::type_error(fmt::format("{}: expected numbers, got {}", what, typeName(value)));
  }
  return number;
}

std::vector<geometry::Pose> rowsFromArray(const py::handle& poses, const char* what) {
  // A list or tuple of rows is read directly: a controller's few rows cost less so than
  // through a numpy array made for them.
  if (py::isinstance<py::list>(poses) || py::isinstance<py::tuple>(poses)) {
    std::vector<geometry::Pose> out;
    for (const py::handle row : py::reinterpret_borrow<py::sequence>(poses)) {
      if (!py::isinstance<py::sequence>(row) || py::len(row) != 3)
        throw py::value_error(std::string(what) + ": expected rows of x, y, yaw");
      const auto r = py::reinterpret_borrow<py::sequence>(row);
      out.push_back({numberFrom(r[0], what), numberFrom(r[1], what), numberFrom(r[2], what)});
    }
    return out;
  }
  const Array a = Array::ensure(poses);
  if (!a || a.ndim() != 2 || a.shape(1) != 3) {
    throw py::value_error(std::string(what) + ": expected an (M, 3) array of x, y, yaw");
  }
  std::vector<geometry::Pose> out(static_cast<std::size_t>(a.shape(0)));
  const auto v = a.unchecked<2>();
  for (std::size_t j = 0; j < out.size(); ++j)
    out[j] = {v(j, 0), v(j, 1), v(j, 2)};
  return out;
}

std::vector<geometry::Pose> teamsFromArray(const py::handle& teams, std::size_t& teamSize) {
  const Array a = Array::ensure(teams);
  if (!a || (a.ndim() != 2 && a.ndim() != 3) || a.shape(a.ndim() - 1) != 3) {
    throw py::value_error(
        "teams: expected an (N, M, 3) array of poses, or (N, 3) for single "
        "cameras");
  }
  teamSize = a.ndim() == 3 ? static_cast<std::size_t>(a.shape(1)) : 1;
  const std::size_t poses = static_cast<std::size_t>(a.size() / 3);
  std::vector<geometry::Pose> out(poses);
  const double* v = a.data();
  for (std::size_t k = 0; k < poses; ++k)
    out[k] = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
  requireScenePoses(out, "teams");
  return out;
}

std::vector<double> valuesFromArray(const py::handle& values, std::size_t count, const char* what,
                                    double limit) {
  const Array a = Array::ensure(values);
  if (!a || a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != count) {
    throw py::value_error(std::string(what) + ": expected " + std::to_string(count) + " numbers");
  }
  std::vector<double> out(a.data(), a.data() + count);
  for (std::size_t i = 0; i < count; ++i) {
    if (!std::isfinite(out[i]) || std::abs(out[i]) > limit) {
      throw py::value_error(fmt::format("{}: entry {} is {}: expected a finite number within ±{}",
                                        what, i, readableNumber(out[i]), readableNumber(limit)));
    }
  }
  return out;
}

namespace {

// visibleBy as bits of one number per segment: uint64 for a team of up to 64 cameras, else
// Python's own integers (an object array), which hold as many bits as the team has cameras.
py::array visibleByArray(std::span<const visibility::Segment> segments, std::size_t cameras) {
  const auto n = static_cast<py::ssize_t>(segments.size());
  if (cameras <= 64) {
    py::array_t<std::uint64_t> bits(n);
    auto view = bits.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i)
      view(i) = segments[static_cast<std::size_t>(i)].visibleBy.word(0);
    return bits;
  }
  py::list numbers;
  for (const visibility::Segment& s : segments) {
    py::object value = py::int_(0);
    for (std::size_t w = scene::CameraSet::kWords; w-- > 0;)
      value = value.attr("__lshift__")(64).attr("__or__")(py::int_(s.visibleBy.word(w)));
    numbers.append(value);
  }
  return py::module_::import("numpy").attr("array")(numbers, py::arg("dtype") = "O");
}

}  // namespace

py::dict segmentsToDict(std::span<const visibility::Segment> segments, std::size_t cameras,
                        std::span<const std::int64_t> team) {
  const auto n = static_cast<py::ssize_t>(segments.size());
  Array a({n, py::ssize_t{2}}), b({n, py::ssize_t{2}});
  py::array_t<std::int64_t> target(n), edge(n);
  auto av = a.mutable_unchecked<2>(), bv = b.mutable_unchecked<2>();
  auto tv = target.mutable_unchecked<1>(), ev = edge.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const visibility::Segment& s = segments[static_cast<std::size_t>(i)];
    av(i, 0) = s.a.x;
    av(i, 1) = s.a.y;
    bv(i, 0) = s.b.x;
    bv(i, 1) = s.b.y;
    tv(i) = s.target;
    ev(i) = s.edge;
  }
  py::dict out;
  out["a"] = a;
  out["b"] = b;
  out["target"] = target;
  out["edge"] = edge;
  out["visible_by"] = visibleByArray(segments, cameras);
  if (!team.empty()) out["team"] = py::array_t<std::int64_t>(n, team.data());
  return out;
}

py::object jsonToPython(const nlohmann::json& value) {
  return py::module_::import("json").attr("loads")(value.dump());
}

py::dict termsToDict(const reward::RewardTerms& terms) {
  py::dict d;
  d["coverage"] = terms.coverage;
  d["weightedCoverage"] = terms.weightedCoverage;
  d["utilization"] = terms.utilization;
  d["repulsion"] = terms.repulsion;
  d["reward"] = terms.reward;
  return d;
}

}  // namespace camcov::python
