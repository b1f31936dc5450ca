#include "control/methods.h"

#include <array>
#include <string>

#include "control/local_controller.h"
#include "control/paper_controller.h"
#include "util/input_error.h"

namespace camcov::control {
namespace {

constexpr std::array kMethods{
    Method{"paper", "paper (global + local)", "#ff7f0e", false,
           [](const scene::Scene& s, const params::Parameters& p,
              std::uint64_t seed) -> std::unique_ptr<Controller> {
             return std::make_unique<PaperController>(s, p, seed);
           }},
    Method{"local", "local optimization", "#1f77b4", true,
           [](const scene::Scene& s, const params::Parameters& p, std::uint64_t)
               -> std::unique_ptr<Controller> { return std::make_unique<LocalController>(s, p); }},
};

}  // namespace

std::span<const Method> methods() {
  return kMethods;
}

const Method* findMethod(std::string_view name) {
  for (const Method& m : kMethods) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

const Method& requireMethod(std::string_view name) {
  if (const Method* m = findMethod(name)) return *m;
  std::string known;
  for (const Method& m : kMethods)
    known += (known.empty() ? "" : ", ") + std::string(m.name);
  throw InputError("unknown method '" + std::string(name) + "' (known: " + known + ")");
}

std::string referenceAmong(const std::vector<std::string>& methods) {
  for (const std::string& name : methods) {
    const Method* m = findMethod(name);
    if (m != nullptr && m->baseline) return name;
  }
  return methods.front();
}

}  // namespace camcov::control
