#pragma once
// How each method looks in every figure and table, from the table of methods
// (control/methods.h); a method it does not know is grey.
#include <string>
#include <string_view>
#include <vector>

namespace camcov::reports {

struct MethodStyle {
  std::string_view label;  // for legends and table headers
  std::string_view color;  // CSS colour
};

MethodStyle methodStyle(std::string_view method);
// In the table's order, then any other, by name.
std::vector<std::string> orderedMethods(std::vector<std::string> methods);

}  // namespace camcov::reports
