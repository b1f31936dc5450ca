#pragma once
// JSON has no infinity: a distance that is undefined (no object, a single camera) is written
// as null and read back as infinity. One pair, used by every results format.
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

namespace camcov::records {

inline nlohmann::json finiteOrNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

inline double numberOrInfinity(const nlohmann::json& v) {
  return v.is_null() ? std::numeric_limits<double>::infinity() : v.get<double>();
}

}  // namespace camcov::records
