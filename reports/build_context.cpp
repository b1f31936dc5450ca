#include "reports/build_context.h"

#include <fmt/format.h>

#include <unistd.h>

#include <array>
#include <ctime>
#include <fstream>
#include <thread>

namespace camcov::reports {
namespace {

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) break;
    const auto start = line.find_first_not_of(" \t", colon + 1);
    return start == std::string::npos ? std::string() : line.substr(start);
  }
  return {};
}

std::string hostname() {
  std::array<char, 256> name{};
  if (::gethostname(name.data(), name.size() - 1) != 0) return {};
  return name.data();
}

}  // namespace

BuildContext currentBuildContext() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  std::array<char, 32> date{};
  std::strftime(date.data(), date.size(), "%Y-%m-%d %H:%M UTC", &utc);
  return {date.data(), hostname(), cpuModel(), std::thread::hardware_concurrency()};
}

std::string machineDescription(const BuildContext& context) {
  return fmt::format("{} — {}, {} hardware threads", context.hostname,
                     context.cpuModel.empty() ? "CPU unknown" : context.cpuModel, context.cores);
}

}  // namespace camcov::reports
