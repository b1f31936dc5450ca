// The report in a real browser: headless Chromium (Debian package `chromium`) opens it from a
// file:// URL, takes screenshots into the build tree (tests/reports/screenshots/), and the
// test fails on any console error, uncaught exception, failed load or blocked fetch — or if
// Chromium does not start at all.
//
// Errors are collected by a small script injected at the top of a copy of the report (the
// report itself logs nothing): it records console.error calls, error events (scripts, and
// resources such as a missing video, caught in the capture phase), unhandled rejections and
// Content-Security-Policy violations into attributes of <html>, which --dump-dom prints.
#include <gtest/gtest.h>

#include <cstdlib>

#include "report_fixture.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kScreenshots = fs::path(CAMCOV_REPORTS_TEST_OUTPUT_DIR) / "screenshots";

constexpr const char* kErrorCollector = R"(<script>
(() => {
  const errors = [];
  const record = (what) => {
    errors.push(String(what));
    document.documentElement.setAttribute("data-test-errors", errors.join(" | "));
  };
  const consoleError = console.error;
  console.error = (...args) => { record("console.error: " + args.join(" ")); consoleError(...args); };
  window.addEventListener("error", (e) => {
    const t = e.target;
    record(t && t !== window ? "failed to load <" + t.tagName + "> " + (t.currentSrc || t.src || t.href)
                             : "uncaught: " + e.message);
  }, true);
  window.addEventListener("unhandledrejection", (e) => record("unhandled rejection: " + e.reason));
  document.addEventListener("securitypolicyviolation",
                            (e) => record("blocked by CSP: " + e.blockedURI));
  window.addEventListener("load", () => document.documentElement.setAttribute("data-test-loaded", "1"));
})();
</script>
)";

// CAMCOV_CHROMIUM, else `chromium` on the PATH; empty if neither.
std::string chromium() {
  if (const char* env = std::getenv("CAMCOV_CHROMIUM"); env != nullptr && *env != '\0') return env;
  const auto r = runShell("command -v chromium");
  return r.exitCode == 0 ? r.out.substr(0, r.out.find('\n')) : std::string();
}

// One headless run with a fresh profile; `timeout` keeps a hung browser from hanging the test.
CommandResult runChromium(const fs::path& profile, const std::string& arguments) {
  return runShell("timeout 90 " + chromium() +
                  " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                  " --disable-background-networking --disable-component-update --disable-sync"
                  " --hide-scrollbars --user-data-dir=" +
                  profile.string() + " " + arguments);
}

// The errors the injected collector saw while `page` loaded, or a reason the check could not
// run. Writes an instrumented copy beside `page`, so relative URLs resolve the same.
std::string consoleErrors(const fs::path& page, const fs::path& scratch) {
  std::string html = readFile(page);
  const auto head = html.find("<head>");
  if (head == std::string::npos) return "no <head> in " + page.string();
  html.insert(head + 6, kErrorCollector);
  const fs::path copy = page.parent_path() / ("instrumented-" + page.filename().string());
  std::ofstream(copy, std::ios::binary) << html;
  // The virtual time budget lets late events (media metadata, timers) happen before the dump.
  const auto r =
      runChromium(scratch / "profile-dom",
                  "--virtual-time-budget=3000 --dump-dom 'file://" + copy.string() + "'");
  fs::remove(copy);
  if (r.exitCode != 0) return "chromium failed (exit " + std::to_string(r.exitCode) + "): " + r.err;
  if (r.out.find("data-test-loaded=\"1\"") == std::string::npos) {
    return "the page never finished loading: " + r.out.substr(0, 300);
  }
  const auto at = r.out.find("data-test-errors=\"");
  if (at == std::string::npos) return {};
  return r.out.substr(at, r.out.find('"', at + 18) - at);
}

class Browser : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_FALSE(chromium().empty())
        << "headless Chromium is needed: install the Debian package `chromium` "
           "(scripts/install_deps.sh does), or point CAMCOV_CHROMIUM at a binary";
  }
  ScratchDir dir_;
};

TEST_F(Browser, OpensTheReportWithoutConsoleErrorsAndTakesScreenshots) {
  const auto bench = benchFixture(dir_ / "results");
  ASSERT_EQ(bench.exitCode, 0) << bench.err;
  const fs::path report = dir_ / "results" / "report.html";
  EXPECT_EQ(consoleErrors(report, dir_.path()), "");

  fs::create_directories(kScreenshots);
  // A laptop's first screen, and the whole page for a person to look at.
  for (const auto& [name, size] :
       {std::pair{"report-laptop.png", "1366,900"}, std::pair{"report-full.png", "1366,5200"}}) {
    const fs::path shot = kScreenshots / name;
    fs::remove(shot);
    const auto r =
        runChromium(dir_ / ("profile-" + std::string(name)),
                    "--window-size=" + std::string(size) + " --screenshot=" + shot.string() +
                        " 'file://" + report.string() + "'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_TRUE(fs::exists(shot)) << r.err;
    EXPECT_EQ(readFile(shot).substr(1, 3), "PNG");
    EXPECT_GT(fs::file_size(shot), 20000u) << "a blank page compresses to almost nothing";
    EXPECT_EQ(r.err.find("Uncaught"), std::string::npos) << r.err;
  }
}

TEST_F(Browser, OpensTheSettingsReportWithoutConsoleErrors) {
  ASSERT_EQ(benchFixture(dir_ / "sweep" / "global.K=30", "--no-report").exitCode, 0);
  ASSERT_EQ(benchFixture(dir_ / "sweep" / "global.K=60", "--set global.K=60").exitCode, 0);
  const auto r = runCamcov("report " + (dir_ / "sweep").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const fs::path report = dir_ / "sweep" / "report.html";
  EXPECT_EQ(consoleErrors(report, dir_.path()), "");
  fs::create_directories(kScreenshots);
  const fs::path shot = kScreenshots / "settings-report.png";
  fs::remove(shot);
  const auto s = runChromium(dir_ / "profile-settings",
                             "--window-size=1366,1800 --screenshot=" + shot.string() + " 'file://" +
                                 report.string() + "'");
  ASSERT_EQ(s.exitCode, 0) << s.err;
  EXPECT_GT(fs::file_size(shot), 20000u) << "a blank page compresses to almost nothing";
}

TEST_F(Browser, TheCheckCatchesErrorsAndBlockedFetches) {
  // The harness must be able to fail: a page with a script error, a console error and an
  // image from the network, under the report's own policy.
  const fs::path page = dir_ / "broken.html";
  std::ofstream(page) << R"(<!DOCTYPE html><html><head><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; script-src 'unsafe-inline'; img-src data:">
<title>broken</title></head><body><img src="https://example.invalid/x.png">
<script>console.error("boom"); undefinedFunction();</script></body></html>)";
  const std::string errors = consoleErrors(page, dir_.path());
  EXPECT_NE(errors.find("console.error: boom"), std::string::npos) << errors;
  EXPECT_NE(errors.find("uncaught"), std::string::npos) << errors;
  EXPECT_NE(errors.find("blocked by CSP: https://example.invalid/x.png"), std::string::npos)
      << errors;
}

}  // namespace
}  // namespace camcov::testing
