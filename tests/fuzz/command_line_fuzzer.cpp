// libFuzzer target: bytes -> the arguments of `camcov` (split at NUL bytes) -> the real
// application's parser (cli::addCommands, as main() builds it). Parsing must end in success
// or in one of CLI11's errors (which main() turns into exit 0 for --help and --version, 2
// otherwise); any other exception would escape main() and abort. No command's action runs.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "cli/command.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace camcov;
  std::vector<std::string> args{"camcov"};
  std::string current;
  for (std::size_t i = 0; i < size && args.size() < 32; ++i) {
    if (data[i] == 0) {
      args.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  if (args.size() < 32) args.push_back(current);
  std::vector<char*> argv;
  for (std::string& a : args)
    argv.push_back(a.data());
  // Built once: CLI11 clears what the previous input parsed before it parses the next, and
  // building the application anew costs more than parsing.
  static CLI::App app{"camcov"};
  static const auto commands = cli::addCommands(app);  // owns the variables options write to
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::Error&) {
    return 0;  // --help, --version or a parse error: main() says so and exits
  } catch (const std::exception& e) {
    std::fprintf(stderr, "command-line fuzzer: escaped the parser: %s\n", e.what());
    std::abort();
  }
  return 0;
}
