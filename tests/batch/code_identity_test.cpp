// A C++ method rebuilt from changed code has another identity, so a resume refuses its old
// results: the identity is the hash cmake/code_identity.cmake takes of the run-making sources,
// run here on files of the test's own.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <regex>

#include "support/scratch.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

// The identity the build script computes for the files listed, as code_identity.cpp has it.
std::string identityOf(const fs::path& dir, const std::vector<fs::path>& files) {
  std::string list;
  for (const auto& f : files) {
    if (!list.empty()) list += ';';
    list += f.string();
  }
  std::ofstream(dir / "list.txt") << list;
  const fs::path out = dir / "identity.cpp";
  const std::string command = std::string(CAMCOV_CMAKE) + " -DROOT=" + dir.string() +
                              " -DLIST=" + (dir / "list.txt").string() + " -DOUT=" + out.string() +
                              " -P " + CAMCOV_SOURCE_DIR + "/cmake/code_identity.cmake";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  std::smatch m;
  const std::string text = readFile(out);
  EXPECT_TRUE(std::regex_search(text, m, std::regex("return \"([0-9a-f]{16})\"")));
  return m.size() > 1 ? m[1].str() : "";
}

TEST(CodeIdentity, ChangesWithAnyRunMakingSourceAndOnlyWithThem) {
  const ScratchDir dir;
  fs::create_directories(dir / "src");
  const fs::path a = dir / "src" / "method.cpp", b = dir / "src" / "helper.h";
  std::ofstream(a) << "double gain() { return 0.5; }\n";
  std::ofstream(b) << "#pragma once\n";
  const std::string first = identityOf(dir.path(), {a, b});
  ASSERT_EQ(first.size(), 16u);
  EXPECT_EQ(identityOf(dir.path(), {b, a}), first) << "the order of the list does not matter";
  std::ofstream(a) << "double gain() { return 0.6; }\n";  // the method rebuilt from changed code
  const std::string changed = identityOf(dir.path(), {a, b});
  EXPECT_NE(changed, first);
  std::ofstream(a) << "double gain() { return 0.5; }\n";
  EXPECT_EQ(identityOf(dir.path(), {a, b}), first) << "the same sources, the same identity";
}

}  // namespace
}  // namespace camcov::testing
