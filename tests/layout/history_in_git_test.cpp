// History lives in git: no code, comment, help text, script or document of the tree names the
// tracker's issues by number, which mean nothing to a reader without the tracker.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "support/scratch.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

// A line's words without what only continues a comment or a string onto it: leading blanks,
// comment leaders (//, #, *, --) and quotes, so that a number split from its "issue" by a
// line break reads as one phrase.
std::string continuation(const std::string& text) {
  const std::regex leader(R"(^\s*(//+|#+|\*+|--|"|')?\s*)");
  return std::regex_replace(text, leader, "", std::regex_constants::format_first_only);
}

// "file:line: text" for every line under `root` where an issue is named by number (the line
// where "issue" stands, also when its number is on the next line).
std::string issueNumbers(const fs::path& root) {
  const std::regex number(R"(\bissues?\s*["']?\s+#?[0-9]+)", std::regex::icase);
  std::string found;
  const auto scan = [&](const fs::path& file) {
    const std::string ext = file.extension().string();
    if (ext != ".h" && ext != ".cpp" && ext != ".py" && ext != ".js" && ext != ".sh" &&
        ext != ".md" && ext != ".txt" && ext != ".css" && ext != ".html" && ext != ".json" &&
        ext != ".toml" && file.filename() != "run")
      return;
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string text; std::getline(in, text);)
      lines.push_back(text);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      // The line, and the start of the next one as its continuation.
      const std::string next = i + 1 < lines.size() ? continuation(lines[i + 1]) : "";
      const std::string joined = lines[i] + " " + next.substr(0, 16);
      std::smatch m;
      if (std::regex_search(joined, m, number) &&
          static_cast<std::size_t>(m.position(0)) < lines[i].size()) {
        found += fs::relative(file, root).string() + ":" + std::to_string(i + 1) + ": " + lines[i] +
                 "\n";
      }
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

TEST(HistoryInGit, AnIssueNumberSplitOverALineBreakIsFound) {
  const ScratchDir dir;
  fs::create_directories(dir / "src" / "cli");
  std::ofstream(dir / "src" / "cli" / "a.cpp") << "// a seeded scene (iss"
                                                  "ue\n// 23; the generator)\n";
  std::ofstream(dir / "src" / "cli" / "b.cpp") << "help(\"as iss"
                                                  "ue \"\n    \"#4 asked\");\n";
  std::ofstream(dir / "src" / "cli" / "c.cpp") << "// an issue\n// of taste, not 5 numbers\n";
  EXPECT_EQ(issueNumbers(dir.path() / "src" / "cli" / ".." / ".."),
            "src/cli/a.cpp:1: // a seeded scene (iss"
            "ue\n"
            "src/cli/b.cpp:1: help(\"as iss"
            "ue \"\n")
      << "c.cpp's next line starts with a word, not a number";
}

}  // namespace
}  // namespace camcov::testing
