#include "control/methods.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "control/decentralized_controller.h"
#include "control/learned_controller.h"
#include "control/local_controller.h"
#include "control/paper_controller.h"
#include "util/input_error.h"

namespace camcov::control {
namespace {

// Built on first use, so registrations from other files' static initialization find it.
std::vector<Method>& table() {
  static std::vector<Method> all{
      {"paper", "paper (global + local)", "#ff7f0e", Role::method,
       [](const scene::Scene& s, const params::Parameters& p,
          std::uint64_t seed) -> std::unique_ptr<Controller> {
         return std::make_unique<PaperController>(s, p, seed);
       }},
      {"local", "local optimization", "#1f77b4", Role::baseline,
       [](const scene::Scene& s, const params::Parameters& p, std::uint64_t)
           -> std::unique_ptr<Controller> { return std::make_unique<LocalController>(s, p); }},
      {"camcov", "camcov (paper's loop: judged over a horizon, compass search)", "#9467bd",
       Role::method,
       [](const scene::Scene& s, const params::Parameters& p,
          std::uint64_t seed) -> std::unique_ptr<Controller> {
         return std::make_unique<PaperController>(s, p, seed, PaperController::Variant::Camcov);
       }},
      // Run when asked for by name: in the default batch it would change every published
      // batch's report and verdicts.
      {"camcov-dec", "camcov decentralized (each camera on its own knowledge)", "#637939",
       Role::example,
       [](const scene::Scene& s, const params::Parameters& p,
          std::uint64_t seed) -> std::unique_ptr<Controller> {
         return std::make_unique<DecentralizedController>(s, p, seed);
       }},
      {"learned", "learned (one shared policy, trained by scripts/train_learned.py)", "#7f7f7f",
       Role::example,
       [](const scene::Scene& s, const params::Parameters& p, std::uint64_t)
           -> std::unique_ptr<Controller> { return std::make_unique<LearnedController>(s, p); }},
  };
  return all;
}

}  // namespace

bool isMethodName(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  });
}

std::span<const Method> methods() {
  return table();
}

bool registerMethod(const Method& method) {
  if (!isMethodName(method.name))
    throw std::logic_error("method name '" + std::string(method.name) + "' is not [a-z0-9-]+");
  if (findMethod(method.name) != nullptr)
    throw std::logic_error("method '" + std::string(method.name) + "' registered twice");
  table().push_back(method);
  return true;
}

const Method* findMethod(std::string_view name) {
  for (const Method& m : table()) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

const Method& requireMethod(std::string_view name, std::span<const Method> extra) {
  for (const Method& m : extra) {
    if (m.name == name) return m;
  }
  if (const Method* m = findMethod(name)) return *m;
  std::string known;
  for (const Method& m : extra)
    known += (known.empty() ? "" : ", ") + m.name;
  for (const Method& m : table())
    known += (known.empty() ? "" : ", ") + m.name;
  throw InputError("unknown method '" + std::string(name) + "' (known: " + known + ")");
}

std::vector<std::string> defaultMethods() {
  std::vector<std::string> names;
  for (const Method& m : table()) {
    if (m.role != Role::example) names.emplace_back(m.name);
  }
  return names;
}

std::vector<std::string> inMethodOrder(std::vector<std::string> names) {
  const std::vector<Method>& all = table();
  const auto place = [&all](const std::string& name) {
    const auto row =
        std::find_if(all.begin(), all.end(), [&](const Method& m) { return m.name == name; });
    return std::make_pair(row - all.begin(), std::string_view(name));
  };
  std::sort(names.begin(), names.end(),
            [&](const std::string& a, const std::string& b) { return place(a) < place(b); });
  return names;
}

std::string referenceAmong(const std::vector<std::string>& methods) {
  for (const std::string& name : methods) {
    const Method* m = findMethod(name);
    if (m != nullptr && m->role == Role::baseline) return name;
  }
  return methods.front();
}

}  // namespace camcov::control
