#include "reports/method_style.h"

#include <array>

#include <fmt/format.h>

#include "control/methods.h"
#include "util/fnv1a.h"

namespace camcov::reports {
namespace {

thread_local const std::map<std::string, records::MethodLook>* broughtLooks = nullptr;

}  // namespace

BroughtMethodLooks::BroughtMethodLooks(const std::map<std::string, records::MethodLook>& looks)
    : previous_(broughtLooks) {
  broughtLooks = &looks;
}

BroughtMethodLooks::~BroughtMethodLooks() {
  broughtLooks = previous_;
}

MethodStyle methodStyle(std::string_view method) {
  if (const control::Method* m = control::findMethod(method)) return {m->description, m->color};
  const records::MethodLook* look = nullptr;
  if (broughtLooks != nullptr) {
    if (const auto it = broughtLooks->find(std::string(method)); it != broughtLooks->end())
      look = &it->second;
  }
  // The rest of the Tableau 10 palette the table's colours come from.
  static constexpr std::array<std::string_view, 5> kOthers{"#d62728", "#8c564b", "#e377c2",
                                                           "#bcbd22", "#17becf"};
  const std::string_view color = kOthers[fnv1a(method) % kOthers.size()];
  if (look == nullptr) return {method, color};
  return {look->description.empty() ? method : std::string_view(look->description),
          look->color.empty() ? color : std::string_view(look->color)};
}

std::string methodMark(std::string_view color, std::string_view html) {
  return fmt::format(
      "<span class=\"method-mark\"><span class=\"method-dot\" style=\"--c:{}\"></span>{}</span>",
      color, html);
}

}  // namespace camcov::reports
