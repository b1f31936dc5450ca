#pragma once
// "1 scene", "2 scenes", "0 scenes": a count and its noun as a person writes them.
#include <cstddef>
#include <string>
#include <string_view>

namespace camcov {

inline std::string counted(std::size_t n, std::string_view one, std::string_view many) {
  return std::to_string(n) + " " + std::string(n == 1 ? one : many);
}

}  // namespace camcov
