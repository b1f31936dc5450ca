// What a stage links, read from the camcov_add_stage() calls that declare it: a reader of
// results files (records) must not drag in the algorithms that made them, so that a tool
// reading results links none of the simulator, the methods or the geometry of visibility.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/scratch.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

// Stage name -> the camcov stages it names after DEPENDS, for every src/*/CMakeLists.txt.
std::map<std::string, std::vector<std::string>> stageDepends(const fs::path& root) {
  std::map<std::string, std::vector<std::string>> depends;
  const std::regex call(R"(camcov_add_stage\(\s*NAME\s+(\w+)([^)]*)\))");
  const std::regex dependency(R"(\bcamcov_(\w+))");
  for (const auto& entry : fs::directory_iterator(root / "src")) {
    std::ifstream in(entry.path() / "CMakeLists.txt");
    std::stringstream text;
    text << in.rdbuf();
    const std::string file = text.str();
    for (std::sregex_iterator m(file.begin(), file.end(), call), end; m != end; ++m) {
      const std::string body = (*m)[2];
      const auto at = body.find("DEPENDS");
      auto& list = depends[(*m)[1]];
      if (at == std::string::npos) continue;
      const std::string names = body.substr(at);
      for (std::sregex_iterator d(names.begin(), names.end(), dependency); d != end; ++d)
        list.push_back((*d)[1]);
    }
  }
  return depends;
}

// Every stage `stage` links, directly or through others.
std::set<std::string> linkedBy(const std::map<std::string, std::vector<std::string>>& depends,
                               const std::string& stage) {
  std::set<std::string> seen;
  std::vector<std::string> open{stage};
  while (!open.empty()) {
    const std::string next = open.back();
    open.pop_back();
    const auto it = depends.find(next);
    if (it == depends.end()) continue;
    for (const std::string& d : it->second) {
      if (seen.insert(d).second) open.push_back(d);
    }
  }
  return seen;
}

// The algorithm stages that `stage` links, comma-separated.
std::string algorithmsLinkedBy(const fs::path& root, const std::string& stage) {
  std::string found;
  for (const std::string& s : linkedBy(stageDepends(root), stage)) {
    for (const char* algorithm :
         {"kinematics", "visibility", "reward", "planners", "control", "safety", "sim"}) {
      if (s == algorithm) found += (found.empty() ? "" : ", ") + s;
    }
  }
  return found;
}

TEST(LinkTable, TheResultsStageLinksNoAlgorithm) {
  const auto depends = stageDepends(CAMCOV_SOURCE_DIR);
  ASSERT_TRUE(depends.count("records") && depends.count("sim") && depends.count("batch"))
      << "the stage declarations were not found";
  EXPECT_EQ(algorithmsLinkedBy(CAMCOV_SOURCE_DIR, "records"), "");
  // The batch stage runs runs, so it does link the simulator.
  EXPECT_TRUE(linkedBy(depends, "batch").count("sim"));
}

TEST(LinkTable, AnAlgorithmLinkedThroughAnotherStageIsFound) {
  const ScratchDir dir;
  for (const char* stage : {"records", "helpers", "sim"})
    fs::create_directories(dir / "src" / stage);
  std::ofstream(dir / "src" / "records" / "CMakeLists.txt")
      << "camcov_add_stage(NAME records SOURCES a.cpp\n  DEPENDS camcov_helpers fmt::fmt)\n";
  std::ofstream(dir / "src" / "helpers" / "CMakeLists.txt")
      << "camcov_add_stage(NAME helpers SOURCES b.cpp DEPENDS camcov_sim)\n";
  std::ofstream(dir / "src" / "sim" / "CMakeLists.txt")
      << "camcov_add_stage(NAME sim SOURCES c.cpp DEPENDS camcov_reward)\n";
  EXPECT_EQ(algorithmsLinkedBy(dir.path(), "records"), "reward, sim");
}

}  // namespace
}  // namespace camcov::testing
