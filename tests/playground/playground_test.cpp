// `camcov playground`: one offline page holding the engine, the scene as written and the
// page's script, nothing fetched, under 3 MB; bad input refused with exit 2 and no page.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

TEST(Playground, IsOneOfflinePageWithTheEngineAndTheSceneUnder3MB) {
  const ScratchDir dir;
  const fs::path out = dir / "page.html";
  const auto r = runCamcov("playground " + (ownScenesDir() / "fig1_example.json").string() +
                           " --time 2 -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string page = readFile(out);
  EXPECT_LT(fs::file_size(out), 3u * 1000 * 1000);
  EXPECT_NE(page.find("createCamcovEngine"), std::string::npos) << "the engine is in the page";
  EXPECT_NE(page.find("\"file\":\"fig1_example.json\""), std::string::npos);
  EXPECT_NE(page.find("\"time\":2.0"), std::string::npos);
  EXPECT_NE(page.find("default-src 'none'"), std::string::npos);
  // No element that loads anything (the SVG namespace's "http://" names, it fetches nothing).
  for (const char* loads : {"https://", "src=\"", "<link", "<iframe", "<img"})
    EXPECT_EQ(page.find(loads), std::string::npos) << loads;
}

TEST(Playground, BadInputExitsTwoAndWritesNothing) {
  const ScratchDir dir;
  const fs::path out = dir / "page.html";
  const std::string scene = (ownScenesDir() / "fig1_example.json").string();
  const struct {
    std::string arguments, words;
  } cases[] = {
      {(testDataDir() / "bad" / "weights_negative.json").string(), "edgeWeights[1]"},
      {scene + " --engine " + (dir / "missing.js").string(), "the WebAssembly engine is not there"},
      {scene + " --time -1", "--time"},
  };
  for (const auto& c : cases) {
    const auto r = runCamcov("playground " + c.arguments + " -o " + out.string());
    EXPECT_EQ(r.exitCode, 2) << c.arguments;
    EXPECT_NE((r.out + r.err).find(c.words), std::string::npos) << r.out << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.arguments;
  }
  const auto wrongName = runCamcov("playground " + scene + " -o " + (dir / "page.txt").string());
  EXPECT_EQ(wrongName.exitCode, 2);
}

}  // namespace
}  // namespace camcov::testing
