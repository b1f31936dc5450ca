#pragma once
// The table of methods: the one place that knows which methods exist. A method is a name (in
// files and on the command line), what it is, its colour in every figure, and how to make its
// controller. Adding a method is one controller file plus one row in methods.cpp; the batch,
// the summary's tables and the report take it from here.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "control/controller.h"
#include "params/parameters.h"
#include "scene/scene.h"

namespace camcov::control {

struct Method {
  std::string_view name;         // "paper": in results file names, --method, --methods
  std::string_view description;  // for legends and tables
  std::string_view color;        // CSS colour in every figure (the paper's Fig. 4 colours)
  bool baseline;                 // what the others are compared with by default
  // The controller of one run. It may keep a reference to `scene`, which outlives it.
  std::unique_ptr<Controller> (*make)(const scene::Scene& scene, const params::Parameters& params,
                                      std::uint64_t seed);
};

// Every method, in the order figures and tables list them.
std::span<const Method> methods();
// The method called `name`, or nullptr.
const Method* findMethod(std::string_view name);
// The same, or InputError naming the known methods.
const Method& requireMethod(std::string_view name);
// What a batch of these methods compares the others with: the first baseline among them,
// else the first of them. `methods` must not be empty.
std::string referenceAmong(const std::vector<std::string>& methods);

}  // namespace camcov::control
