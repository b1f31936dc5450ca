// The run explorer's page from the command line: `camcov explore` on recorded runs writes one
// offline page whose embedded data is what the format says, is deterministic, fits the size
// the issue asks for, and refuses bad requests with exit 2. What the page shows in a browser
// is tests/explorer/test_explorer_browser.py.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>

#include "records/run_files.h"
#include "reports/explorer/explorer_data.h"
#include "reports/explorer/packed_stream.h"
#include "scene/scene_loader.h"
#include "support/html_checks.h"
#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"
#include "util/input_error.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

TEST(PackedStream, VarintsZigzagAndBase64AsTheStandardsGiveThem) {
  reports::explorer::PackedStream s;
  s.putUnsigned(300);  // LEB128: AC 02
  s.putSigned(-1);     // zigzag 1
  s.putSigned(1);      // zigzag 2
  s.putSigned(-64);    // zigzag 127
  EXPECT_EQ(s.bytes(), (std::vector<std::uint8_t>{0xAC, 0x02, 0x01, 0x02, 0x7F}));
  // A camera set is the number whose bit j is camera j: 2^100 is fourteen groups of seven zero
  // bits, then 2^2; a set within 64 cameras is written as putUnsigned writes its bits.
  reports::explorer::PackedStream far, near, asNumber;
  far.putBits(scene::CameraSet::only(100));
  std::vector<std::uint8_t> twoToThe100(14, 0x80);
  twoToThe100.push_back(0x04);
  EXPECT_EQ(far.bytes(), twoToThe100);
  near.putBits(scene::CameraSet::fromBits(0x8000'0000'0000'0301));
  asNumber.putUnsigned(0x8000'0000'0000'0301);
  EXPECT_EQ(near.bytes(), asNumber.bytes());
  reports::explorer::PackedStream nobody;
  nobody.putBits({});
  EXPECT_EQ(nobody.bytes(), (std::vector<std::uint8_t>{0x00}));
  // RFC 4648: "Man" → "TWFu", "Ma" → "TWE=", "M" → "TQ==".
  for (const auto& [text, expected] :
       {std::pair{"Man", "TWFu"}, std::pair{"Ma", "TWE="}, std::pair{"M", "TQ=="}}) {
    reports::explorer::PackedStream t;
    for (const char* c = text; *c != '\0'; ++c)
      t.putUnsigned(static_cast<unsigned char>(*c));
    EXPECT_EQ(t.base64(), expected) << text;
  }
}

// The JSON the page embeds.
nlohmann::json embeddedData(const fs::path& page) {
  const std::string html = readFile(page);
  const std::string open = "<script type=\"application/json\" id=\"camcov-data\">";
  const auto start = html.find(open) + open.size();
  return nlohmann::json::parse(html.substr(start, html.find("</script>", start) - start));
}

class Explore : public ::testing::Test {
 protected:
  fs::path run(const std::string& scene, const std::string& method, const std::string& extra) {
    const auto r = runCamcov("run " + scene + " --method " + method + " --seed 1 --out " +
                             dir_.path().string() + " " + extra);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const fs::path file = dir_ / (fs::path(scene).stem().string() + "-" + method + "-seed1.json");
    EXPECT_TRUE(fs::exists(file)) << r.out;
    return file;
  }
  ScratchDir dir_;
};

TEST_F(Explore, WritesOneOfflinePageWithEveryRunAndStep) {
  const std::string scene = (testDataDir() / "scenes" / "tiny_dynamic.json").string();
  const fs::path paper = run(scene, "paper", "--set sim.duration=2");
  const fs::path local = run(scene, "local", "--set sim.duration=2");
  const fs::path page = dir_ / "page.html";
  const auto r =
      runCamcov("explore " + paper.string() + " " + local.string() + " -o " + page.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string html = readFile(page);
  // The SVG namespace is a name, not an address: the script creates elements in it.
  std::string fetchable = html;
  const std::string svgNamespace = "http://www.w3.org/2000/svg";
  for (auto at = fetchable.find(svgNamespace); at != std::string::npos;
       at = fetchable.find(svgNamespace))
    fetchable.erase(at, svgNamespace.size());
  EXPECT_EQ(externalFetch(fetchable), "");
  EXPECT_EQ(fetchable.find("src="), std::string::npos) << "nothing to load, not even locally";
  EXPECT_EQ(nestingError(html), "");
  EXPECT_NE(html.find("Content-Security-Policy\" content=\"default-src 'none'"), std::string::npos);

  const nlohmann::json data = embeddedData(page);
  EXPECT_EQ(data["format"], "camcov-explorer/1");
  ASSERT_EQ(data["runs"].size(), 2u);
  EXPECT_EQ(data["runs"][0]["method"], "paper");
  EXPECT_EQ(data["runs"][1]["method"], "local");
  const nlohmann::json recorded = nlohmann::json::parse(readFile(paper));
  EXPECT_EQ(data["runs"][0]["series"]["coverage"], recorded["series"]["coverage"]);
  EXPECT_EQ(data["runs"][0]["series"]["time"], recorded["series"]["time"]);

  // Same runs, same bytes.
  const auto again = runCamcov("explore " + paper.string() + " " + local.string() + " -o " +
                               (dir_ / "again.html").string());
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_EQ(readFile(dir_ / "again.html"), html);
}

TEST_F(Explore, ARunUnderLimitedKnowledgeSaysWhoHeardWhomAtEachStep) {
  // Two cameras, a message each way at every step that has come round (every 0.5 s), and
  // every one heard at once.
  const std::string scene = (testDataDir() / "scenes" / "tiny_static.json").string();
  const fs::path limited = run(scene, "local",
                               "--set sim.duration=2 --set knowledge.limited=true "
                               "--set comms.period=0.5");
  const fs::path page = dir_ / "page.html";
  ASSERT_EQ(runCamcov("explore " + limited.string() + " -o " + page.string()).exitCode, 0);
  const nlohmann::json heard = embeddedData(page)["runs"][0]["series"]["heard"];
  ASSERT_EQ(heard.size(), 21u);
  for (std::size_t k = 0; k < heard.size(); ++k) {
    const nlohmann::json expected =
        k % 5 == 0 ? nlohmann::json{{0, 1}, {1, 0}} : nlohmann::json::array();
    EXPECT_EQ(heard[k], expected) << "step " << k;
  }
  // The record says it too, with the time each message was sent; a run with full knowledge
  // says nothing of it.
  const nlohmann::json recorded = nlohmann::json::parse(readFile(limited));
  EXPECT_EQ(recorded["series"]["heard"][5], (nlohmann::json{{0, 1, 0.5}, {1, 0, 0.5}}));
  const fs::path full = run(scene, "paper", "--set sim.duration=2");
  ASSERT_EQ(runCamcov("explore " + full.string() + " -o " + page.string()).exitCode, 0);
  EXPECT_FALSE(embeddedData(page)["runs"][0]["series"].contains("heard"));
}

TEST_F(Explore, TwoMethodsOfDynamic9ForThirtySecondsFitWellUnderTwoMegabytes) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  const std::string scene = (publishedScenesDir() / "dynamic9.json").string();
  const fs::path paper = run(scene, "paper", "");
  const fs::path local = run(scene, "local", "");
  const fs::path page = dir_ / "d9.html";
  ASSERT_EQ(runCamcov("explore " + paper.string() + " " + local.string() + " -o " + page.string())
                .exitCode,
            0);
  EXPECT_EQ(embeddedData(page)["runs"][0]["series"]["time"].size(), 301u);
  EXPECT_LT(fs::file_size(page), 1'000'000u) << "well under the 2 MB a page may weigh";
}

// A page holds at most kMaxPackedSteps of packed steps over its runs: pages past it would not
// load. The limit is checked as the steps are packed, to the byte; here set at two runs' worth.
TEST_F(Explore, APageHoldsAtMostItsLimitOfPackedStepsAndSaysWhatToDoPastIt) {
  const std::string tiny = (testDataDir() / "scenes" / "tiny_dynamic.json").string();
  const std::vector<records::RunRecord> runs{records::loadRunFile(run(tiny, "paper", "")),
                                             records::loadRunFile(run(tiny, "local", ""))};
  const scene::Scene scene = scene::loadScene(tiny);
  std::size_t packed = 0;  // bytes, from the base64 of each run's steps
  const nlohmann::json whole = reports::explorer::explorerData(runs, scene);
  for (const auto& r : whole["runs"]) {
    const std::string steps = r["steps"];
    packed += steps.size() / 4 * 3 - std::count(steps.end() - 2, steps.end(), '=');
  }
  EXPECT_NO_THROW(reports::explorer::explorerData(runs, scene, packed));
  try {
    reports::explorer::explorerData(runs, scene, packed - 1);
    ADD_FAILURE() << "one byte past the limit is refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the run of local, seed 1 reached it at step"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("explore fewer runs at once"), std::string::npos);
  }
}

TEST_F(Explore, BadRequestsExitWithTwoAndWriteNothing) {
  const std::string tiny = (testDataDir() / "scenes" / "tiny_dynamic.json").string();
  const std::string other = (testDataDir() / "scenes" / "tiny_static.json").string();
  const fs::path a = run(tiny, "paper", "--set sim.duration=1");
  const fs::path b = run(other, "paper", "--set sim.duration=1");
  // A run whose scene file has moved.
  fs::copy_file(tiny, dir_ / "moved.json");
  const fs::path c = run((dir_ / "moved.json").string(), "local", "--set sim.duration=1");
  fs::remove(dir_ / "moved.json");
  struct Case {
    std::string arguments, message;
  };
  const fs::path out = dir_ / "out.html";
  for (const Case& k : {
           Case{a.string() + " " + b.string() + " -o " + out.string(), "not of one scene"},
           Case{c.string() + " -o " + out.string(), "give it with --scene"},
           Case{a.string() + " -o " + (dir_ / "out.svg").string(), "name it *.html"},
           Case{(dir_ / "nope.json").string() + " -o " + out.string(), "nope.json"},
       }) {
    const auto r = runCamcov("explore " + k.arguments);
    EXPECT_EQ(r.exitCode, 2) << k.arguments;
    EXPECT_NE(r.err.find(k.message), std::string::npos) << k.arguments << ": " << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  const auto moved =
      runCamcov("explore " + c.string() + " --scene " + tiny + " -o " + out.string());
  EXPECT_EQ(moved.exitCode, 0) << moved.err;
  EXPECT_TRUE(fs::exists(out));
}

TEST(BenchExplorers, OnePagePerSceneWithEachMethodsMedianRunLinkedFromTheReport) {
  const ScratchDir dir;
  const auto bench = [&](const std::string& out, const std::string& extra) {
    return runCamcov("bench --scenes " + (testDataDir() / "scenes").string() +
                     " --seeds 3 --duration 2 --videos none --out " + (dir / out).string() + " " +
                     extra);
  };
  ASSERT_EQ(bench("default", "").exitCode, 0);
  const nlohmann::json summary = nlohmann::json::parse(readFile(dir / "default" / "summary.json"));
  for (const std::string scene : {"tiny_dynamic", "tiny_static"}) {
    const fs::path page = dir / "default" / "explore" / (scene + ".html");
    ASSERT_TRUE(fs::exists(page)) << scene;
    const nlohmann::json data = embeddedData(page);
    std::vector<std::pair<std::string, std::uint64_t>> shown, median;
    for (const auto& run : data["runs"])
      shown.emplace_back(run["method"], run["seed"]);
    for (const auto& m : summary["methods"]) {
      if (m["scene"] == scene) median.emplace_back(m["method"], m["medianSeed"]);
    }
    // Side by side in the order of every table (control/methods.h), not by name.
    std::vector<std::string> order;
    for (const auto& [method, seed] : shown)
      order.push_back(method);
    EXPECT_EQ(order, (std::vector<std::string>{"paper", "local", "camcov"})) << scene;
    std::sort(shown.begin(), shown.end());
    std::sort(median.begin(), median.end());
    EXPECT_EQ(shown, median) << scene;
    EXPECT_NE(readFile(dir / "default" / "report.html")
                  .find("class=\"explore\" href=\"explore/" + scene + ".html\""),
              std::string::npos)
        << scene;
  }
  ASSERT_EQ(bench("none", "--explorer none").exitCode, 0);
  EXPECT_FALSE(fs::exists(dir / "none" / "explore"));
  EXPECT_EQ(readFile(dir / "none" / "report.html").find("class=\"explore\""), std::string::npos);
  const auto all = bench("all", "--explorer all");
  EXPECT_EQ(all.exitCode, 2);
  EXPECT_NE(all.err.find("--explorer all: one of none, median, best"), std::string::npos)
      << all.err;
  EXPECT_FALSE(fs::exists(dir / "all" / "runs")) << "refused before any job ran";
}

}  // namespace
}  // namespace camcov::testing
