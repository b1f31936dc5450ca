"""The report's layout as a real browser computes it: headless Chromium driven by Selenium
(tests/support/browser.py) opens a report of the three default methods in a 1400 × 900 window
and reads the boxes it laid out. The summary tables fit the page (no column behind a scrollbar,
no element wider than the window, even with a scene's weighted and resolved lines) and no
method's name is torn from its colour dot; the verdict rule is stated once; the box plots'
boxes get room to read; a camera's label in Fig. 3 sits beside its camera; the videos come in
the method order of every table; the header's command names `camcov`, not where it was built.
A self-check shows the measurement sees a table that does not fit, in a window too narrow for it.

Run from the repository root with the Debian python (it has selenium):
  CAMCOV_BINARY=build/src/cli/camcov CAMCOV_REPORTS_SCREENSHOTS=DIR \\
    /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/reports/test_report_layout_browser.py
"""
import json
import os
import pathlib
import shutil
import subprocess

import pytest

from browser import start_chromium  # tests/support/browser.py
from selenium.webdriver.common.by import By

REPO = pathlib.Path(__file__).resolve().parents[2]
# The two tiny scenes and our scene of the longest name, which the scene column must hold.
# Rooms of our own whose cameras have little free room beside them, for the labels of Fig. 3.
SCENES = [REPO / "tests" / "data" / "scenes", REPO / "scenes" / "dynamic_fast_target_slow_cameras.json",
          *(REPO / "scenes" / f"{name}.json" for name in ("l_shaped_room", "walking_figures",
                                                          "crowd_large_room", "sliding_door"))]
METHODS = ["paper", "local", "camcov"]  # the table of methods' order (control/methods.h)

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
// Every element whose box reaches past the window's right edge (inside a scrolling box or not).
const wider = Array.from(document.querySelectorAll("body *"))
  .filter((e) => e.getBoundingClientRect().right > document.documentElement.clientWidth + 0.5)
  .map((e) => `${e.tagName.toLowerCase()}.${e.className.baseVal ?? e.className}: ` +
              `${(e.textContent || "").trim().slice(0, 40)}`).slice(0, 10);
return {tables, torn, wider, window: window.innerWidth,
        pageScrolls: document.documentElement.scrollWidth - document.documentElement.clientWidth};
"""


def weighted_resolved_scene(folder):
    """tiny_dynamic with importance weights and a resolution (docs/scene-format.md): its table
    rows carry a weighted and a resolved line under the mean, the widest cells of the summary."""
    scene = json.loads((REPO / "tests" / "data" / "scenes" / "tiny_dynamic.json").read_text())
    edges = scene["targets"][0]["shape"].count(",") + 1
    scene["targets"][0]["edgeWeights"] = [4] + [1] * (edges - 1)
    scene["imageWidth"] = 640
    scene["resolution"] = {"minDensity": 20}
    path = folder / "weighted_and_resolved_with_a_long_name.json"
    path.write_text(json.dumps(scene))
    return path


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    binary = os.environ.get("CAMCOV_BINARY")
    if not binary:
        pytest.fail("CAMCOV_BINARY is not set: it names the camcov CLI to test", pytrace=False)
    folder = tmp_path_factory.mktemp("layout")
    out = folder / "bench"
    result = subprocess.run(
        [binary, "bench", "--scenes", *map(str, SCENES), weighted_resolved_scene(folder),
         "--methods", ",".join(METHODS), "--seeds", "2", "--duration", "0.5",
         "--set", "global.K=30", "--videos", "none", "--explorer", "none",
         "--optimum-budget", "0", "--jobs", "2", "--out", str(out)],
        capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    return out / "report.html"


@pytest.fixture(scope="module")
def report_with_videos(report, tmp_path_factory):
    """The same results with videos as `camcov bench --videos` names them (empty files: their
    order is what is read), reported again: the report lists what videos/ holds."""
    out = tmp_path_factory.mktemp("videos") / "bench"
    shutil.copytree(report.parent, out)
    (out / "videos").mkdir()
    for method in sorted(METHODS):
        (out / "videos" / f"tiny_static-{method}-seed1.mp4").write_bytes(b"")
    result = subprocess.run([os.environ["CAMCOV_BINARY"], "report", str(out)],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    return out / "report.html"


@pytest.fixture
def browser():
    driver = start_chromium(width=1400, height=900)
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
    assert not layout["wider"], f"elements reach past the window's right edge: {layout['wider']}"
    assert not layout["torn"], f"method names wrapped away from their dots: {layout['torn']}"
    severe = [e["message"] for e in browser.get_log("browser") if e.get("level") == "SEVERE"]
    assert not severe, severe


def test_the_measurement_sees_a_table_wider_than_its_window(report, browser):
    browser.set_window_size(700, 1000)
    browser.get(report.as_uri())
    layout = browser.execute_script(MEASURE)
    assert any(t["scrolls"] > 0 and t["width"] > t["room"] for t in layout["tables"]), layout


def test_the_verdict_rule_is_said_once_and_everything_else_points_to_it(report, browser):
    browser.get(report.as_uri())
    text = browser.execute_script("return document.body.innerText")
    assert text.count("A12 > 0.5") == 1, "the rule of docs/statistics.md, word for word, " \
        f"{text.count('A12 > 0.5')} times"
    links = browser.execute_script(
        "return Array.from(document.querySelectorAll('a[href=\"#verdict-rule\"]')).length")
    assert links >= 2, "the header's verdicts and the pairs point to the rule"
    rule = browser.find_element(By.ID, "verdict-rule")
    assert "A12 > 0.5" in rule.text


def test_box_plots_give_their_boxes_room_to_read(report, browser):
    """The plot area (the axes' height on screen) of every box plot, whatever the scene names
    slanted below it take."""
    browser.get(report.as_uri())
    heights = browser.execute_script(
        "return Array.from(document.querySelectorAll('figure[data-figure=\"box\"] svg'))"
        ".map((svg) => svg.querySelector('path.axes, path[fill=\"none\"]')"
        ".getBoundingClientRect().height)")
    assert heights, "no box plot"
    assert min(heights) >= 200, f"box plot areas {heights} px high"


# Per scene picture of Fig. 3: each label reading "cam J…", its distance on screen from camera
# J's centre to the nearest point of the label's box, and the px on screen per px drawn.
CAMERA_LABELS = """
return Array.from(document.querySelectorAll("#scenes svg.scene")).flatMap((svg) => {
  const scale = svg.getBoundingClientRect().width / svg.viewBox.baseVal.width;
  const cameras = svg.querySelectorAll("g.camera");
  return Array.from(svg.querySelectorAll("text.label")).flatMap((label) => {
    // A two-line label's first line is its name.
    const match = /^cam (\\d+)$/.exec(label.querySelector("tspan").textContent.split(" · ")[0]);
    if (!match) return [];
    const body = cameras[Number(match[1])].querySelector("circle").getBoundingClientRect();
    const cx = body.left + body.width / 2, cy = body.top + body.height / 2;
    const box = label.getBoundingClientRect();
    const dx = Math.max(box.left - cx, 0, cx - box.right);
    const dy = Math.max(box.top - cy, 0, cy - box.bottom);
    return [{label: label.textContent, scene: svg.getAttribute("aria-label"),
             distance: Math.hypot(dx, dy), scale}];
  });
});
"""


def test_a_camera_label_sits_beside_its_camera(report, browser):
    """No camera's label in the open, far from its camera: its nearest point within 40 px
    drawn of the camera's centre (the dot and at most 24 px of gap, the corner of a label set
    diagonally a √2 farther)."""
    browser.get(report.as_uri())
    labels = browser.execute_script(CAMERA_LABELS)
    assert len(labels) >= 10, labels
    far = [f"{l['scene']}: '{l['label']}' {l['distance'] / l['scale']:.0f} px away"
           for l in labels if l["distance"] > 40 * l["scale"]]
    assert not far, far


def test_videos_come_in_the_method_order_of_every_table(report_with_videos, browser):
    browser.get(report_with_videos.as_uri())
    captions = [c.text for c in browser.find_elements(By.CSS_SELECTOR, "#videos figcaption")]
    assert captions == [f"tiny_static-{m}-seed1" for m in METHODS], captions
    rows = browser.execute_script(
        "return Array.from(document.querySelectorAll('table.summary tbody')[0].rows)"
        ".map((r) => r.querySelector('.method-mark').textContent.trim())")
    assert rows == METHODS, rows


def test_the_header_shows_the_command_as_a_reader_types_it(report, browser):
    browser.get(report.as_uri())
    facts = browser.find_elements(By.CSS_SELECTOR, "header dl.facts dt")
    command = next(dt for dt in facts if dt.text == "Command").find_element(
        By.XPATH, "following-sibling::dd[1]").text
    assert command.startswith("camcov bench --scenes "), command
