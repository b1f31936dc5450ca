#include "reports/method_style.h"

#include <algorithm>
#include <tuple>

#include "control/methods.h"

namespace camcov::reports {
namespace {

// Position in the table of methods; methods it does not know (results of another version)
// come after, by name.
std::size_t rank(std::string_view method) {
  const auto all = control::methods();
  return static_cast<std::size_t>(
      std::find_if(all.begin(), all.end(), [&](const auto& m) { return m.name == method; }) -
      all.begin());
}

}  // namespace

MethodStyle methodStyle(std::string_view method) {
  if (const control::Method* m = control::findMethod(method)) return {m->description, m->color};
  return {method, "#7f7f7f"};
}

std::vector<std::string> orderedMethods(std::vector<std::string> methods) {
  std::sort(methods.begin(), methods.end(), [](const std::string& a, const std::string& b) {
    return std::make_tuple(rank(a), a) < std::make_tuple(rank(b), b);
  });
  return methods;
}

}  // namespace camcov::reports
