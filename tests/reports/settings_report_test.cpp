// The report of settings side by side: `camcov report` over a folder of results
// folders (a sweep) or over several folders. Its numbers are checked against each folder's own
// summary.json and, for the verdicts, against Mann-Whitney p-values worked out by hand.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "report_fixture.h"
#include "reports/build_context.h"
#include "reports/settings_report.h"
#include "support/html_checks.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

struct Cell {
  bool found = false;
  double mean = 0.0;
  std::string verdict;
  std::string title;
  std::string text;
};

std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const auto at = tag.find(key);
  if (at == std::string::npos) return {};
  const auto start = at + key.size();
  return tag.substr(start, tag.find('"', start) - start);
}

// The per-scene table's cell of (scene, method) in setting `setting`.
Cell sceneCell(const std::string& html, const std::string& scene, const std::string& method,
               const std::string& setting) {
  const std::string rows = section(html, "per-scene");
  const auto row = rows.find("<tr data-scene=\"" + scene + "\" data-method=\"" + method + "\">");
  if (row == std::string::npos) return {};
  const auto rowEnd = rows.find("</tr>", row);
  const auto at = rows.find("data-setting=\"" + setting + "\"", row);
  if (at == std::string::npos || at > rowEnd) return {};
  const auto tagStart = rows.rfind('<', at), tagEnd = rows.find('>', at);
  const std::string tag = rows.substr(tagStart, tagEnd - tagStart);
  return {true, std::stod(attribute(tag, "data-mean")), attribute(tag, "data-verdict"),
          attribute(tag, "title"),
          rows.substr(tagEnd + 1, rows.find("</td>", tagEnd) - tagEnd - 1)};
}

nlohmann::json summaryOf(const fs::path& folder) {
  return nlohmann::json::parse(readFile(folder / "summary.json"));
}

TEST(SettingsReport, ShowsASweepsSettingsSideBySideWithTheSummariesNumbers) {
  const ScratchDir dir;
  const fs::path sweep = dir / "sweep";
  ASSERT_EQ(benchFixture(sweep / "global.K=30", "--no-report").exitCode, 0);
  const auto k60 = benchFixture(sweep / "global.K=60", "--set global.K=60");
  ASSERT_EQ(k60.exitCode, 0) << k60.err;
  // The same setting again: Δ = 0 everywhere, and with 3 seeds every comparison with the
  // reference is undecided (no p can be below 0.1), never a tie.
  fs::copy(sweep / "global.K=30", sweep / "global.K=30-again", fs::copy_options::recursive);

  const auto r = runCamcov("report " + sweep.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string html = readFile(sweep / "report.html");
  EXPECT_EQ(nestingError(html), "");
  EXPECT_EQ(externalFetch(html), "");

  // Only K differs; the folders come in natural order, the first is the reference.
  const std::string settings = section(html, "settings");
  EXPECT_EQ(countOf(settings, "<th scope=\"col\" title="), 1) << settings;
  EXPECT_NE(settings.find("title=\"global.K\""), std::string::npos);
  EXPECT_EQ(countOf(settings, "class=\"note\""), 0) << "nothing but K differs";
  const auto first = settings.find("data-setting=\"global.K=30\"");
  const auto again = settings.find("data-setting=\"global.K=30-again\"");
  const auto last = settings.find("data-setting=\"global.K=60\"");
  ASSERT_NE(first, std::string::npos);
  EXPECT_LT(first, again);
  EXPECT_LT(again, last);
  EXPECT_NE(settings.substr(first, again - first).find("reference"), std::string::npos);
  // Only the folder that has its own report links to it.
  EXPECT_EQ(countOf(settings, "title=\"its own report\""), 1);
  EXPECT_NE(settings.find("href=\"global.K%3D60/report.html\""), std::string::npos) << settings;

  for (const std::string folder : {"global.K=30", "global.K=30-again", "global.K=60"}) {
    const nlohmann::json summary = summaryOf(sweep / folder);
    for (const auto& m : summary["methods"]) {
      const Cell c = sceneCell(html, m["scene"], m["method"], folder);
      ASSERT_TRUE(c.found) << folder << " " << m["scene"] << " " << m["method"];
      EXPECT_EQ(c.mean, m["averageCoverage"]["mean"].get<double>()) << folder;
      if (folder == "global.K=30") {
        EXPECT_EQ(c.verdict, "reference");
      } else if (folder == "global.K=30-again") {
        EXPECT_EQ(c.verdict, "undecided");
        EXPECT_NE(c.title.find("Δ +0.000"), std::string::npos) << c.title;
      } else {
        EXPECT_EQ(c.verdict, "undecided");
      }
    }
  }
  // Over all scenes: undecided on both scenes for both methods.
  const std::string overall = section(html, "overall");
  EXPECT_EQ(countOf(overall, "<td class=\"num\" data-setting=\"global.K=30-again\""), 3);
  EXPECT_EQ(
      countOf(overall, "data-wins=\"0\" data-ties=\"0\" data-losses=\"0\" data-undecided=\"2\">"),
      6)
      << "the copy (3 methods), and K=60: 3 seeds cannot decide";
  EXPECT_EQ(countOf(overall, "data-figure=\"settings-difference\""), 1);
}

records::BatchManifest manifest(std::uint64_t seeds) {
  records::BatchManifest m;
  m.toolVersion = "test";
  m.methods = {"paper"};
  m.seeds = seeds;
  return m;
}

// Two scenes; setting "high" is clearly better on one, equal on the other, "low" clearly worse.
reports::SettingsData handMadeSettings() {
  reports::SettingsData data;
  const std::vector<double> base{0.1, 0.2, 0.3, 0.4, 0.5};
  const std::vector<double> high{0.6, 0.7, 0.8, 0.9, 1.0};
  const std::vector<double> low{0.01, 0.02, 0.03, 0.04, 0.05};
  const auto setting = [&](const std::string& name, const std::vector<double>& a) {
    reports::Setting s;
    s.name = s.label = name;
    s.folder = name;
    s.manifest = manifest(5);
    s.runs["one"]["paper"] = {a, a, 0};
    s.runs["two"]["paper"] = {base, base, 0};
    return s;
  };
  data.settings = {setting("base", base), setting("high", high), setting("low", low)};
  data.scenes = {"one", "two"};
  data.groups = {{"one", reports::SceneGroup::Other}, {"two", reports::SceneGroup::Other}};
  data.methods = {"paper"};
  return data;
}

TEST(SettingsReport, MarksWhatTheExactTestFindsSignificant) {
  // Five runs each, no overlap: the exact two-sided p is 2 / C(10, 5) = 2 / 252 = 0.00794.
  const std::string html =
      reports::buildSettingsReportHtml(handMadeSettings(), reports::BuildContext{});
  const Cell high = sceneCell(html, "one", "paper", "high");
  EXPECT_EQ(high.verdict, "better");
  EXPECT_NE(high.title.find("Δ +0.500"), std::string::npos) << high.title;
  EXPECT_NE(high.title.find("p = 0.00794 (exact)"), std::string::npos) << high.title;
  EXPECT_NE(high.text.find("▲"), std::string::npos);
  EXPECT_NE(high.text.find("<b>0.800 ± 0.158</b>"), std::string::npos) << high.text;
  const Cell low = sceneCell(html, "one", "paper", "low");
  EXPECT_EQ(low.verdict, "worse");
  EXPECT_NE(low.text.find("▼"), std::string::npos);
  const Cell equal = sceneCell(html, "two", "paper", "high");
  EXPECT_EQ(equal.verdict, "tie");
  EXPECT_NE(equal.title.find("p = 1"), std::string::npos) << equal.title;
  EXPECT_EQ(equal.text.find("<b>"), std::string::npos) << "equal means: no best";

  // Over both scenes: "high" wins one and ties one, "low" ties one and loses one.
  const std::string overall = section(html, "overall");
  const std::string highTag = tagWith(overall, "<td class=\"num\" data-setting=\"high\"");
  EXPECT_NEAR(std::stod(attribute(highTag, "data-mean")), (0.8 + 0.3) / 2, 1e-12);
  EXPECT_NE(highTag.find("data-wins=\"1\" data-ties=\"1\" data-losses=\"0\""), std::string::npos)
      << highTag;
  const std::string lowTag = tagWith(overall, "<td class=\"num\" data-setting=\"low\"");
  EXPECT_NEAR(std::stod(attribute(lowTag, "data-mean")), (0.03 + 0.3) / 2, 1e-12);
  EXPECT_NE(lowTag.find("data-wins=\"0\" data-ties=\"1\" data-losses=\"1\""), std::string::npos)
      << lowTag;
  EXPECT_NE(html.find("<b>high</b> has the highest mean coverage"), std::string::npos);
}

// A study of one parameter draws each method's mean coverage against the parameter's value,
// in numeric order ("inf" last); a study of two parameters, or none, has no such figure.
TEST(SettingsReport, OneParameterStudiedDrawsMeanCoverageAgainstItsValue) {
  reports::SettingsData data = handMadeSettings();  // base, high, low
  data.parameters = {{"comms.range", "comms.range", {"10", "inf", "5"}}};
  const std::string html = reports::buildSettingsReportHtml(data, reports::BuildContext{});
  const std::string overall = section(html, "overall");
  const std::string figure =
      tagWith(overall, "<figure class=\"panel\" data-figure=\"settings-trend\"");
  EXPECT_EQ(attribute(figure, "data-order"), "5,10,inf");
  // One line, paper's: low (0.165), base (0.3), high (0.55) from left to right, rising (SVG's y
  // runs down).
  const auto at = overall.find("<polyline", overall.find("data-figure=\"settings-trend\""));
  ASSERT_NE(at, std::string::npos);
  const std::string line = overall.substr(at, overall.find("/>", at) - at);
  std::stringstream points(attribute(line, "points"));
  std::vector<double> ys;
  for (std::string pair; points >> pair;)
    ys.push_back(std::stod(pair.substr(pair.find(',') + 1)));
  ASSERT_EQ(ys.size(), 3u) << line;
  EXPECT_GT(ys[0], ys[1]);
  EXPECT_GT(ys[1], ys[2]);
  EXPECT_NEAR((ys[0] - ys[1]) / (ys[1] - ys[2]), (0.3 - 0.165) / (0.55 - 0.3), 1e-3);

  data.parameters.push_back({"global.K", "K", {"50", "100", "200"}});
  EXPECT_EQ(reports::buildSettingsReportHtml(data, reports::BuildContext{}).find("settings-trend"),
            std::string::npos);
}

TEST(SettingsReport, TheReferenceSettingCanBeChosen) {
  reports::SettingsData data = handMadeSettings();
  data.reference = 1;  // "high"
  const std::string html = reports::buildSettingsReportHtml(data, reports::BuildContext{});
  EXPECT_EQ(sceneCell(html, "one", "paper", "base").verdict, "worse");
  EXPECT_EQ(sceneCell(html, "one", "paper", "high").verdict, "reference");
  EXPECT_NE(html.find("reference setting <b>high</b>"), std::string::npos);
}

TEST(SettingsReport, SaysWhatElseDiffersBetweenTheFolders) {
  const ScratchDir dir;
  ASSERT_EQ(benchFixture(dir / "a", "--no-report").exitCode, 0);
  const auto b = runCamcov("bench --scenes " + (testDataDir() / "scenes").string() +
                           " --seeds 2 --duration 2 --methods paper --videos none --no-report "
                           "--set global.K=30 --set planner.T2=0.05 --out " +
                           (dir / "b").string());
  ASSERT_EQ(b.exitCode, 0) << b.err;
  const auto r = runCamcov("report " + (dir / "a").string() + " " + (dir / "b").string() + " -o " +
                           (dir / "both.html").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string settings = section(readFile(dir / "both.html"), "settings");
  EXPECT_NE(settings.find("a ran the methods paper, local, camcov, b ran paper."),
            std::string::npos)
      << settings;
  EXPECT_NE(settings.find("a ran seeds 1–3, b seeds 1–2."), std::string::npos) << settings;
  EXPECT_NE(settings.find("Every parameter is the same in all settings."), std::string::npos);
}

TEST(SettingsReport, BadRequestsExitWithTwo) {
  const ScratchDir dir;
  ASSERT_EQ(benchFixture(dir / "sweep" / "a", "--no-report").exitCode, 0);
  fs::copy(dir / "sweep" / "a", dir / "sweep" / "b", fs::copy_options::recursive);
  fs::create_directories(dir / "empty");
  const std::string a = (dir / "sweep" / "a").string(), b = (dir / "sweep" / "b").string();
  struct Case {
    std::string arguments, message;
  };
  for (const Case& c : {
           Case{a + " " + b, "needs --out FILE"},
           Case{(dir / "sweep").string() + " --reference-setting c",
                "not one of the settings (a, b)"},
           Case{(dir / "empty").string(), "no folder in it is one"},
           Case{a + " " + (dir / "empty").string() + " -o x.html", "no batch.json"},
           Case{a + " --reference-setting a", "compares several results folders"},
       }) {
    const auto r = runCamcov("report " + c.arguments);
    EXPECT_EQ(r.exitCode, 2) << c.arguments;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.arguments << ": " << r.err;
  }
  const auto ok = runCamcov("report " + (dir / "sweep").string() + " --reference-setting b");
  EXPECT_EQ(ok.exitCode, 0) << ok.err;
}

}  // namespace
}  // namespace camcov::testing
