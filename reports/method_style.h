#pragma once
// How each method looks in every figure and table: the paper's Fig. 4 draws its own method
// orange and local optimization blue, and so do we.
#include <string>
#include <string_view>
#include <vector>

namespace camcov::reports {

struct MethodStyle {
  std::string_view label;  // for legends and table headers
  std::string_view color;  // CSS colour
};

MethodStyle methodStyle(std::string_view method);
// The paper's method first, then local optimization, then any other, by name.
std::vector<std::string> orderedMethods(std::vector<std::string> methods);

}  // namespace camcov::reports
