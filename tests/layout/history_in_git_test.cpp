// History lives in git: no code, comment, help text, script or document of the tree names the
// tracker's issues by number, which mean nothing to a reader without the tracker.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "support/scratch.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

// "file:line: text" for every line under `root` that names an issue by number.
std::string issueNumbers(const fs::path& root) {
  const std::regex number(R"(\bissues?\s+#?[0-9]+)", std::regex::icase);
  std::string found;
  const auto scan = [&](const fs::path& file) {
    const std::string ext = file.extension().string();
    if (ext != ".h" && ext != ".cpp" && ext != ".py" && ext != ".js" && ext != ".sh" &&
        ext != ".md" && ext != ".txt" && ext != ".css" && ext != ".html" && ext != ".json" &&
        ext != ".toml" && file.filename() != "run")
      return;
    std::ifstream in(file);
    int line = 0;
    for (std::string text; std::getline(in, text);) {
      ++line;
      if (std::regex_search(text, number))
        found +=
            fs::relative(file, root).string() + ":" + std::to_string(line) + ": " + text + "\n";
    }
  };
  for (const char* top :
       {"src", "viz", "reports", "tests", "examples", "scripts", "docs", "scenes", ".ci"}) {
    if (!fs::exists(root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (entry.is_regular_file()) scan(entry.path());
    }
  }
  for (const char* file : {"README.md", "CMakeLists.txt"}) {
    if (fs::exists(root / file)) scan(root / file);
  }
  return found;
}

TEST(HistoryInGit, NoFileOfTheTreeNamesAnIssueNumber) {
  EXPECT_EQ(issueNumbers(CAMCOV_SOURCE_DIR), "");
}

TEST(HistoryInGit, APlantedIssueNumberIsFound) {
  const ScratchDir dir;
  fs::create_directories(dir / "src" / "sim");
  // Spelled in two pieces, so that this file does not name one itself.
  std::ofstream(dir / "src" / "sim" / "a.h") << "// the step\n// as Iss"
                                                "ue 7 asked\n";
  EXPECT_EQ(issueNumbers(dir.path()),
            "src/sim/a.h:2: // as Iss"
            "ue 7 asked\n");
  // A scene's description and the README are read too.
  fs::create_directories(dir / "scenes");
  std::ofstream(dir / "scenes" / "s.json") << "{\"description\": \"for iss"
                                              "ues #12\"}\n";
  std::ofstream(dir / "README.md") << "see Iss"
                                      "ue 3\n";
  const std::string found = issueNumbers(dir.path());
  EXPECT_NE(found.find("scenes/s.json:1:"), std::string::npos) << found;
  EXPECT_NE(found.find("README.md:1:"), std::string::npos) << found;
}

}  // namespace
}  // namespace camcov::testing
