// `camcov import csv`: a table of tracks in any layout and units. A table written from an
// imported scene's tracks imports back to the same scene; renamed columns, another delimiter
// and other units read as the rows say (computed here from the rows); a heading, a radius and
// a colour per person reach the scene. Bad rows are in importer_test.cpp's table of bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <numbers>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

nlohmann::json importScene(const std::string& arguments, const fs::path& out) {
  const auto r = runCamcov("import " + arguments + " -o " + out.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(readFile(out));
}

// The first vertex of a disc about the origin is (r, 0): its radius as the file has it.
double discRadius(const nlohmann::json& target) {
  const std::string shape = target["shape"];
  return std::stod(shape.substr(shape.find("((") + 2));
}

// The scene's targets as a table: id (zero-padded, so that targets starting together keep
// their order), t, x, y, radius, color.
void writeTable(const nlohmann::json& scene, const fs::path& file) {
  std::ofstream out(file);
  out << std::setprecision(17) << "id,t,x,y,radius,color\n";
  for (std::size_t i = 0; i < scene["targets"].size(); ++i) {
    const auto& target = scene["targets"][i];
    for (const auto& sample : target["track"]["samples"]) {
      out << "p" << std::setw(4) << std::setfill('0') << i << std::setfill(' ') << ","
          << sample[0].get<double>() << "," << sample[1].get<double>() << ","
          << sample[2].get<double>() << "," << discRadius(target) << ","
          << target.value("color", std::string()) << "\n";
    }
  }
}

TEST(ImportCsv, ATableOfAnImportedScenesTracksImportsBackToTheSameScene) {
  const ScratchDir dir;
  // The pedestrians of the committed extract, without its walls (a table holds people only).
  fs::create_directories(dir / "people");
  fs::copy_file(testDataDir() / "tracks" / "ethucy_extract" / "obsmat.txt",
                dir / "people" / "obsmat.txt");
  const std::string options = " --cameras 3 --radius 0.3 --max-gap 0.5";
  nlohmann::json original =
      importScene("ethucy " + (dir / "people").string() + " --fps 25" + options, dir / "a.json");
  ASSERT_GE(original["targets"].size(), 2u);
  writeTable(original, dir / "tracks.csv");
  nlohmann::json again =
      importScene("csv " + (dir / "tracks.csv").string() + options, dir / "b.json");
  original.erase("description");
  again.erase("description");
  EXPECT_EQ(again, original);
}

TEST(ImportCsv, RenamedColumnsAnotherDelimiterAndUnitsReadAsTheRowsSay) {
  const ScratchDir dir;
  // Centimetres, milliseconds from a clock that started long before, radians.
  std::ofstream(dir / "table.txt") << "who;when;east;north;facing;size;shirt\n"
                                      "anna;5000;100;-250;0;40;red\n"
                                      "ben;5500;0;0;1.5707963267948966;30;#00FF00\n"
                                      "anna;6000;300;-250;3.141592653589793;40;red\n";
  const auto r =
      runCamcov("import csv " + (dir / "table.txt").string() + " -o " + (dir / "s.json").string() +
                " --delimiter ';' --id-column who --time-column when --x-column east"
                " --y-column north --heading-column facing --radius-column size"
                " --color-column shirt --time-unit ms --length-unit cm"
                " --heading-unit rad --front-weight 1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("time starts at the table's earliest, 5 s"), std::string::npos) << r.err;
  const auto scene = nlohmann::json::parse(readFile(dir / "s.json"));
  ASSERT_EQ(scene["targets"].size(), 2u);
  const auto& anna = scene["targets"][0];
  const auto& ben = scene["targets"][1];
  EXPECT_EQ(anna["color"], "#ff0000");
  EXPECT_EQ(ben["color"], "#00ff00");
  EXPECT_DOUBLE_EQ(discRadius(anna), 0.4);
  EXPECT_DOUBLE_EQ(discRadius(ben), 0.3);
  const auto& a = anna["track"]["samples"];
  ASSERT_EQ(a.size(), 2u);
  const std::vector<std::vector<double>> expectedAnna{{0.0, 1.0, -2.5, 0.0},
                                                      {1.0, 3.0, -2.5, 180.0}};
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t c = 0; c < 4; ++c)
      EXPECT_NEAR(a[k][c].get<double>(), expectedAnna[k][c], 1e-9) << k << "," << c;
  }
  const auto& b = ben["track"]["samples"];
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NEAR(b[0][0].get<double>(), 0.5, 1e-9);
  EXPECT_NEAR(b[0][3].get<double>(), 90.0, 1e-9);
  EXPECT_FALSE(anna.contains("frontWeight"));
  EXPECT_EQ(runCamcov("validate " + (dir / "s.json").string()).exitCode, 0);
}

TEST(ImportCsv, FramesNeedARateAndColumnsNotInTheHeaderAreNotRead) {
  const ScratchDir dir;
  std::ofstream(dir / "t.csv") << "id,frame,x,y\n1,10,0,0\n1,35,1,0\n";
  const std::string base =
      "import csv " + (dir / "t.csv").string() + " -o " + (dir / "s.json").string();
  const auto refused = runCamcov(base + " --time-column frame --time-unit frames");
  EXPECT_EQ(refused.exitCode, 2);
  EXPECT_NE(refused.err.find("give the frame rate, --rate"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir / "s.json"));
  ASSERT_EQ(runCamcov(base + " --time-column frame --time-unit frames --rate 25").exitCode, 0);
  const auto scene = nlohmann::json::parse(readFile(dir / "s.json"));
  const auto& samples = scene["targets"][0]["track"]["samples"];
  EXPECT_NEAR(samples[1][0].get<double>(), 1.0, 1e-9);  // 25 frames at 25 per second
  EXPECT_EQ(samples[1].size(), 3u) << "no heading column: [t, x, y]";
  EXPECT_DOUBLE_EQ(discRadius(scene["targets"][0]), 0.25);  // the default radius
}

}  // namespace
}  // namespace camcov::testing
