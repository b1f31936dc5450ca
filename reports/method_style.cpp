#include "reports/method_style.h"

#include <algorithm>
#include <tuple>

namespace camcov::reports {
namespace {

int rank(std::string_view method) {
  if (method == "paper") return 0;
  if (method == "local") return 1;
  return 2;
}

}  // namespace

MethodStyle methodStyle(std::string_view method) {
  if (method == "paper") return {"paper (global + local)", "#ff7f0e"};
  if (method == "local") return {"local optimization", "#1f77b4"};
  return {method, "#7f7f7f"};
}

std::vector<std::string> orderedMethods(std::vector<std::string> methods) {
  std::sort(methods.begin(), methods.end(), [](const std::string& a, const std::string& b) {
    return std::make_tuple(rank(a), a) < std::make_tuple(rank(b), b);
  });
  return methods;
}

}  // namespace camcov::reports
