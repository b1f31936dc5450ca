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
  for (const char* top : {"src", "viz", "reports", "tests", "examples", "scripts", "docs"}) {
    if (!fs::exists(root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() ||
          (ext != ".h" && ext != ".cpp" && ext != ".py" && ext != ".js" && ext != ".sh" &&
           ext != ".md" && ext != ".txt" && ext != ".css" && ext != ".html"))
        continue;
      std::ifstream in(entry.path());
      int line = 0;
      for (std::string text; std::getline(in, text);) {
        ++line;
        if (std::regex_search(text, number))
          found += fs::relative(entry.path(), root).string() + ":" + std::to_string(line) + ": " +
                   text + "\n";
      }
    }
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
}

}  // namespace
}  // namespace camcov::testing
