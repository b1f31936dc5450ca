#include "reports/summary_reader.h"

#include <fstream>
#include <limits>

#include "util/input_error.h"

namespace camcov::reports {
namespace {

records::Description describedFrom(const nlohmann::json& j) {
  return {j.at("count").get<int>(),  j.at("mean").get<double>(), j.at("sd").get<double>(),
          j.at("min").get<double>(), j.at("q1").get<double>(),   j.at("median").get<double>(),
          j.at("q3").get<double>(),  j.at("max").get<double>()};
}

// The summary writes an undefined distance (no object, a single camera) as null.
double numberOrInfinity(const nlohmann::json& v) {
  return v.is_null() ? std::numeric_limits<double>::infinity() : v.get<double>();
}

}  // namespace

records::BatchSummary summaryFromJson(const nlohmann::json& j, const std::string& source) {
  try {
    if (j.at("format") != "camcov-summary/2") {
      throw InputError(source + ": not a camcov summary (format camcov-summary/2)");
    }
    records::BatchSummary s;
    for (const auto& m : j.at("methods")) {
      records::MethodSummary ms;
      ms.scene = m.at("scene").get<std::string>();
      ms.method = m.at("method").get<std::string>();
      ms.runs = m.at("runs").get<int>();
      ms.failed = m.at("failed").get<int>();
      ms.coverage = describedFrom(m.at("averageCoverage"));
      ms.utilization = describedFrom(m.at("averageUtilization"));
      ms.meanObjectCollisionTime = m.at("meanObjectCollisionTime").get<double>();
      ms.meanCameraCollisionTime = m.at("meanCameraCollisionTime").get<double>();
      ms.runsWithCollision = m.at("runsWithCollision").get<int>();
      ms.meanAvoidableContactTime = m.at("meanAvoidableContactTime").get<double>();
      ms.meanUnavoidableContactTime = m.at("meanUnavoidableContactTime").get<double>();
      ms.runsWithAvoidableContact = m.at("runsWithAvoidableContact").get<int>();
      ms.runsWithUnavoidableContact = m.at("runsWithUnavoidableContact").get<int>();
      ms.minObjectDistance = numberOrInfinity(m.at("minObjectDistance"));
      ms.minCameraDistance = numberOrInfinity(m.at("minCameraDistance"));
      ms.medianSeed = m.at("medianSeed").get<std::uint64_t>();
      ms.bestSeed = m.at("bestSeed").get<std::uint64_t>();
      s.methods.push_back(std::move(ms));
    }
    for (const auto& c : j.at("scenes")) {
      s.scenes.push_back({c.at("scene").get<std::string>(), c.at("winner").get<std::string>(),
                          c.at("pValue").get<double>(), c.at("exactTest").get<bool>(),
                          c.at("meanCoverageDifference").get<double>()});
    }
    const auto& totals = j.at("totals");
    s.paperWins = totals.at("paperWins").get<int>();
    s.ties = totals.at("ties").get<int>();
    s.localWins = totals.at("localWins").get<int>();
    for (const auto& f : j.at("failures")) {
      s.failures.push_back({f.at("scene").get<std::string>(),
                            f.at("method").get<std::string>(),
                            f.at("seed").get<std::uint64_t>(),
                            true,
                            f.at("error").get<std::string>(),
                            {}});
    }
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source + ": malformed summary: " + e.what());
  }
}

records::BatchSummary loadSummaryFile(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot open the batch summary");
  try {
    return summaryFromJson(nlohmann::json::parse(in), file.string());
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file.string() + ": invalid JSON: " + e.what());
  }
}

}  // namespace camcov::reports
