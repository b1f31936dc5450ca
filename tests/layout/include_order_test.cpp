// The folders tell the story of the data, and a stage may only use what comes before it:
// no file of a stage includes a header of a stage after it. Linking catches a wrong-way
// call, not a wrong-way type (a struct needs no symbol), so the order is checked here, read
// from the CMake files that declare it: the top-level CMakeLists.txt and src/CMakeLists.txt.
// A front end built as a project of its own (the WebAssembly engine, src/wasm) comes last, and
// may include only the stages its CMakeLists.txt builds it from.
#include <gtest/gtest.h>

#include <algorithm>
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

// The first capture of `pattern` on each line of a file that matches it, in order.
std::vector<std::string> matches(const fs::path& file, const std::regex& pattern) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string text; std::getline(in, text);) {
    std::smatch m;
    if (std::regex_search(text, m, pattern)) out.push_back(m[1]);
  }
  return out;
}

// The add_subdirectory() arguments of a CMakeLists.txt, in order.
std::vector<std::string> subdirectories(const fs::path& cmakeLists) {
  return matches(cmakeLists, std::regex(R"(^\s*add_subdirectory\(([^)\s]+)\))"));
}

// The folders of the projects of their own a CMakeLists.txt builds (ExternalProject_Add's
// SOURCE_DIR ${PROJECT_SOURCE_DIR}/<folder>), in order.
std::vector<std::string> ownProjects(const fs::path& cmakeLists) {
  return matches(cmakeLists, std::regex(R"(^\s*SOURCE_DIR\s+\$\{PROJECT_SOURCE_DIR\}/(\S+))"));
}

// The stages a project of its own is built from: its `set(<NAME>_STAGES ...)`.
std::set<std::string> stagesBuiltFrom(const fs::path& cmakeLists) {
  std::set<std::string> stages;
  for (const std::string& list :
       matches(cmakeLists, std::regex(R"(^\s*set\(\w+_STAGES\s+([^)]*)\))"))) {
    std::istringstream words(list);
    for (std::string stage; words >> stage;)
      stages.insert(stage);
  }
  return stages;
}

// Stage folders (relative to the root) in data-flow order: "src" expands to its own list; the
// projects of their own come last.
std::vector<std::string> stageOrder(const fs::path& root) {
  std::vector<std::string> order;
  for (const std::string& dir : subdirectories(root / "CMakeLists.txt")) {
    if (dir == "tests") continue;
    if (dir == "src") {
      for (const std::string& stage : subdirectories(root / "src" / "CMakeLists.txt"))
        order.push_back("src/" + stage);
    } else {
      order.push_back(dir);
    }
  }
  for (const std::string& project : ownProjects(root / "CMakeLists.txt"))
    order.push_back(project);
  return order;
}

// Edges the order alone would allow but no stage may take: the CLI and Python are siblings
// (each calls the bench stage, neither the other), and no stage reads the tests' support code.
struct Sideways {
  const char* from;  // a stage folder, or "*" for every stage
  const char* to;    // the first folder of the include's path
};
constexpr Sideways kSideways[] = {{"src/python", "cli"}, {"src/cli", "python"}, {"*", "support"}};

// "file:line: <stage> includes <later stage>/..." for every wrong-way include under `root`,
// "file:line: <stage> includes <folder> sideways" for the edges of kSideways, and
// "file:line: <project> includes <stage>, which it is not built from" for a project of its own.
std::vector<std::string> wrongWayIncludes(const fs::path& root) {
  const std::vector<std::string> order = stageOrder(root);
  std::map<std::string, std::set<std::string>> builtFrom;  // of each project of its own
  for (const std::string& project : ownProjects(root / "CMakeLists.txt"))
    builtFrom[project] = stagesBuiltFrom(root / project / "CMakeLists.txt");
  std::map<std::string, std::size_t> rank;  // by the name used in includes: "control", "viz"
  for (std::size_t i = 0; i < order.size(); ++i)
    rank[fs::path(order[i]).filename().string()] = i;
  const std::regex include(R"(^\s*#\s*include\s*"([a-z_]+)/)");
  std::vector<std::string> found;
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (const auto& entry : fs::recursive_directory_iterator(root / order[i])) {
      const auto ext = entry.path().extension();
      if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
      // A stage's benchmark programs (viz/bench/) are programs beside it, not part of it: they
      // may share the tests' support code.
      const bool benchmarkProgram =
          fs::relative(entry.path(), root / order[i]).string().rfind("bench/", 0) == 0;
      std::ifstream in(entry.path());
      int number = 0;
      for (std::string text; std::getline(in, text);) {
        ++number;
        std::smatch m;
        if (!std::regex_search(text, m, include)) continue;
        for (const Sideways& edge : kSideways) {
          if ((std::string(edge.from) == "*" || order[i] == edge.from) && m[1] == edge.to &&
              !benchmarkProgram) {
            found.push_back(fs::relative(entry.path(), root).string() + ":" +
                            std::to_string(number) + ": " + order[i] + " includes " + edge.to +
                            " sideways (" + text + ")");
          }
        }
        const auto it = rank.find(m[1]);
        const auto project = builtFrom.find(order[i]);
        if (it != rank.end() && project != builtFrom.end() && !project->second.contains(m[1])) {
          found.push_back(fs::relative(entry.path(), root).string() + ":" + std::to_string(number) +
                          ": " + order[i] + " includes " + order[it->second] +
                          ", which it is not built from (" + text + ")");
        } else if (it != rank.end() && it->second > i) {
          found.push_back(fs::relative(entry.path(), root).string() + ":" + std::to_string(number) +
                          ": " + order[i] + " includes " + order[it->second] + " (" + text + ")");
        }
      }
    }
  }
  return found;
}

// A planted tree's file, its folders made.
void writeFile(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

TEST(IncludeOrder, TheTreeReadsTheStagesInOrder) {
  const fs::path root = CAMCOV_SOURCE_DIR;
  const std::vector<std::string> order = stageOrder(root);
  ASSERT_GE(order.size(), 10u) << "the stage lists were not found";
  EXPECT_EQ(order.front(), "src/geometry");
  ASSERT_GE(order.size(), 3u);
  EXPECT_EQ(order[order.size() - 3], "src/cli") << "the programs wire everything: they come last";
  EXPECT_EQ(order[order.size() - 2], "src/python");
  EXPECT_EQ(order.back(), "src/wasm") << "the engine, a project of its own, is checked too";
  std::string report;
  for (const std::string& line : wrongWayIncludes(root))
    report += line + "\n";
  EXPECT_TRUE(report.empty()) << "wrong-way includes:\n" << report;
}

TEST(IncludeOrder, APlantedWrongWayIncludeIsFound) {
  const ScratchDir dir;
  const fs::path root = dir.path();
  const auto write = [&](const fs::path& file, const std::string& text) {
    writeFile(root / file, text);
  };
  write("CMakeLists.txt",
        "add_subdirectory(src)\nadd_subdirectory(viz)\nadd_subdirectory(tests)\n");
  write("src/CMakeLists.txt", "add_subdirectory(geometry)\nadd_subdirectory(planners)\n");
  write("src/geometry/ring.h", "#include \"geometry/vec2.h\"\n");
  write("src/planners/plan.h", "#include \"geometry/ring.h\"\n");
  write("viz/frame.h", "#include \"planners/plan.h\"\n");
  EXPECT_TRUE(wrongWayIncludes(root).empty());
  write("src/geometry/vec2.h", "#pragma once\n  #include \"viz/frame.h\"\n");
  const auto found = wrongWayIncludes(root);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].rfind("src/geometry/vec2.h:2: src/geometry includes viz", 0), 0u) << found[0];
}

TEST(IncludeOrder, APlantedSidewaysIncludeIsFound) {
  const ScratchDir dir;
  const fs::path root = dir.path();
  const auto write = [&](const fs::path& file, const std::string& text) {
    writeFile(root / file, text);
  };
  write("CMakeLists.txt",
        "add_subdirectory(src)\nadd_subdirectory(src/cli)\n"
        "add_subdirectory(src/python)\n");
  write("src/CMakeLists.txt", "add_subdirectory(bench)\n");
  write("src/bench/run.h", "#pragma once\n");
  write("src/cli/main.cpp", "#include \"bench/run.h\"\n");
  write("src/python/module.cpp", "#include \"bench/run.h\"\n");
  EXPECT_TRUE(wrongWayIncludes(root).empty());
  // Later in the order, so allowed by it, but a front end reaching into the other.
  write("src/python/module.cpp", "#include \"bench/run.h\"\n#include \"cli/command.h\"\n");
  write("src/bench/run.h", "#pragma once\n#include \"support/scratch.h\"\n");
  auto found = wrongWayIncludes(root);
  std::sort(found.begin(), found.end());
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].rfind("src/bench/run.h:2: src/bench includes support sideways", 0), 0u)
      << found[0];
  EXPECT_EQ(found[1].rfind("src/python/module.cpp:2: src/python includes cli sideways", 0), 0u)
      << found[1];
}

TEST(IncludeOrder, AnEngineIncludeOfAStageItIsNotBuiltFromIsFound) {
  const ScratchDir dir;
  const fs::path root = dir.path();
  const auto write = [&](const fs::path& file, const std::string& text) {
    writeFile(root / file, text);
  };
  write("CMakeLists.txt",
        "add_subdirectory(src)\nExternalProject_Add(engine\n"
        "  SOURCE_DIR ${PROJECT_SOURCE_DIR}/src/wasm\n  BINARY_DIR wasm)\n");
  write("src/CMakeLists.txt", "add_subdirectory(scene)\nadd_subdirectory(planners)\n");
  write("src/wasm/CMakeLists.txt", "set(CAMCOV_ENGINE_STAGES scene)\n");
  write("src/scene/scene.h", "#pragma once\n");
  write("src/planners/plan.h", "#pragma once\n");
  write("src/wasm/engine.cpp", "#include \"scene/scene.h\"\n");
  EXPECT_TRUE(wrongWayIncludes(root).empty());
  // Before the engine in the order, but not among the stages it is compiled from.
  write("src/wasm/engine.cpp", "#include \"scene/scene.h\"\n#include \"planners/plan.h\"\n");
  const auto found = wrongWayIncludes(root);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].rfind("src/wasm/engine.cpp:2: src/wasm includes src/planners, which it is "
                           "not built from",
                           0),
            0u)
      << found[0];
}

}  // namespace
}  // namespace camcov::testing
