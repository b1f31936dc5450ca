// `camcov generate`: it writes a scene `camcov validate` accepts, the same bytes for
// the same options, nothing at all for bad options (exit 2); and scripts/make_large_scenes.sh
// remakes the committed scenes/large/ to the byte.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

TEST(CliGenerate, WritesTheSceneAskedForThatValidateAccepts) {
  const ScratchDir dir;
  const fs::path out = dir / "sub" / "crowd.json";
  const std::string options =
      "generate --targets 30 --cameras 6 --vertices 6 --field 60,40 --target-size 1.2,0.8 "
      "--loop 3 --target-speed 0.8 --camera-speed 2.5 --camera-turn 1.2 --fov 25 "
      "--clearance 1.5 --seed 9 --description 'thirty hexagons'";
  const auto r = runCamcov(options + " -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("30 target(s) of 6 vertices, 6 camera(s), seed 9"), std::string::npos)
      << r.out;
  const auto v = runCamcov("validate " + out.string());
  EXPECT_EQ(v.exitCode, 0) << v.out << v.err;
  const nlohmann::json scene = nlohmann::json::parse(readFile(out));
  EXPECT_EQ(scene["description"], "thirty hexagons");
  EXPECT_EQ(scene["boundary"], "POLYGON((-30 -20,30 -20,30 20,-30 20))");
  EXPECT_EQ(scene["cameraFoV"], 25.0);
  EXPECT_EQ(scene["targets"].size(), 30u);
  EXPECT_EQ(scene["targets"][0]["velocity"], 0.8);
  EXPECT_EQ(scene["cameras"].size(), 6u);
  EXPECT_EQ(scene["cameras"][0]["maxVelocity"], 2.5);
  EXPECT_EQ(scene["cameras"][0]["maxAngularVelocity"], 1.2);

  const fs::path again = dir / "again.json";
  ASSERT_EQ(runCamcov(options + " -o " + again.string()).exitCode, 0);
  EXPECT_EQ(readFile(again), readFile(out));
}

TEST(CliGenerate, BadOptionsExitTwoAndWriteNothing) {
  const ScratchDir dir;
  const fs::path out = dir / "scene.json";
  for (const std::string bad : {
           "--targets 0",
           "--cameras 129",
           "--vertices 2",
           "--field 30",
           "--field 30,-1",
           "--target-size 1,x",
           "--loop -1",
           "--fov 180",
           "--clearance -1",
           "--targets 500",  // too crowded for the default 30 x 30 m field
           "--vertices 100000 --target-size 0.01,0.01",
       }) {
    SCOPED_TRACE(bad);
    const auto r = runCamcov("generate " + bad + " -o " + out.string());
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_FALSE(r.err.empty());
    EXPECT_TRUE(fs::is_empty(dir.path())) << "a file was left behind";
  }
  EXPECT_EQ(runCamcov("generate --targets 3").exitCode, 2);  // no -o
}

TEST(CliGenerate, TheScriptRemakesTheCommittedLargeScenesToTheByte) {
  const ScratchDir dir;
  const fs::path script = fs::path(CAMCOV_SOURCE_DIR) / "scripts" / "make_large_scenes.sh";
  const auto r =
      runShell("bash " + script.string() + " " + dir.path().string() + " " + camcovBinary());
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const auto committed = jsonFilesIn(ownScenesDir() / "large");
  ASSERT_EQ(committed.size(), 3u);
  for (const auto& file : committed) {
    SCOPED_TRACE(file.string());
    EXPECT_EQ(readFile(dir / file.filename().string()), readFile(file));
  }
  const auto v = runCamcov("validate " + (ownScenesDir() / "large" / "*.json").string());
  EXPECT_EQ(v.exitCode, 0) << v.out << v.err;
}

// `camcov generate --family` (scene/scene_families.h): N validated scenes named by family and
// seed, the table with `--family list`; bad input exits 2 and leaves no folder behind.
TEST(GenerateFamilies, WritesCountScenesNamedByFamilyAndSeedThatValidateAccepts) {
  const ScratchDir dir;
  const fs::path out = dir / "l";
  const auto r = runCamcov("generate --family l_rooms --count 3 --seed 5 -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("3 scene(s) of family l_rooms, seeds 5 to 7 (tune seeds)"),
            std::string::npos)
      << r.out;
  const auto files = jsonFilesIn(out);
  ASSERT_EQ(files.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const std::string name = "l_rooms-" + std::to_string(5 + i) + ".json";
    EXPECT_EQ(files[i].filename(), name);
    const nlohmann::json scene = nlohmann::json::parse(readFile(files[i]));
    EXPECT_EQ(scene["description"].get<std::string>().rfind(
                  "family l_rooms seed " + std::to_string(5 + i) + ": L room", 0),
              0u)
        << scene["description"];
  }
  const auto v = runCamcov("validate " + (out / "*.json").string());
  EXPECT_EQ(v.exitCode, 0) << v.out << v.err;

  const fs::path again = dir / "again";
  ASSERT_EQ(runCamcov("generate --family l_rooms --count 1 --seed 6 -o " + again.string()).exitCode,
            0);
  EXPECT_EQ(readFile(again / "l_rooms-6.json"), readFile(out / "l_rooms-6.json"));
}

TEST(GenerateFamilies, ListPrintsEveryFamilyWithItsTuneAndTestSeeds) {
  for (const std::string option : {"--family list", "--list-families"}) {
    SCOPED_TRACE(option);
    const auto r = runCamcov("generate " + option);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* name : {"published_like", "l_rooms", "corridors", "deforming_targets"})
      EXPECT_NE(r.out.find(name), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("100001-101000"), std::string::npos) << r.out;
  }
}

TEST(GenerateFamilies, AnUnknownFamilyExitsTwoNamingTheKnownOnes) {
  const ScratchDir dir;
  const fs::path out = dir / "scenes";
  const auto r = runCamcov("generate --family l_room --count 3 -o " + out.string());
  EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("l_room"), std::string::npos) << r.err;
  for (const char* name : {"published_like", "l_rooms", "u_rooms", "big_teams"})
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(GenerateFamilies, BadCountsAMissingOutAndOptionsOfOneSceneExitTwo) {
  const ScratchDir dir;
  const fs::path out = dir / "scenes";
  for (const std::string& bad : std::vector<std::string>{
           "--family l_rooms --count 0 -o " + out.string(),
           "--family l_rooms --count 100001 -o " + out.string(),
           "--family l_rooms --count -1 -o " + out.string(),
           "--family l_rooms --count 3",  // no -o
           "--family l_rooms --targets 3 -o " + out.string(),
           "--family l_rooms --seed 18446744073709551615 --count 2 -o " + out.string(),
           "--count 3 -o " + (dir / "one.json").string(),  // --count without --family
       }) {
    SCOPED_TRACE(bad);
    const auto r = runCamcov("generate " + bad);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_FALSE(r.err.empty());
    EXPECT_TRUE(fs::is_empty(dir.path())) << "something was left behind";
  }
  const fs::path file = dir / "file";
  std::ofstream(file) << "x";
  const auto r = runCamcov("generate --family l_rooms -o " + file.string());
  EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
  EXPECT_EQ(readFile(file), "x");
}

}  // namespace
}  // namespace camcov::testing
