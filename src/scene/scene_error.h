#pragma once
#include <string>

#include "util/input_error.h"

namespace camcov::scene {

// A scene file problem, located by file and JSON path, e.g.
//   "scenes/x.json: targets[2].shape: ring intersects itself (edges 0 and 2)".
class SceneError : public InputError {
 public:
  SceneError(const std::string& file, const std::string& jsonPath, const std::string& problem)
      : InputError(file + ": " + (jsonPath.empty() ? std::string("(top level)") : jsonPath) + ": " +
                   problem),
        jsonPath_(jsonPath),
        problem_(problem) {}
  const std::string& jsonPath() const { return jsonPath_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string jsonPath_;
  std::string problem_;
};

}  // namespace camcov::scene
