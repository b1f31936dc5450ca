"""The visibility playground (`camcov playground SCENE -o page.html`) in a real browser.

Each test writes a page with the real CLI, opens it from a file:// URL in headless Chromium
driven by Selenium, acts as a person would (mouse drags, the wheel, double-clicks, keys,
buttons) and reads what the page shows, checked against `camcov inspect --json` and `camcov
validate` on the files the page exports. The page is reached through its DOM contract
(reports/playground/playground.js): body[data-ready|data-busy|data-valid|data-sweep-step],
#message, #terms [data-term], #cameras tr[data-camera], svg#world (g.camera[data-camera],
.handle[data-ring|data-vertex], .segment[data-segment]), #edge, #sweep-back, #sweep-forward,
#sweep-step, #time, #fov, #export and its links (#export-scene, #export-poses: data-content).

Every test ends by asserting an empty browser console at level SEVERE; name resolution is off,
so a page that reaches for the network fails.

Run from the repository root with Debian's python (it has selenium):
  PYTHONPATH=tests/support CAMCOV_BINARY=build/src/cli/camcov \\
    /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/playground/test_playground_browser.py
It needs the WebAssembly engine built (Debian's emscripten) and chromium, chromium-driver and
python3-selenium (scripts/install_deps.sh installs them); it fails, rather than skips, without.
"""
import json
import os
import pathlib
import subprocess

import pytest

from browser import start_chromium  # tests/support/browser.py

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.actions.wheel_input import ScrollOrigin
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import WebDriverWait

REPO = pathlib.Path(__file__).resolve().parents[2]
FIG1 = REPO / "scenes" / "fig1_example.json"
TINY = REPO / "tests" / "data" / "scenes" / "tiny_dynamic.json"


def camcov(*args):
    binary = os.environ.get("CAMCOV_BINARY", str(REPO / "build" / "src" / "cli" / "camcov"))
    return subprocess.run([binary, *map(str, args)], capture_output=True, text=True, timeout=120)


class Page:
    def __init__(self, driver):
        self.driver = driver
        self.console = []

    def open(self, page):
        """A page file, or a file:// URL (with a fragment)."""
        self.driver.get(page if str(page).startswith("file:") else pathlib.Path(page).as_uri())
        self.wait(lambda d: d.execute_script("return document.body.dataset.ready") == "1",
                  "the page never became ready")

    def wait(self, condition, what):
        WebDriverWait(self.driver, 20, poll_frequency=0.05).until(condition, what)

    def settled(self):
        """After the page's pending recomputation and two frames."""
        self.driver.execute_async_script(
            "const done = arguments[0];"
            "requestAnimationFrame(() => requestAnimationFrame(() => done()));")
        self.wait(lambda d: d.execute_script("return document.body.dataset.busy") != "1",
                  "the page never finished recomputing")

    def find(self, selector):
        return self.driver.find_element(By.CSS_SELECTOR, selector)

    def all(self, selector):
        return self.driver.find_elements(By.CSS_SELECTOR, selector)

    def text(self, selector):
        return (self.find(selector).get_attribute("textContent") or "").strip()

    def term(self, name):
        return float(self.text(f'#terms [data-term="{name}"]'))

    def drag(self, element, dx, dy, moves=2):
        """Presses on element, moves the mouse by (dx, dy) px in `moves` moves, releases."""
        chain = ActionChains(self.driver).move_to_element(element).click_and_hold()
        for k in range(moves):
            chain.move_by_offset(dx * (k + 1) // moves - dx * k // moves,
                                 dy * (k + 1) // moves - dy * k // moves)
        chain.release().perform()
        self.settled()

    def click_at(self, point):
        """A click on the world at a point in metres, as the mouse would give it."""
        self.driver.execute_script(
            "const svg = document.getElementById('world');"
            "const p = new DOMPoint(arguments[0], -arguments[1]).matrixTransform(svg.getScreenCTM());"
            "svg.dispatchEvent(new MouseEvent('click', {clientX: p.x, clientY: p.y, bubbles: true}));",
            *point)
        self.settled()

    def exported(self, folder):
        """Clicks export; writes the scene and poses it offers into folder: their paths."""
        self.find("#export").click()
        self.wait(lambda d: d.find_element(By.ID, "export-poses").get_attribute("data-content"),
                  "export offered no files")
        scene = folder / self.find("#export-scene").get_attribute("download")
        poses = folder / self.find("#export-poses").get_attribute("download")
        scene.write_text(self.find("#export-scene").get_attribute("data-content"))
        poses.write_text(self.find("#export-poses").get_attribute("data-content"))
        return scene, poses

    def severe(self):
        self.console += self.driver.get_log("browser")
        return [e["message"] for e in self.console if e.get("level") == "SEVERE"]


@pytest.fixture
def page():
    driver = start_chromium()
    yield Page(driver)
    driver.quit()


def write_page(folder, scene=FIG1, *extra):
    out = folder / "playground.html"
    result = camcov("playground", scene, "-o", out, *extra)
    assert result.returncode == 0, result.stdout + result.stderr
    return out


def inspect(scene, poses, time):
    result = camcov("inspect", scene, "--time", time, "--cameras", poses, "--json")
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def test_a_dragged_camera_gives_the_coverage_camcov_inspect_computes(page, tmp_path):
    page.open(write_page(tmp_path))
    before = page.term("coverage")
    camera = page.find('g.camera[data-camera="0"] .body')
    page.drag(camera, 60, -40)
    assert page.term("coverage") != before, "the drag changed nothing"
    scene, poses = page.exported(tmp_path)
    moved = json.loads(poses.read_text())[0]
    assert (moved["x"], moved["y"]) != (-8.0, -5.5), "the camera did not move"
    reference = inspect(scene, poses, 0)
    for term in ("coverage", "utilization", "repulsion", "reward"):
        assert abs(page.term(term) - reference[term]) <= 1e-9, term
    assert page.text("#export-command") == \
        f"camcov inspect {scene.name} --time 0 --cameras {poses.name} --json"
    # The one-file case for tests/data/visibility_cases/ holds the same.
    case = json.loads(page.find("#export-case").get_attribute("data-content"))
    assert case == {"scene": json.loads(scene.read_text()), "time": 0,
                    "poses": json.loads(poses.read_text())}
    # The wheel turns the camera 2° a notch.
    yaw = float(page.text('#cameras tr[data-camera="0"] td:nth-child(3)').rstrip("°"))
    page.driver.execute_script(
        "arguments[0].dispatchEvent(new WheelEvent('wheel', {deltaY: -100, bubbles: true,"
        " cancelable: true}));", page.find('g.camera[data-camera="0"]'))
    page.settled()
    turned = float(page.text('#cameras tr[data-camera="0"] td:nth-child(3)').rstrip("°"))
    assert turned == pytest.approx(yaw + 2.0, abs=1e-6)
    assert not page.severe(), page.severe()


def test_a_vertex_dragged_into_a_bow_tie_shows_the_validators_words(page, tmp_path):
    page.open(write_page(tmp_path))
    segments = len(page.all(".segment"))
    coverage = page.term("coverage")
    # Target 0's vertex 0 dragged out past the middle of its edge from vertex 1 to 2: the edge
    # back from vertex 3 then crosses that edge.
    handles = [page.find(f'.handle[data-ring="target 0"][data-vertex="{k}"]') for k in range(4)]
    at = [(h.location["x"], h.location["y"]) for h in handles]
    centre = [sum(p[i] for p in at) / 4 for i in (0, 1)]
    middle = [(at[1][i] + at[2][i]) / 2 for i in (0, 1)]
    goal = [middle[i] + 0.6 * (middle[i] - centre[i]) for i in (0, 1)]
    # In one move: every state the page computes on the way is the bow-tie.
    page.drag(handles[0], int(goal[0] - at[0][0]), int(goal[1] - at[0][1]), moves=1)
    page.wait(lambda d: d.find_element(By.ID, "message").is_displayed(), "no message shown")
    message = page.text("#message")
    assert "intersects itself" in message, message
    assert page.driver.execute_script("return document.body.dataset.valid") == "0"
    # The last valid picture stays.
    assert len(page.all(".segment")) == segments and page.term("coverage") == coverage
    scene, _ = page.exported(tmp_path)
    validated = camcov("validate", scene)
    assert validated.returncode == 2
    # The same words, file name and JSON path included.
    assert message.split(": ", 1)[1] in validated.stdout + validated.stderr, \
        (message, validated.stdout + validated.stderr)
    assert not page.severe(), page.severe()


def test_a_camera_dragged_into_an_obstacle_shows_the_validators_words(page, tmp_path):
    page.open(write_page(tmp_path))
    camera = page.find('g.camera[data-camera="0"] .body')
    obstacle = page.find('polygon[data-kind="obstacle"]')
    start, goal = camera.rect, obstacle.rect
    dx = goal["x"] + goal["width"] / 2 - (start["x"] + start["width"] / 2)
    dy = goal["y"] + goal["height"] / 2 - (start["y"] + start["height"] / 2)
    page.drag(camera, int(dx), int(dy), moves=1)
    page.wait(lambda d: d.find_element(By.ID, "message").is_displayed(), "no message shown")
    message = page.text("#message")
    assert "cameras[0].pos" in message and "inside obstacles[0]" in message, message
    scene, _ = page.exported(tmp_path)
    validated = camcov("validate", scene)
    assert validated.returncode == 2
    assert message.split(": ", 1)[1] in validated.stdout + validated.stderr
    assert not page.severe(), page.severe()


def test_vertices_are_added_and_deleted_and_the_numbers_follow(page, tmp_path):
    page.open(write_page(tmp_path))
    count = len(page.all('.handle[data-ring="obstacle 0"]'))
    # Double-click the middle of the obstacle's edge 0.
    a = page.find('.handle[data-ring="obstacle 0"][data-vertex="0"]')
    b = page.find('.handle[data-ring="obstacle 0"][data-vertex="1"]')
    page.driver.execute_script(
        "const a = arguments[0].getBoundingClientRect(), b = arguments[1].getBoundingClientRect();"
        "document.getElementById('world').dispatchEvent(new MouseEvent('dblclick', {bubbles: true,"
        " clientX: (a.x + a.width / 2 + b.x + b.width / 2) / 2,"
        " clientY: (a.y + a.height / 2 + b.y + b.height / 2) / 2}));", a, b)
    page.settled()
    assert len(page.all('.handle[data-ring="obstacle 0"]')) == count + 1
    page.find("body").send_keys(Keys.DELETE)
    page.settled()
    assert len(page.all('.handle[data-ring="obstacle 0"]')) == count
    scene, poses = page.exported(tmp_path)
    assert abs(page.term("coverage") - inspect(scene, poses, 0)["coverage"]) <= 1e-9
    assert not page.severe(), page.severe()


def test_a_sweep_steps_forward_and_back_and_an_edge_says_who_sees_it(page, tmp_path):
    page.open(write_page(tmp_path))
    page.find('#cameras tr[data-camera="1"]').click()
    page.settled()
    for _ in range(3):
        page.find("#sweep-forward").click()
    assert page.driver.execute_script("return document.body.dataset.sweepStep") == "2"
    assert page.text("#sweep-step").startswith("event 3 of ")
    assert page.all(".sweep-ray") and page.all(".sweep-hit")
    page.find("#sweep-back").click()
    assert page.text("#sweep-step").startswith("event 2 of ")
    # An edge: who sees it and why the others do not, as camcov inspect says.
    scene, poses = page.exported(tmp_path)
    reference = inspect(scene, poses, 0)
    seen = max((i for i, s in enumerate(reference["segments"]) if s["visibleBy"]),
               key=lambda i: reference["segments"][i]["length"])
    a, b = reference["segments"][seen]["a"], reference["segments"][seen]["b"]
    page.click_at(((a[0] + b[0]) / 2, (a[1] + b[1]) / 2))
    assert page.find(".segment.selected").get_attribute("data-segment") == str(seen)
    expected = ", ".join(map(str, reference["segments"][seen]["visibleBy"]))
    page.wait(lambda d: d.find_element(By.CSS_SELECTOR, '#edge [data-field="visibleBy"]').text
              == f"seen by camera {expected}", "the edge's visibleBy")
    assert not page.severe(), page.severe()


def test_time_and_the_field_of_view_change_the_picture_as_camcov_computes_it(page, tmp_path):
    page.open(write_page(tmp_path, TINY))
    time = page.find("#time")
    page.driver.execute_script(
        "arguments[0].value = '1.5'; arguments[0].dispatchEvent(new Event('input'));", time)
    page.settled()
    page.driver.execute_script(
        "const f = document.getElementById('fov'); f.value = '45';"
        " f.dispatchEvent(new Event('input'));")
    page.settled()
    scene, poses = page.exported(tmp_path)
    assert json.loads(scene.read_text())["cameras"][0]["cameraFoV"] == 45
    reference = inspect(scene, poses, 1.5)
    assert abs(page.term("coverage") - reference["coverage"]) <= 1e-9
    resources = page.driver.execute_script(
        "return performance.getEntriesByType('resource').map((e) => e.name);")
    assert not [r for r in resources if not r.startswith(("file:", "data:", "blob:"))]
    assert not page.severe(), page.severe()


def test_the_explorer_opens_a_step_in_the_playground_at_its_time_and_poses(page, tmp_path):
    result = camcov("run", TINY, "--method", "paper", "--seed", 1, "--set", "sim.duration=3",
                    "--out", tmp_path)
    assert result.returncode == 0, result.stderr
    run_file = tmp_path / "tiny_dynamic-paper-seed1.json"
    run = json.loads(run_file.read_text())
    playground = write_page(tmp_path, TINY)
    explorer = tmp_path / "explore.html"
    result = camcov("explore", run_file, "--playground", playground, "-o", explorer)
    assert result.returncode == 0, result.stdout + result.stderr
    page.driver.get(explorer.as_uri())
    page.wait(lambda d: d.execute_script("return document.body.dataset.ready") == "1",
              "the explorer never became ready")
    k = 17
    page.driver.execute_script(
        "const s = document.getElementById('slider'); s.value = arguments[0];"
        " s.dispatchEvent(new Event('input'));", str(k))
    page.wait(lambda d: d.execute_script("return document.body.dataset.step") == str(k),
              "the explorer did not seek")
    link = page.find("a.playground").get_attribute("href")
    assert link.startswith(playground.as_uri() + "#t="), link
    page.open(link)
    time = run["series"]["time"][k]
    assert page.text("#time-value") == f"t = {time:.2f} s"
    # The poses of the step (to the millimetre the explorer keeps) and the run's coverage there.
    scene, poses = page.exported(tmp_path)
    shown = json.loads(poses.read_text())
    for pose, recorded in zip(shown, run["series"]["cameras"]):
        assert abs(pose["x"] - recorded[k][0]) <= 1e-3 and abs(pose["y"] - recorded[k][1]) <= 1e-3
    assert abs(page.term("coverage") - inspect(scene, poses, time)["coverage"]) <= 1e-9
    assert abs(page.term("coverage") - run["series"]["coverage"][k]) <= 1e-2
    assert not page.severe(), page.severe()


# ----------------------------------------------------------------------------- a crowd
# 40 people (discs of 0.25 m, 12-gons) walking across a 60 m × 40 m plaza, as a recording of
# pedestrians gives them (`camcov import csv`): each person is under 1% of the room across.

def crowd_page(folder):
    rows = ["id,t,x,y"]
    for i in range(40):
        x, y = 2 + (i * 37) % 56, 2 + (i * 23) % 36
        rows += [f"{i},{k},{x + 0.8 * k},{y}" for k in range(5)]
    table = folder / "crowd.csv"
    table.write_text("\n".join(rows) + "\n")
    scene = folder / "crowd.json"
    result = camcov("import", "csv", table, "--cameras", 4, "-o", scene)
    assert result.returncode == 0, result.stderr
    return write_page(folder, scene)


# Every vertex handle on screen: its centre and radius in px.
HANDLES_JS = """
return Array.from(document.querySelectorAll("#world .handle")).map((h) => {
  const r = h.getBoundingClientRect();
  return [r.left + r.width / 2, r.top + r.height / 2, r.width / 2];
});
"""


def overlapping_handles(page):
    handles = page.driver.execute_script(HANDLES_JS)
    return handles, [(a, b) for i, a in enumerate(handles) for b in handles[i + 1:]
                     if ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5 < a[2] + b[2] - 0.5]


def people_across(page):
    """Each person's size on screen, px (the larger side of the polygon drawn)."""
    return page.driver.execute_script(
        "return Array.from(document.querySelectorAll('#world polygon.object[data-kind=\"target\"]'))"
        ".map((p) => { const r = p.getBoundingClientRect(); return Math.max(r.width, r.height); })")


def test_a_crowd_is_drawn_enlarged_without_blobs_of_handles(page, tmp_path):
    page.driver.set_window_size(1400, 900)
    page.open(crowd_page(tmp_path).as_uri() + "#t=1")
    sizes = people_across(page)
    assert len(sizes) == 40, sizes
    assert min(sizes) >= 12, f"people drawn {min(sizes):.1f} px across: too small to see"
    handles, overlaps = overlapping_handles(page)
    assert handles, "not even the plaza's corners have handles"
    assert not overlaps, f"{len(overlaps)} pairs of {len(handles)} handles overlap"
    assert not page.severe(), page.severe()


def view_box(page):
    return [float(v) for v in page.driver.execute_script(
        "return document.getElementById('world').getAttribute('viewBox')").split()]


def test_the_wheel_zooms_a_drag_pans_and_whole_scene_resets(page, tmp_path):
    page.driver.set_window_size(1400, 900)
    page.open(crowd_page(tmp_path).as_uri() + "#t=1")
    home = view_box(page)
    person = page.find('#world polygon.object[data-kind="target"][data-id="0"]')
    # Zoomed about one person until people are drawn at true size: their own vertex handles
    # appear, still clear of each other.
    for _ in range(8):
        ActionChains(page.driver).scroll_from_origin(
            ScrollOrigin.from_element(page.find('#world polygon.object[data-id="0"]')), 0, -300) \
            .perform()
        page.settled()
    zoomed = view_box(page)
    assert zoomed[2] < home[2] / 20, f"the wheel did not zoom in: {home} -> {zoomed}"
    handles, overlaps = overlapping_handles(page)
    assert len(page.all('#world .handle[data-ring="target 0"]')) == 12, \
        "at true size a person gets its 12 vertex handles"
    assert not overlaps, overlaps
    # A drag on the floor pans: 120 px to the left shows what lay 120 px to the right, and is
    # not a click (no edge gets explained).
    scale = zoomed[2] / page.find("#world").rect["width"]
    floor = page.find("#world")
    ActionChains(page.driver).move_to_element_with_offset(floor, 5, 5).click_and_hold() \
        .move_by_offset(-60, 0).move_by_offset(-60, 0).release().perform()
    page.settled()
    panned = view_box(page)
    assert panned[0] == pytest.approx(zoomed[0] + 120 * scale, rel=0.05, abs=3 * scale), \
        (zoomed, panned)
    assert not page.all("#world .segment.selected"), "the end of the pan selected an edge"
    page.find("#zoom-reset").click()
    page.settled()
    assert view_box(page) == pytest.approx(home)
    assert not page.severe(), page.severe()
