#pragma once
// The table of methods: the one place that knows which methods exist. A method is a name (in
// files and on the command line), what it is, its colour in every figure, its role, and how
// to make its controller. The built-in methods are the rows of methods.cpp; a method defined
// elsewhere (examples/) registers itself with one line,
//
//   const bool kRegistered = camcov::control::registerMethod({"name", ..., &make});
//
// in its own file, compiled into an object library that the programs link (examples/
// CMakeLists.txt). The batch, the summary's tables and the report take every method from here.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "control/controller.h"
#include "params/parameters.h"
#include "scene/scene.h"

namespace camcov::control {

enum class Role {
  method,    // in the default batch
  baseline,  // in the default batch, and what the others are compared with by default
  example,   // run only when asked for by name (--methods)
};

// The controller of one run: the scene (which outlives it), the run's parameters, and the seed
// of the run's own random generator. Called from the batch's worker threads.
using MakeController = std::function<std::unique_ptr<Controller>(
    const scene::Scene& scene, const params::Parameters& params, std::uint64_t seed)>;

struct Method {
  std::string name;         // "paper": in results file names, --method, --methods
  std::string description;  // for legends and tables
  std::string color;        // CSS colour in every figure (the paper's Fig. 4 colours)
  Role role = Role::method;
  MakeController make;
  // What makes its results, for a batch's resume: empty for a method compiled into this build
  // (its identity is the build's code, util/code_identity.h); a fingerprint of the code for a
  // method brought from elsewhere (Python's).
  std::string identity = {};
};

// Every method: the built-in rows in order, then registered ones in registration order.
std::span<const Method> methods();
// Adds a method defined outside src/control (static initialization of its own file). Returns
// true, to initialize a constant with; std::logic_error if the name is taken or not a
// method name. Not for use while a batch runs: the table is read without a lock.
bool registerMethod(const Method& method);
// A name can be a method's: [a-z0-9-]+, as it goes into file names.
bool isMethodName(std::string_view name);
// The method called `name`, or nullptr.
const Method* findMethod(std::string_view name);
// The method called `name` among `extra` (methods a caller brings for one batch, such as
// Python's) and then the table, or InputError naming the known methods.
const Method& requireMethod(std::string_view name, std::span<const Method> extra = {});
// The methods a batch runs when not told which: every one but the examples.
std::vector<std::string> defaultMethods();
// `names` in the one order of methods wherever several are listed (the summary's rows, the
// CLI's columns, the report's tables, figures and videos): the table's, the built-in rows then
// registered ones; names it does not know (a Python controller's, one of another version)
// after them, by name.
std::vector<std::string> inMethodOrder(std::vector<std::string> names);
// What a batch of these methods compares the others with: the first baseline among them,
// else the first of them. `methods` must not be empty.
std::string referenceAmong(const std::vector<std::string>& methods);

}  // namespace camcov::control
