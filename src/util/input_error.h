#pragma once
// Bad input from a user (scene file, parameter file, command-line value). The CLI maps it to
// exit code 2; anything else escaping a command is an internal error (exit 1).
#include <stdexcept>
#include <string>

namespace camcov {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace camcov
