"""The report's layout as a real browser computes it: headless Chromium driven by Selenium
(tests/support/browser.py) opens a report of the three default methods in a 1400 px window and
reads the boxes it laid out. The summary tables fit the page (no column behind a scrollbar)
and no method's name is torn from its colour dot. A self-check shows the measurement sees a
table that does not fit, in a window too narrow for it.

Run from the repository root with the Debian python (it has selenium):
  CAMCOV_BINARY=build/src/cli/camcov CAMCOV_REPORTS_SCREENSHOTS=DIR \\
    /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/reports/test_report_layout_browser.py
"""
import os
import pathlib
import subprocess

import pytest

from browser import start_chromium  # tests/support/browser.py

REPO = pathlib.Path(__file__).resolve().parents[2]
# The two tiny scenes and our scene of the longest name, which the scene column must hold.
SCENES = [REPO / "tests" / "data" / "scenes", REPO / "scenes" / "dynamic_fast_target_slow_cameras.json"]

# Per summary table: its width, the width of the box it scrolls in, and how far that box
# scrolls; the page's own horizontal scroll; the method names that take more than one line.
MEASURE = """
const tables = Array.from(document.querySelectorAll("table.summary")).map((t) => {
  const wrap = t.closest(".table-wrap");
  const lastHeader = t.tHead.rows[0].cells[t.tHead.rows[0].cells.length - 1];
  return {group: t.dataset.group, width: t.getBoundingClientRect().width,
          room: wrap.clientWidth, scrolls: wrap.scrollWidth - wrap.clientWidth,
          lastColumnEnd: lastHeader.getBoundingClientRect().right,
          pageEnd: wrap.getBoundingClientRect().right};
});
const torn = Array.from(document.querySelectorAll("table.summary .method-mark"))
  .filter((m) => m.getClientRects().length > 1).map((m) => m.textContent);
return {tables, torn, window: window.innerWidth,
        pageScrolls: document.documentElement.scrollWidth - document.documentElement.clientWidth};
"""


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    binary = os.environ.get("CAMCOV_BINARY")
    if not binary:
        pytest.fail("CAMCOV_BINARY is not set: it names the camcov CLI to test", pytrace=False)
    out = tmp_path_factory.mktemp("layout") / "bench"
    result = subprocess.run(
        [binary, "bench", "--scenes", *map(str, SCENES), "--seeds", "2", "--duration", "0.5",
         "--set", "global.K=30", "--videos", "none", "--explorer", "none",
         "--optimum-budget", "0", "--jobs", "2", "--out", str(out)],
        capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    return out / "report.html"


@pytest.fixture
def browser():
    driver = start_chromium(width=1400, height=1000)
    yield driver
    driver.quit()


def screenshot(driver, name, tmp_path):
    folder = pathlib.Path(os.environ.get("CAMCOV_REPORTS_SCREENSHOTS") or tmp_path)
    folder.mkdir(parents=True, exist_ok=True)
    driver.execute_script("document.querySelector('#summary').scrollIntoView()")
    driver.save_screenshot(str(folder / name))


def test_summary_tables_fit_a_1400_px_window_without_hiding_columns(report, browser, tmp_path):
    browser.get(report.as_uri())
    layout = browser.execute_script(MEASURE)
    screenshot(browser, "summary-1400.png", tmp_path)
    assert layout["window"] == 1400, layout
    assert len(layout["tables"]) == 2, "a static and a dynamic group"
    for table in layout["tables"]:
        assert table["width"] <= table["room"] + 0.5, table
        assert table["scrolls"] <= 0, table
        assert table["lastColumnEnd"] <= table["pageEnd"] + 0.5, table
    assert layout["pageScrolls"] <= 0, layout
    assert not layout["torn"], f"method names wrapped away from their dots: {layout['torn']}"
    severe = [e["message"] for e in browser.get_log("browser") if e.get("level") == "SEVERE"]
    assert not severe, severe


def test_the_measurement_sees_a_table_wider_than_its_window(report, browser):
    browser.set_window_size(700, 1000)
    browser.get(report.as_uri())
    layout = browser.execute_script(MEASURE)
    assert any(t["scrolls"] > 0 and t["width"] > t["room"] for t in layout["tables"]), layout
