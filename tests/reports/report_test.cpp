// The report end to end: `camcov bench` writes it, `camcov report` and `camcov merge` rewrite
// it, and its structure holds: every scene in every section, every plot with axes, two boxes
// per scene, a time-series figure per scene, nothing fetched from the network, well-nested
// HTML, and the same bytes from the same folder except the build date and machine.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "report_fixture.h"
#include "reports/build_context.h"
#include "reports/report_builder.h"
#include "reports/report_data.h"
#include "support/html_checks.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

// Every <svg ...>...</svg> in `html`.
std::vector<std::string> svgs(const std::string& html, const std::string& cls) {
  std::vector<std::string> out;
  const std::string open = "<svg class=\"" + cls + "\"";
  for (auto at = html.find(open); at != std::string::npos; at = html.find(open, at + 1)) {
    out.push_back(html.substr(at, html.find("</svg>", at) - at));
  }
  return out;
}

TEST(Report, BenchWritesItWithEverySceneInEverySection) {
  const ScratchDir dir;
  const auto r = benchFixture(dir / "results");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const std::string html = readFile(dir / "results" / "report.html");
  ASSERT_FALSE(html.empty());
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  // A scene's name in the summary may break after each '_' (<wbr>), as its column is narrow.
  std::string summary = section(html, "summary");
  for (auto at = summary.find("<wbr>"); at != std::string::npos; at = summary.find("<wbr>", at))
    summary.erase(at, 5);
  for (const std::string scene : kFixtureScenes) {
    EXPECT_NE(summary.find(">" + scene + "</a>"), std::string::npos) << scene;
    EXPECT_EQ(countOf(section(html, "time-series"),
                      "data-figure=\"series\" data-scene=\"" + scene + "\""),
              1)
        << scene;
    EXPECT_EQ(
        countOf(section(html, "scenes"), "data-figure=\"scene\" data-scene=\"" + scene + "\""), 1)
        << scene;
    for (const char* method : {"paper", "local"}) {
      EXPECT_EQ(
          countOf(section(html, "box-plots"), "data-metric=\"coverage\" data-scene=\"" + scene +
                                                  "\" data-method=\"" + method + "\""),
          1)
          << scene << " " << method;
    }
  }
  EXPECT_NE(section(html, "parameters").find("Table I"), std::string::npos);
}

TEST(Report, GroupsScenesByFolderWhenThereAreSeveralAndCountsEachGroupsVerdicts) {
  const ScratchDir dir;
  const auto one = benchFixture(dir / "one", "--no-report");
  ASSERT_EQ(one.exitCode, 0) << one.out << one.err;
  ASSERT_EQ(runCamcov("report " + (dir / "one").string()).exitCode, 0);
  EXPECT_EQ(readFile(dir / "one" / "report.html").find("id=\"groups\""), std::string::npos)
      << "one folder: nothing to group";
  fs::create_directories(dir / "other");
  fs::copy_file(testDataDir() / "scenes" / "tiny_static.json", dir / "other" / "lone.json");
  const auto two = benchFixture(dir / "two", "--scenes " + (dir / "other").string());
  ASSERT_EQ(two.exitCode, 0) << two.out << two.err;
  EXPECT_NE(two.out.find("by family or folder"), std::string::npos) << two.out;
  const std::string groups = section(readFile(dir / "two" / "report.html"), "groups");
  ASSERT_FALSE(groups.empty());
  // Each folder's row: its name, its scene count, a mean per method, and the three comparisons
  // of the default methods (3 seeds: undecided on every scene, marked "?").
  EXPECT_NE(groups.find("<th scope=\"row\">scenes</th><td class=\"num\">2</td>"), std::string::npos)
      << groups;
  EXPECT_NE(groups.find("<th scope=\"row\">other</th><td class=\"num\">1</td>"), std::string::npos);
  EXPECT_EQ(countOf(groups, "0 / 0 / 0 / 2?"), 3) << groups;
  EXPECT_EQ(countOf(groups, "0 / 0 / 0 / 1?"), 3);
  const auto summary = nlohmann::json::parse(readFile(dir / "two" / "summary.json"));
  ASSERT_EQ(summary["groups"].size(), 2u);
  EXPECT_EQ(summary["groups"][0]["name"], "other") << "in the order of each group's first scene";
  EXPECT_EQ(summary["groups"][0]["scenes"], nlohmann::json::array({"lone"}));
}

TEST(Report, ShowsContactsBelowDeltaByKindInTheTableAndOnTheTimePlots) {
  // The corridor scene of tests/data/safety: a contact no method can avoid, proven there.
  const ScratchDir dir;
  const auto r =
      runCamcov("bench --scenes " + (testDataDir() / "safety" / "corridor_outpaced.json").string() +
                " --seeds 2 --duration 8 --set global.K=30 --set planner.T2=0.05"
                " --jobs 2 --videos none --out " +
                (dir / "results").string());
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const std::string html = readFile(dir / "results" / "report.html");
  const std::string summary = section(html, "summary");
  EXPECT_NE(summary.find("avoidable / unavoidable"), std::string::npos);
  EXPECT_NE(summary.find("runs with avoidable contact"), std::string::npos);
  // Each method: no avoidable time (0.00 first), some unavoidable, no run with an avoidable one.
  EXPECT_EQ(countOf(summary, "\">0.00 / 0."), 3) << summary;
  EXPECT_EQ(countOf(summary, "2 runs had an unavoidable contact\">0 / 2<"), 3) << summary;
  const std::string series = section(html, "time-series");
  // Cameras are counted from 0 here too, as in the frames, the explorer and the results.
  EXPECT_GE(countOf(series, "unavoidable-contact camera 0 (outpaced)"), 2) << "a mark per method";
  EXPECT_NE(series.find(">unavoidable contact &lt; δ<"), std::string::npos) << "in the legend";
  EXPECT_EQ(series.find(">avoidable contact &lt; δ<"), std::string::npos);
}

TEST(Report, EveryPlotHasAxesAndTheRightNumberOfBoxes) {
  const ScratchDir dir;
  ASSERT_EQ(benchFixture(dir / "results").exitCode, 0);
  const std::string html = readFile(dir / "results" / "report.html");
  const auto charts = svgs(html, "chart");
  // Box plots: coverage and utilization for the static and the dynamic group; time series:
  // coverage and utilization per scene.
  EXPECT_EQ(charts.size(), 4u + 2u * std::size(kFixtureScenes));
  for (const auto& svg : charts) {
    EXPECT_GE(countOf(svg, "<text class=\"tick\""), 4) << svg.substr(0, 200);
    EXPECT_EQ(countOf(svg, "<text class=\"axis-label\""), 2) << svg.substr(0, 200);
    EXPECT_GE(countOf(svg, "<text class=\"legend\""), 2) << svg.substr(0, 200);
  }
  const std::string boxes = section(html, "box-plots");
  EXPECT_EQ(countOf(boxes, "class=\"box\" data-metric=\"coverage\""),
            3 * static_cast<int>(std::size(kFixtureScenes)));
  EXPECT_EQ(countOf(boxes, "class=\"box\" data-metric=\"utilization\""),
            3 * static_cast<int>(std::size(kFixtureScenes)));
  for (const std::string scene : kFixtureScenes) {
    const auto at = html.find("data-figure=\"series\" data-scene=\"" + scene + "\"");
    ASSERT_NE(at, std::string::npos);
    const std::string figure = html.substr(at, html.find("</figure>", at) - at);
    EXPECT_EQ(countOf(figure, "<svg class=\"chart\""), 2) << "coverage and utilization";
    EXPECT_EQ(countOf(figure, "<polyline"), 6) << "the median run of each method, twice";
    EXPECT_GE(countOf(figure, "class=\"axis-mark\""), 2) << "the paper's replan at t = 0";
  }
  EXPECT_EQ(svgs(html, "scene").size(), std::size(kFixtureScenes));
}

TEST(Report, FetchesNothingAndNestsWell) {
  const ScratchDir dir;
  ASSERT_EQ(benchFixture(dir / "results").exitCode, 0);
  const std::string html = readFile(dir / "results" / "report.html");
  EXPECT_EQ(externalFetch(html), "");
  EXPECT_NE(html.find("Content-Security-Policy\" content=\"default-src 'none'"), std::string::npos);
  EXPECT_EQ(nestingError(html), "");
  for (const char* tag : {"html", "head", "body", "main", "section", "figure", "svg", "table"}) {
    EXPECT_EQ(
        countOf(html, std::string("<") + tag + ">") + countOf(html, std::string("<") + tag + " "),
        countOf(html, std::string("</") + tag + ">"))
        << tag;
  }
}

TEST(Report, NestingCheckCatchesBrokenMarkup) {
  EXPECT_EQ(nestingError("<div><p>a</p><svg><path d=\"M0 0\"/></svg></div>"), "");
  EXPECT_NE(nestingError("<div><p>a</div></p>"), "");
  EXPECT_NE(nestingError("<section><div></section>"), "");
  EXPECT_EQ(nestingError("<style>a > b {}</style><script>if (a < b) {}</script>"), "");
}

TEST(Report, HeaderNamesCommandJobsAndParameterOverrides) {
  const ScratchDir dir;
  ASSERT_EQ(benchFixture(dir / "results").exitCode, 0);
  const std::string html = readFile(dir / "results" / "report.html");
  EXPECT_NE(html.find("18 = 2 scenes × 3 methods × 3 seeds; 0 failed"), std::string::npos);
  EXPECT_NE(html.find("bench --scenes"), std::string::npos);
  EXPECT_NE(html.find("<dt>Machine</dt>"), std::string::npos);
  EXPECT_NE(html.find("summed over 18 jobs"), std::string::npos);
  const std::string parameters = section(html, "parameters");
  EXPECT_EQ(countOf(parameters, "<tr class=\"override\">"), 3) << "K, T2 and the duration";
  EXPECT_NE(parameters.find("<code>global.K</code> = 30 (default 500)"), std::string::npos);
}

TEST(Report, NoReportFlagSkipsIt) {
  const ScratchDir dir;
  ASSERT_EQ(benchFixture(dir / "results", "--no-report").exitCode, 0);
  EXPECT_TRUE(fs::exists(dir / "results" / "summary.json"));
  EXPECT_FALSE(fs::exists(dir / "results" / "report.html"));
}

TEST(Report, ReportCommandWritesWhereAskedAndEmbedsVideosByRelativeUrl) {
  const ScratchDir dir;
  ASSERT_EQ(benchFixture(dir / "results", "--no-report").exitCode, 0);
  fs::create_directories(dir / "results" / "videos");
  for (const char* name : {"tiny_static-paper-seed1.mp4", "tiny_static.mp4", "notes.txt"}) {
    std::ofstream(dir / "results" / "videos" / name) << "x";
  }
  auto r = runCamcov("report " + (dir / "results").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string here = readFile(dir / "results" / "report.html");
  const std::string videos = section(here, "videos");
  EXPECT_EQ(countOf(videos, "<video controls"), 2);
  EXPECT_NE(videos.find("src=\"videos/tiny_static-paper-seed1.mp4\""), std::string::npos);
  EXPECT_NE(videos.find("src=\"videos/tiny_static.mp4\""), std::string::npos);

  r = runCamcov("report " + (dir / "results").string() + " -o " +
                (dir / "out" / "r.html").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(readFile(dir / "out" / "r.html").find("src=\"../results/videos/tiny_static.mp4\""),
            std::string::npos);

  r = runCamcov("report " + testDataDir().string());
  EXPECT_EQ(r.exitCode, 2) << "not a results folder";
  EXPECT_NE(r.err.find("batch.json"), std::string::npos) << r.err;
}

// The optimum's table sets the median final coverage of each method against the optimum's
// coverage: rewriting the optimum file to a known multiple of it must show that fraction.
TEST(Report, SetsEachMethodsMedianFinalCoverageAgainstTheOptimum) {
  const ScratchDir dir;
  const fs::path results = dir / "results";
  ASSERT_EQ(benchFixture(results, "--no-report --optimum-budget 2000").exitCode, 0);
  const auto summary = nlohmann::json::parse(readFile(results / "summary.json"));
  double paperFinal = -1.0;
  for (const auto& m : summary["methods"]) {
    if (m["scene"] == "tiny_static" && m["method"] == "paper")
      paperFinal = m["finalCoverage"]["median"];
  }
  ASSERT_GT(paperFinal, 0.0);
  const fs::path file = results / "optimum" / "tiny_static.json";
  auto optimum = nlohmann::json::parse(readFile(file));
  optimum["travelTime"] = 1.5;  // s: within the fixture's 2 s runs
  const auto reportWith = [&](double optimumCoverage) {
    optimum["best"]["coverage"] = optimumCoverage;
    std::ofstream(file) << optimum.dump(1);
    EXPECT_EQ(runCamcov("report " + results.string()).exitCode, 0);
    return section(readFile(results / "report.html"), "optimum");
  };
  std::string table = reportWith(paperFinal / 0.5);
  EXPECT_NE(table.find(fmt::format("<td class=\"num\">{:.3f}</td><td class=\"num\">50.0&nbsp;%",
                                   paperFinal)),
            std::string::npos)
      << table;
  table = reportWith(paperFinal / 0.99);
  EXPECT_NE(table.find("<td class=\"num near-optimum\">✓ 99.0&nbsp;%"), std::string::npos) << table;
  EXPECT_EQ(countOf(table, "<tr><th scope=\"row\">"), 1) << "one scene holds still";
  // A pose the team needs longer than the run to reach is shown, greyed, and not counted.
  EXPECT_EQ(table.find("class=\"out-of-reach\""), std::string::npos);
  EXPECT_NE(table.find("<td class=\"num\">1.5</td>"), std::string::npos);
  optimum["travelTime"] = 1e3;
  table = reportWith(paperFinal / 0.99);
  EXPECT_NE(table.find("1000.0 <span class=\"out-of-reach\">out of reach</span>"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("<td class=\"num muted\">99.0&nbsp;%"), std::string::npos) << table;
  EXPECT_NE(table.find("not counted (1 of 1 scenes here)"), std::string::npos);
  EXPECT_NE(table.find("<td class=\"num\" colspan=\"2\">0 of 0</td>"), std::string::npos);
  optimum.erase("travelTime");

  // An optimum made from another version of the scene is not a reference for these runs.
  std::string hash = optimum["scene"]["hash"];
  hash.back() = hash.back() == '0' ? '1' : '0';
  optimum["scene"]["hash"] = hash;
  EXPECT_EQ(reportWith(paperFinal), "");
}

TEST(Report, MergeWritesItWithAFailedJobsSection) {
  const ScratchDir dir;
  ASSERT_EQ(benchFixture(dir / "results", "--no-report").exitCode, 0);
  std::ofstream(dir / "results" / "runs" / "tiny_static-paper-seed4.error.json")
      << R"({"format": "camcov-failure/1", "scene": "tiny_static", "method": "paper", "seed": 4,
            "error": "planner <exploded>"})";
  const auto r =
      runCamcov("merge " + (dir / "results").string() + " --out " + (dir / "merged").string());
  EXPECT_EQ(r.exitCode, 1) << "a failed job: " << r.err;
  const std::string html = readFile(dir / "merged" / "report.html");
  const std::string failures = section(html, "failures");
  EXPECT_NE(failures.find("Failed jobs (1)"), std::string::npos);
  EXPECT_NE(failures.find("planner &lt;exploded&gt;"), std::string::npos);
  EXPECT_NE(html.find("href=\"#failures\""), std::string::npos);
}

// What `prefix"...` opens, in order, in `html`: the ids after each prefix.
std::vector<std::string> idsAfter(const std::string& html, const std::string& prefix) {
  std::vector<std::string> ids;
  for (auto at = html.find(prefix); at != std::string::npos; at = html.find(prefix, at + 1)) {
    const auto from = at + prefix.size();
    ids.push_back(html.substr(from, html.find('"', from) - from));
  }
  return ids;
}

TEST(Report, TheNavigationLinksEverySectionShownInThePagesOrderAndNoOther) {
  const ScratchDir dir;
  ASSERT_EQ(benchFixture(dir / "results", "--no-report").exitCode, 0);
  std::ofstream(dir / "results" / "runs" / "tiny_static-paper-seed4.error.json")
      << R"({"format": "camcov-failure/1", "scene": "tiny_static", "method": "paper", "seed": 4,
            "error": "planner exploded"})";
  runCamcov("merge " + (dir / "results").string() + " --out " + (dir / "merged").string());
  const std::string html = readFile(dir / "merged" / "report.html");
  const auto navEnd = html.find("</nav>");
  ASSERT_NE(navEnd, std::string::npos);
  std::vector<std::string> linked = idsAfter(html.substr(0, navEnd), "<a href=\"#");
  const auto main = html.find("<main>");
  std::vector<std::string> shown =
      idsAfter(html.substr(main, html.find("</main>") - main), "<section id=\"");
  EXPECT_NE(std::find(shown.begin(), shown.end(), "failures"), shown.end());
  EXPECT_EQ(linked, shown);
}

TEST(Report, SameFolderSameBytesButTheBuildContext) {
  const ScratchDir dir;
  ASSERT_EQ(benchFixture(dir / "results").exitCode, 0);
  const fs::path file = dir / "results" / "report.html";
  const reports::ReportData data = reports::loadReportData(dir / "results", file);
  const reports::BuildContext context{"2000-01-01 00:00 UTC", "host", "cpu", 4};
  const std::string html = reports::buildReportHtml(data, context);
  EXPECT_EQ(html,
            reports::buildReportHtml(reports::loadReportData(dir / "results", file), context));

  // The file camcov wrote differs only in the date and machine lines.
  EXPECT_EQ(withoutBuildContext(readFile(file)), withoutBuildContext(html));
}

}  // namespace
}  // namespace camcov::testing

namespace camcov::testing {
namespace {

TEST(Report, RecordedPeopleHaveTheirOwnGroupAndThePeoplePresentOverTime) {
  const ScratchDir dir;
  const auto r = runCamcov("bench --scenes " + (testDataDir() / "scenes_tracks").string() +
                           " --seeds 2 --duration 4 --set global.K=30 --videos none --out " +
                           (dir / "results").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string html = readFile(dir / "results" / "report.html");
  EXPECT_NE(section(html, "summary").find("Recorded people"), std::string::npos);
  const std::string series = section(html, "time-series");
  // Nobody before 0.5 s and after 3 s: 5 + 10 of the 41 steps.
  EXPECT_NE(series.find("at most 2 people at once; 15 of 41 steps without anyone"),
            std::string::npos)
      << series.substr(0, 2000);
  EXPECT_EQ(countOf(series, "aria-label=\"people present over time, comes_and_goes\""), 1);
}

// A weighted scene's rows give the average weighted coverage under the plain one, as the
// batch summary records it; a scene without weights has none.
TEST(Report, AWeightedScenesRowsShowItsWeightedCoverageToo) {
  const ScratchDir dir;
  const std::string scenes = (ownScenesDir() / "weighted_stage_and_walkers.json").string() + " " +
                             (ownScenesDir() / "fig1_example.json").string();
  const auto r = runCamcov("bench --scenes " + scenes + " --methods local --seeds 2 --duration 3 " +
                           "--videos none --explorer none --optimum-budget 0 --out " +
                           (dir / "results").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto summary = nlohmann::json::parse(readFile(dir / "results" / "summary.json"));
  std::string expected;
  for (const auto& m : summary["methods"]) {
    if (m["scene"] == "fig1_example") {
      EXPECT_FALSE(m.contains("averageWeightedCoverage"));
      continue;
    }
    const auto& w = m.at("averageWeightedCoverage");
    EXPECT_EQ(w["count"], 2);
    expected = fmt::format("weighted <span class=\"value\">{:.3f} ± {:.3f}</span>",
                           w["mean"].get<double>(), w["sd"].get<double>());
  }
  const std::string table = section(readFile(dir / "results" / "report.html"), "summary");
  EXPECT_EQ(countOf(table, expected), 1) << expected;
  EXPECT_EQ(countOf(table, ">weighted "), 1) << "fig1_example has no weighted line";
}

}  // namespace
}  // namespace camcov::testing
