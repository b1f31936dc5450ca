#pragma once
// Runs the camcov executable (path from CAMCOV_BINARY, set by CTest) for end-to-end tests.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace camcov::testing {

struct CommandResult {
  int exitCode = -1;
  std::string out;  // standard output
  std::string err;  // standard error
};

inline std::string camcovBinary() {
  const char* binary = std::getenv("CAMCOV_BINARY");
  EXPECT_NE(binary, nullptr) << "CAMCOV_BINARY is not set (run through ctest)";
  return binary == nullptr ? std::string("false") : std::string(binary);
}

// Runs a shell command line; its stdout and stderr are captured apart.
inline CommandResult runShell(const std::string& commandLine) {
  const auto errFile = std::filesystem::temp_directory_path() /
                       ("camcov_test_err_" + std::to_string(::getpid()) + ".txt");
  const std::string command = "( " + commandLine + " ) 2>" + errFile.string() + " </dev/null";
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(errFile);
  std::stringstream text;
  text << err.rdbuf();
  result.err = text.str();
  std::filesystem::remove(errFile);
  return result;
}

inline CommandResult runCamcov(const std::string& arguments) {
  return runShell(camcovBinary() + " " + arguments);
}

}  // namespace camcov::testing
