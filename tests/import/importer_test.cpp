// `camcov import` on the committed extracts (tests/data/tracks, sources named in its
// README): sample times and positions as the source rows say (read here independently),
// interpolation between them, people entering and leaving, the window, a track that comes back
// after a gap; every kind of bad input exits 2 naming the file and line and writes nothing;
// and every recording in ../shared/tracks imports, validates and runs with every method.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kTracks = testDataDir() / "tracks";

nlohmann::json importScene(const std::string& arguments, const fs::path& out) {
  const auto r = runCamcov("import " + arguments + " -o " + out.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(readFile(out));
}

// Reference position of the scene's target `i` at time t, as `camcov state` says.
std::vector<double> stateReference(const fs::path& scene, double t, std::size_t id) {
  const auto r = runCamcov("state " + scene.string() + " --time " + std::to_string(t));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json state = nlohmann::json::parse(r.out);
  for (const auto& target : state["targets"]) {
    if (target["id"] == id) return target["reference"].get<std::vector<double>>();
  }
  return {};
}

TEST(ImportLastRow, PlayersAreTeamColouredDiscsAtTheScaledRecordedPositions) {
  const ScratchDir dir;
  const fs::path out = dir / "football.json";
  const nlohmann::json scene =
      importScene("lastrow " + (kTracks / "lastrow_extract.csv").string() + " --cameras 2", out);
  // The source rows, read here: player 12 and 1214 (the ball, player 0, is left out).
  std::map<std::string, std::vector<std::array<double, 3>>> rows;
  std::ifstream csv(kTracks / "lastrow_extract.csv");
  std::string line;
  std::getline(csv, line);
  while (std::getline(csv, line)) {
    std::stringstream fields(line);
    std::string player, frame, x, y;
    std::getline(fields, player, ',');
    std::getline(fields, frame, ',');
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    if (player != "0")
      rows[player].push_back({std::stod(frame) / 20.0, std::stod(x) * 1.05, std::stod(y) * 0.68});
  }
  ASSERT_EQ(scene["targets"].size(), 2u);
  ASSERT_EQ(scene["cameras"].size(), 2u);
  const std::vector<std::string> order{"12", "1214"};  // both at t = 0: by id, as text
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& target = scene["targets"][i];
    EXPECT_EQ(target["color"], "#ff0000") << "bgcolor red";
    const auto& samples = target["track"]["samples"];
    const auto& expected = rows[order[i]];
    ASSERT_EQ(samples.size(), expected.size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
      EXPECT_NEAR(samples[k][0].get<double>(), expected[k][0], 1e-6);
      EXPECT_NEAR(samples[k][1].get<double>(), expected[k][1], 5e-4);
      EXPECT_NEAR(samples[k][2].get<double>(), expected[k][2], 5e-4);
    }
  }
  // Between two samples, on the straight line between them.
  const auto& s = scene["targets"][1]["track"]["samples"];
  const auto mid = stateReference(out, 0.125, 1);
  ASSERT_EQ(mid.size(), 2u);
  EXPECT_NEAR(mid[0], 0.5 * (s[2][1].get<double>() + s[3][1].get<double>()), 1e-9);
  EXPECT_NEAR(mid[1], 0.5 * (s[2][2].get<double>() + s[3][2].get<double>()), 1e-9);
  // The pitch and its 5 m run-off.
  EXPECT_EQ(scene["boundary"], "POLYGON((-5 -5,110 -5,110 73,-5 73))");
  EXPECT_EQ(scene["pitch"], (nlohmann::json{{"length", 105.0}, {"width", 68.0}}))
      << "for its markings";

  EXPECT_EQ(importScene("lastrow " + (kTracks / "lastrow_extract.csv").string() + " --ball target",
                        dir / "ball-target.json")["targets"]
                .size(),
            3u);
  const nlohmann::json ball =
      importScene("lastrow " + (kTracks / "lastrow_extract.csv").string() + " --ball obstacle",
                  dir / "ball.json");
  ASSERT_EQ(ball["obstacles"].size(), 1u);
  EXPECT_EQ(ball["obstacles"][0]["track"]["samples"].size(), 6u);
}

// Found by the importer fuzzer: every track one sample long made a window of no length, and the
// scene's "duration": 0 then failed its own loader.
TEST(ImportLastRow, ARecordingOfOneInstantImportsWithoutADurationOfItsOwn) {
  const ScratchDir dir;
  std::ifstream extract(kTracks / "lastrow_extract.csv");
  std::string header, row;
  std::getline(extract, header);
  while (std::getline(extract, row) && row.rfind("0,", 0) == 0) {
  }  // past the ball's rows: a player's first
  const fs::path csv = dir / "one_instant.csv";
  std::ofstream(csv) << header << "\n" << row << "\n";
  const auto r = runCamcov("import lastrow " + csv.string() + " -o " + (dir / "one.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("a single instant"), std::string::npos) << r.err;
  const nlohmann::json scene = nlohmann::json::parse(readFile(dir / "one.json"));
  EXPECT_FALSE(scene.contains("duration"));
  EXPECT_EQ(runCamcov("validate " + (dir / "one.json").string()).exitCode, 0);
}

TEST(ImportLastRow, PlayersHaveAFrontTheBallDoesNot) {
  const ScratchDir dir;
  const std::string csv = (kTracks / "lastrow_extract.csv").string();
  const nlohmann::json scene = importScene("lastrow " + csv + " --ball target", dir / "f.json");
  int fronts = 0;
  for (const auto& target : scene["targets"]) {
    if (!target.contains("frontWeight")) continue;
    EXPECT_EQ(target["frontWeight"], 2.0) << "the default";
    EXPECT_EQ(target["frontAngle"], 60.0);
    ++fronts;
  }
  EXPECT_EQ(fronts, 2) << "the two players, not the ball";
  const nlohmann::json chosen =
      importScene("lastrow " + csv + " --front-weight 5 --front-angle 30", dir / "g.json");
  EXPECT_EQ(chosen["targets"][0]["frontWeight"], 5.0);
  EXPECT_EQ(chosen["targets"][0]["frontAngle"], 30.0);
  const nlohmann::json none = importScene("lastrow " + csv + " --front-weight 1", dir / "h.json");
  EXPECT_FALSE(none["targets"][0].contains("frontWeight")) << "1: no front";
  const auto bad =
      runCamcov("import lastrow " + csv + " --front-angle 0 -o " + (dir / "i.json").string());
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_FALSE(fs::exists(dir / "i.json"));
}

TEST(ImportLastRow, CamerasComeAsARealRigHasThemUnlessTold) {
  const ScratchDir dir;
  const std::string csv = (kTracks / "lastrow_extract.csv").string();
  // Full HD over 2θ = 50°, 62.5 pixels per metre: a face-on edge is resolved up to
  // 1920 / (50° in radians) / 62.5 = 35.203 m, every camera's sensing range.
  const nlohmann::json scene = importScene("lastrow " + csv + " --fov 25", dir / "a.json");
  EXPECT_EQ(scene["resolution"], nlohmann::json({{"minDensity", 62.5}}));
  const double reach = std::round(1920.0 / (50.0 * std::acos(-1.0) / 180.0) / 62.5 * 1e3) / 1e3;
  for (const auto& camera : scene["cameras"]) {
    EXPECT_EQ(camera["imageWidth"], 1920.0);
    EXPECT_EQ(camera["sensingRange"], reach);
  }
  const nlohmann::json told = importScene(
      "lastrow " + csv + " --image-width 4000 --min-density 25 --sensing-range 50", dir / "b.json");
  EXPECT_EQ(told["resolution"]["minDensity"], 25.0);
  EXPECT_EQ(told["cameras"][0]["imageWidth"], 4000.0);
  EXPECT_EQ(told["cameras"][0]["sensingRange"], 50.0);
  // No image model, no range: the paper's cameras.
  const nlohmann::json plain =
      importScene("lastrow " + csv + " --image-width 0 --sensing-range 0", dir / "c.json");
  EXPECT_FALSE(plain.contains("resolution"));
  EXPECT_FALSE(plain["cameras"][0].contains("imageWidth"));
  EXPECT_FALSE(plain["cameras"][0].contains("sensingRange"));
  for (const char* bad : {"--image-width 19.5", "--min-density 0", "--sensing-range -1"}) {
    const auto r =
        runCamcov("import lastrow " + csv + " " + bad + " -o " + (dir / "d.json").string());
    EXPECT_EQ(r.exitCode, 2) << bad;
    EXPECT_FALSE(fs::exists(dir / "d.json"));
  }
}

TEST(ImportEthUcy, PedestriansEnterAndLeaveWallsBecomeObstaclesAndTheWindowCuts) {
  const ScratchDir dir;
  const fs::path out = dir / "zara.json";
  const std::string folder = (kTracks / "ethucy_extract").string();
  const nlohmann::json scene = importScene("ethucy " + folder + " --fps 25", out);
  ASSERT_EQ(scene["targets"].size(), 3u);
  EXPECT_EQ(scene["obstacles"].size(), 7u) << "the seven <Line> walls of map.xml";
  // Pedestrian 3 enters at frame 51 = 2 s; pedestrian 1 leaves after frame 81 = 3.2 s.
  EXPECT_NEAR(scene["targets"][2]["track"]["samples"][0][0].get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(scene["targets"][0]["track"]["samples"].back()[0].get<double>(), 3.2, 1e-9);
  // The first row of pedestrian 1: x = -2.829260, y (pos_y, the fifth number) = 18.95935.
  EXPECT_NEAR(scene["targets"][0]["track"]["samples"][0][1].get<double>(), -2.829, 1e-9);
  EXPECT_NEAR(scene["targets"][0]["track"]["samples"][0][2].get<double>(), 18.959, 1e-9);
  const auto ids = [&](double t) {
    const auto r = runCamcov("state " + out.string() + " --time " + std::to_string(t));
    std::vector<int> present;
    const nlohmann::json state = nlohmann::json::parse(r.out);
    for (const auto& target : state["targets"])
      present.push_back(target["id"]);
    return present;
  };
  EXPECT_EQ(ids(1.0), (std::vector<int>{0, 1}));
  EXPECT_EQ(ids(3.0), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(ids(4.0), (std::vector<int>{1, 2}));

  const nlohmann::json window =
      importScene("ethucy " + folder + " --fps 25 --from 3 --to 4", dir / "window.json");
  ASSERT_EQ(window["targets"].size(), 3u);
  EXPECT_NEAR(window["targets"][2]["track"]["samples"][0][0].get<double>(), 0.2, 1e-9)
      << "frame 81 = 3.2 s is 0.2 s into the window";
  // The window is how long a run of the scene lasts; without one, to the last sample (5.2 s).
  EXPECT_EQ(window["duration"], 1.0);
  EXPECT_EQ(scene["duration"], 5.2);
}

TEST(ImportEthUcy, TheBusiestWindowHasTheMostPeopleOnAverage) {
  // People present, counted every 0.1 s: 1 from 0 to 3.2 s, 2 from 0 to 5.2 s, 3 from 2 to
  // 5.2 s. Over 2 s windows starting on whole seconds: 40, 50, 53 and 43 counts: from 2 s.
  const ScratchDir dir;
  const auto r = runCamcov("import ethucy " + (kTracks / "ethucy_extract").string() +
                           " --fps 25 --busiest 2 -o " + (dir / "busy.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("the busiest 2 s: from 2 s to 4 s"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("3 targets over 2.0 s (at most 3 at once)"), std::string::npos) << r.out;
}

TEST(ImportEthUcy, ATrackThatComesBackAfterAGapIsANewTargetAndSaysSo) {
  const ScratchDir dir;
  fs::create_directories(dir / "gap");
  std::ofstream(dir / "gap" / "obsmat.txt") << "1 7 0 0 1 0 0 0\n11 7 1 0 1 0 0 0\n"
                                               "101 7 2 0 1 0 0 0\n111 7 3 0 1 0 0 0\n";
  const auto r = runCamcov("import ethucy " + (dir / "gap").string() + " --fps 25 -o " +
                           (dir / "gap.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("1 track vanishes for more than 1 s and comes back"), std::string::npos)
      << r.err;
  const auto scene = nlohmann::json::parse(readFile(dir / "gap.json"));
  ASSERT_EQ(scene["targets"].size(), 2u);
  EXPECT_NEAR(scene["targets"][1]["track"]["samples"][0][0].get<double>(), 4.0, 1e-9);
}

TEST(ImportEthUcy, OnePersonAndOneCameraAreCountedInTheSingular) {
  const ScratchDir dir;
  fs::create_directories(dir / "one");
  std::ofstream(dir / "one" / "obsmat.txt") << "1 7 0 0 1 0 0 0\n11 7 1 0 1 0 0 0\n";
  const auto r = runCamcov("import ethucy " + (dir / "one").string() + " --fps 25 --cameras 1 -o " +
                           (dir / "one.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find(": 1 target over 0.4 s (at most 1 at once), 0 obstacles, 1 camera\n"),
            std::string::npos)
      << r.out;
}

TEST(ImportEthUcy, WithoutFpsTheRateFollowsFromTheRecordedVelocities) {
  const ScratchDir dir;
  // The extract of UCY zara01: the velocities say 25 frames per second, the same file as
  // with --fps 25.
  const std::string folder = (kTracks / "ethucy_extract").string();
  const auto given =
      runCamcov("import ethucy " + folder + " --fps 25 -o " + (dir / "given.json").string());
  const auto told = runCamcov("import ethucy " + folder + " -o " + (dir / "told.json").string());
  ASSERT_EQ(given.exitCode, 0) << given.err;
  ASSERT_EQ(told.exitCode, 0) << told.err;
  EXPECT_EQ(readFile(dir / "told.json"), readFile(dir / "given.json"));
  EXPECT_NE(told.err.find("note: 25 frames per second, from the recorded velocities"),
            std::string::npos)
      << told.err;
  // By hand: one person walks 1 m every 10 frames at a recorded 2 m/s, so a step is 0.5 s and
  // the rate 20 frames per second; another stands (left out of the estimate).
  fs::create_directories(dir / "walk");
  std::ofstream walk(dir / "walk" / "obsmat.txt");
  for (int k = 0; k < 12; ++k) {
    walk << 100 + 10 * k << " 1 " << k << " 0 5 2 0 0\n";
    walk << 100 + 10 * k << " 2 3 0 8 0 0 0\n";
  }
  walk.close();
  const nlohmann::json scene = importScene("ethucy " + (dir / "walk").string(), dir / "walk.json");
  const auto& samples = scene["targets"][0]["track"]["samples"];
  ASSERT_EQ(samples.size(), 12u);
  EXPECT_NEAR(samples[3][0].get<double>(), 1.5, 1e-12) << "frame 130: 30 frames at 20 fps";
  EXPECT_NEAR(samples[11][0].get<double>(), 5.5, 1e-12);
}

TEST(ImportEthUcy, WithoutFpsAndWithoutWalkersItAsksForTheRateAndWritesNothing) {
  const ScratchDir dir;
  fs::create_directories(dir / "still");
  std::ofstream(dir / "still" / "obsmat.txt") << "1 7 0 0 1 0 0 0\n11 7 1 0 1 0 0 0\n";
  const auto r = runCamcov("import ethucy " + (dir / "still").string() + " -o " +
                           (dir / "still.json").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("give --fps: the velocities of the rows do not tell the frame rate (0 "
                       "steps of someone walking, 10 needed)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "still.json"));
  // Velocities of 1e300 m/s tell a rate that overflows: refused the same way, not taken.
  fs::create_directories(dir / "wild");
  std::ofstream wild(dir / "wild" / "obsmat.txt");
  for (int k = 0; k < 12; ++k)
    wild << 1000000 * k << " 1 " << k << " 0 5 1e300 0 1e300\n";
  wild.close();
  const auto w =
      runCamcov("import ethucy " + (dir / "wild").string() + " -o " + (dir / "wild.json").string());
  EXPECT_EQ(w.exitCode, 2);
  EXPECT_NE(w.err.find("give --fps: the velocities of the rows tell inf frames per second"),
            std::string::npos)
      << w.err;
  EXPECT_FALSE(fs::exists(dir / "wild.json"));
}

// The ball is player 0; a player whose team is empty is a player, not a second ball.
TEST(ImportLastRow, APlayerWithoutATeamIsAPlayerNotTheBall) {
  const ScratchDir dir;
  std::ofstream(dir / "t.csv") << "player,frame,x,y,team,bgcolor\n0,0,50,50,,\n5,0,10,10,,\n"
                                  "5,1,11,10,,\n0,1,51,50,,\n";
  const nlohmann::json scene =
      importScene("lastrow " + (dir / "t.csv").string() + " --ball target", dir / "t.json");
  ASSERT_EQ(scene["targets"].size(), 2u) << "player 5 and the ball";
  const int fronts = static_cast<int>(scene["targets"][0].contains("frontWeight")) +
                     static_cast<int>(scene["targets"][1].contains("frontWeight"));
  EXPECT_EQ(fronts, 1) << "the player has a front, the ball none";
}

// A header line, as some copies of obsmat.txt carry, is a comment; --cameras and
// --cameras-from together are refused (one would be ignored).
TEST(ImportEthUcy, ACommentLineIsSkippedAndTwoCameraOptionsAreRefused) {
  const ScratchDir dir;
  fs::create_directories(dir / "people");
  std::ofstream(dir / "people" / "obsmat.txt")
      << "# frame id x z y vx vz vy\n1 1 0 0 1 0 0 0\n11 1 0 0 1.1 0 0 0\n";
  importScene("ethucy " + (dir / "people").string() + " --fps 25", dir / "p.json");
  std::ofstream(dir / "poses.json") << R"([{"x": 0, "y": 0, "yaw_deg": 0}])";
  const auto r = runCamcov("import ethucy " + (dir / "people").string() +
                           " --fps 25 --cameras 3 --cameras-from " + (dir / "poses.json").string() +
                           " -o " + (dir / "q.json").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--cameras excludes --cameras-from"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "q.json"));
}

TEST(ImportLastRow, APlayerBeyondTheRunOffGrowsTheBoundaryAndSaysSo) {
  // Player 3 stands at 150 % of the pitch's length (157.5 m) and -10 % of its width (-6.8 m):
  // the boundary is the pitch with its run-off (5 m for Last Row) grown to hold them with their
  // 0.25 m radius and the same 5 m, rounded out to whole metres: x to 157.75 + 5, y to -12.05.
  const ScratchDir dir;
  std::ofstream(dir / "off.csv") << "player,frame,x,y,team,bgcolor\n"
                                    "2,0,50,50,attack,red\n2,1,51,50,attack,red\n"
                                    "3,0,150,-10,defense,blue\n3,1,150,-10,defense,blue\n";
  const auto r = runCamcov("import lastrow " + (dir / "off.csv").string() + " -o " +
                           (dir / "off.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("beyond the pitch's 5 m run-off: the boundary grows"), std::string::npos)
      << r.err;
  const auto scene = nlohmann::json::parse(readFile(dir / "off.json"));
  EXPECT_EQ(scene["boundary"], "POLYGON((-5 -13,163 -13,163 73,-5 73))");
  EXPECT_EQ(runCamcov("validate " + (dir / "off.json").string()).exitCode, 0);
}

struct BadInput {
  const char* name;
  const char* importer;  // "lastrow", "ethucy" or "csv"
  const char* file;      // what is written: the CSV, or obsmat.txt (ethucy)
  const char* map;       // ethucy: map.xml, or nullptr for none
  const char* message;   // expected in stderr, after the file name
};

const BadInput kBadInputs[] = {
    {"lastrow_empty_file", "lastrow", "", nullptr, ": empty file"},
    {"lastrow_missing_column", "lastrow", "player,frame,y\n1,0,3\n", nullptr,
     ":1: missing column(s) x"},
    {"lastrow_short_row", "lastrow", "player,frame,x,y,team,bgcolor\n1,0,3,4,attack,red\n1,1,3\n",
     nullptr, ":3: 3 fields, the header has 6"},
    {"lastrow_nan", "lastrow", "player,frame,x,y,team,bgcolor\n1,0,nan,4,attack,red\n", nullptr,
     ":2: column x: \"nan\" is not a finite number"},
    {"lastrow_not_a_number", "lastrow", "player,frame,x,y,team,bgcolor\n1,first,3,4,attack,red\n",
     nullptr, ":2: column frame: \"first\" is not a finite number"},
    {"lastrow_time_backwards", "lastrow",
     "player,frame,x,y,team,bgcolor\n1,5,3,4,attack,red\n1,4,3,4,attack,red\n", nullptr,
     ":3: person 1 at t = 0.2 s after t = 0.25 s: time goes backwards"},
    {"lastrow_unclosed_quote", "lastrow", "player,frame,x,y,team,bgcolor\n1,0,3,4,\"attack,red\n",
     nullptr, ":2: a quoted field is not closed"},
    {"lastrow_longer_than_any_recording", "lastrow",
     "player,frame,x,y,team,bgcolor\n1,0,3,4,attack,red\n1,1e12,3,4,attack,red\n", nullptr,
     ":3: person 1 at t = 5e+10 s: a recording's times lie within +-1e+06 s"},
    {"csv_empty_file", "csv", "", nullptr, ": empty file"},
    {"csv_missing_column", "csv", "id,t,x\n1,0,0\n", nullptr,
     ":1: missing column(s) y (--y-column)"},
    {"csv_another_delimiter", "csv", "id;t;x;y\n1;0;0;0\n", nullptr,
     "another delimiter? (--delimiter ;)"},
    {"csv_column_named_twice", "csv", "id,t,x,x,y\n1,0,0,0,0\n", nullptr,
     ":1: column \"x\" is named twice"},
    {"csv_short_row", "csv", "id,t,x,y\n1,0,0,0\n1,1,0\n", nullptr,
     ":3: 3 fields, the header has 4"},
    {"csv_nan", "csv", "id,t,x,y\n1,0,nan,0\n", nullptr,
     ":2: column x: \"nan\" is not a finite number"},
    {"csv_empty_id", "csv", "id,t,x,y\n,0,0,0\n", nullptr, ":2: column id: empty id"},
    {"csv_time_repeats", "csv", "id,t,x,y\n1,0,0,0\n1,0,1,1\n", nullptr,
     ":3: person 1 at t = 0 s after t = 0 s: time goes backwards or repeats"},
    {"csv_longer_than_any_recording", "csv", "id,t,x,y\n1,0,0,0\n1,2e6,0,0\n", nullptr,
     ":3: person 1 at t = 2e+06 s: a recording's times lie within"},
    {"csv_far_away", "csv", "id,t,x,y\n1,0,2e6,0\n", nullptr,
     ":2: column x: 2e+06 m is outside [-1e+06, 1e+06]"},
    {"csv_radius_zero", "csv", "id,t,x,y,radius\n1,0,0,0,0\n", nullptr,
     ":2: column radius: 0 m is outside [0.01, 100]"},
    // A disc too small to write: its 12 vertices would round onto each other.
    {"csv_radius_below_a_writable_disc", "csv", "id,t,x,y,radius\n1,0,0,0,0.0005\n", nullptr,
     ":2: column radius: 0.0005 m is outside [0.01, 100]"},
    {"csv_radius_changes", "csv", "id,t,x,y,radius\n1,0,0,0,0.3\n1,1,1,1,0.4\n", nullptr,
     ":3: person 1: radius 0.4 m after 0.3 m"},
    {"csv_heading_beyond_reason", "csv", "id,t,x,y,heading\n1,0,0,0,1e300\n", nullptr,
     ":2: column heading: 1e+300 is outside"},
    {"csv_no_rows", "csv", "id,t,x,y\n", nullptr, ": no rows after the header"},
    {"ethucy_empty_file", "ethucy", "", nullptr, "obsmat.txt: empty file"},
    {"ethucy_short_row", "ethucy", "1 1 0 0 1 0 0 0\n11 1 0 0 1 0 0\n", nullptr,
     "obsmat.txt:2: 7 numbers, a row has 8"},
    {"ethucy_nan", "ethucy", "1 1 NaN 0 1 0 0 0\n", nullptr,
     "obsmat.txt:1: x: \"NaN\" is not a finite number"},
    {"ethucy_not_a_number", "ethucy", "1 1 0 0 one 0 0 0\n", nullptr,
     "obsmat.txt:1: y: \"one\" is not a finite number"},
    {"ethucy_time_backwards", "ethucy", "11 1 0 0 1 0 0 0\n1 1 0 0 1 0 0 0\n", nullptr,
     "obsmat.txt:2: person 1 at t = 0 s after t = 0.4 s"},
    {"ethucy_unclosed_tag", "ethucy", "1 1 0 0 1 0 0 0\n",
     "<obstacles>\n<Line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\" />\n",
     "map.xml:1: <obstacles> is never closed"},
    {"ethucy_mismatched_tag", "ethucy", "1 1 0 0 1 0 0 0\n", "<a>\n<b>\n</a>\n",
     "map.xml:3: </a> closes <b> of line 2"},
    {"ethucy_line_without_x2", "ethucy", "1 1 0 0 1 0 0 0\n",
     "<Line x1=\"0\" y1=\"0\" y2=\"1\" />\n", "map.xml:1: <Line> has no x2"},
    {"ethucy_circle_without_radius", "ethucy", "1 1 0 0 1 0 0 0\n",
     "<Circle x=\"0\" y=\"1\" radius=\"0\" />\n", "map.xml:1: <Circle> radius 0 is not positive"},
    {"ethucy_tag_not_closed", "ethucy", "1 1 0 0 1 0 0 0\n", "<Line x1=\"0\"\n",
     "map.xml:1: a tag is not closed"},
};

class ImportBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(ImportBadInput, ExitsWithTwoNamingFileAndLineAndWritesNothing) {
  const BadInput& c = GetParam();
  const ScratchDir dir;
  std::string input;
  if (std::string(c.importer) != "ethucy") {
    input = (dir / "input.csv").string();
    std::ofstream(input) << c.file;
  } else {
    fs::create_directories(dir / "input");
    std::ofstream(dir / "input" / "obsmat.txt") << c.file;
    if (c.map != nullptr) std::ofstream(dir / "input" / "map.xml") << c.map;
    input = (dir / "input").string();
  }
  const fs::path out = dir / "out.json";
  const auto r =
      runCamcov("import " + std::string(c.importer) + " " + input +
                (std::string(c.importer) == "ethucy" ? " --fps 25" : "") + " -o " + out.string());
  EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

INSTANTIATE_TEST_SUITE_P(Kinds, ImportBadInput, ::testing::ValuesIn(kBadInputs),
                         [](const auto& info) { return std::string(info.param.name); });

// Every recording of ../shared/tracks (next to the published scenes) imports, validates, and
// runs with every method, with targets present changing over time.
TEST(ImportSharedTracks, EveryRecordingImportsAndRunsWithEveryMethod) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  const fs::path tracks = publishedScenesDir().parent_path() / "tracks";
  ASSERT_TRUE(fs::exists(tracks)) << tracks;
  const ScratchDir dir;
  const std::pair<std::string, std::string> recordings[] = {
      {"lastrow " + (tracks / "football" / "liverpool_2-1_chelsea.csv").string(), "liverpool"},
      {"lastrow " + (tracks / "football" / "real_madrid_vs_barcelona.csv").string() +
           " --ball obstacle",
       "madrid"},
      {"ethucy " + (tracks / "pedestrians" / "eth_univ").string() + " --fps 15", "univ"},
      {"ethucy " + (tracks / "pedestrians" / "eth_hotel").string() + " --fps 25", "hotel"},
      {"ethucy " + (tracks / "pedestrians" / "ucy_zara01").string() + " --fps 25", "zara"},
  };
  for (const auto& [arguments, name] : recordings) {
    const fs::path scene = dir / (name + ".json");
    importScene(arguments + " --from 2 --to 8", scene);
    for (const std::string method : {"paper", "local", "camcov", "nearest-unseen"}) {
      const auto r = runCamcov("run " + scene.string() + " --method " + method +
                               " --duration 6 --set global.K=50 --out " + (dir / "runs").string());
      ASSERT_EQ(r.exitCode, 0) << name << " " << method << ": " << r.err;
      const auto run =
          nlohmann::json::parse(readFile(dir / "runs" / (name + "-" + method + "-seed1.json")));
      const auto& present = run["series"]["targetsPresent"];
      ASSERT_FALSE(present.empty()) << name;
      if (name.rfind("liverpool", 0) != 0 && name != "madrid") {
        EXPECT_NE(std::min_element(present.begin(), present.end())->get<int>(),
                  std::max_element(present.begin(), present.end())->get<int>())
            << name << ": people come and go";
      }
    }
  }
}

}  // namespace
}  // namespace camcov::testing
