"""The explorer page (`camcov explore RUN.json... -o page.html`) in a real browser.

Each test records short runs of tests/data/scenes/tiny_dynamic.json with the real CLI
(`camcov run`), writes their page with `camcov explore`, opens it from a file:// URL in headless
Chromium driven by Selenium, and checks what the page shows against independent sources:
the run's JSON (`series`: time, coverage, utilization, camera poses per step) and
`camcov inspect --json` (the segments S and who sees them, at a step's poses and time).
The page is reached only through its DOM contract: body[data-ready|data-step], #play,
#step-back, #step-forward, #slider, #time, the keyboard, section.run[data-run] with .coverage,
.utilization, svg.world (.segment[data-segment|data-target|data-edge], g.camera[data-camera])
and .info ([data-field=visibleBy|length|pose]), and svg.timeline.

Every test ends by asserting that the browser console logged nothing at level SEVERE
(console.error, uncaught exceptions, failed loads); a self-check shows that this catches a
console.error. Name resolution is disabled in the browser, so a page that reaches for the
network fails too.

Run from the repository root with the Debian python (it has selenium):
  CAMCOV_BINARY=build/src/cli/camcov CAMCOV_EXPLORER_SCREENSHOTS=DIR \\
    /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/explorer/test_explorer_browser.py
It needs the Debian packages chromium, chromium-driver and python3-selenium
(scripts/install_deps.sh installs them) and fails, rather than skips, without them.
Screenshots go to $CAMCOV_EXPLORER_SCREENSHOTS (else the test's tmp_path).
"""
import io
import json
import math
import os
import pathlib
import re
import subprocess
import time

import pytest
from PIL import Image

from browser import start_chromium  # tests/support/browser.py

try:
    from selenium import webdriver
    from selenium.common.exceptions import (ElementClickInterceptedException,
                                            ElementNotInteractableException,
                                            NoSuchElementException,
                                            StaleElementReferenceException,
                                            TimeoutException, WebDriverException)
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.actions.wheel_input import ScrollOrigin
    from selenium.webdriver.common.actions.action_builder import ActionBuilder
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import WebDriverWait
except ImportError:  # reported by the `explorer` fixture, so that every test fails
    webdriver = None

REPO = pathlib.Path(__file__).resolve().parents[2]
SCENE = REPO / "tests" / "data" / "scenes" / "tiny_dynamic.json"
WAIT_SECONDS = 15


# ----------------------------------------------------------------------------- the camcov CLI

@pytest.fixture
def camcov():
    """Runs the camcov CLI from the repository root: camcov("run", ...) -> CompletedProcess."""
    binary = os.environ.get("CAMCOV_BINARY")
    if not binary:
        pytest.fail("CAMCOV_BINARY is not set: it names the camcov CLI to test", pytrace=False)
    binary = pathlib.Path(binary).resolve()
    if not binary.is_file():
        pytest.fail(f"CAMCOV_BINARY={binary} does not exist (cmake --build build)", pytrace=False)

    def run(*args):
        return subprocess.run([str(binary), *map(str, args)], cwd=REPO, capture_output=True,
                              text=True, timeout=300)

    return run


def record_run(camcov, folder, method, scene=SCENE, duration=3):
    """A run of `scene` (default: 3 s of tiny_dynamic) with `method`, seed 1: (its JSON file,
    its parsed JSON)."""
    result = camcov("run", scene, "--method", method, "--seed", 1, "--set",
                    f"sim.duration={duration}", "--out", folder)
    assert result.returncode == 0, f"camcov run failed:\n{result.stderr}"
    path = pathlib.Path(folder) / f"{pathlib.Path(scene).stem}-{method}-seed1.json"
    assert path.is_file(), f"camcov run did not write {path}:\n{result.stdout}"
    return path, json.loads(path.read_text())


def write_explorer(camcov, runs, page):
    """`camcov explore RUN.json... -o page`; returns page."""
    result = camcov("explore", *runs, "-o", page)
    assert result.returncode == 0, \
        f"camcov explore failed (exit {result.returncode}):\n{result.stdout}{result.stderr}"
    assert page.is_file() and page.stat().st_size > 0, f"camcov explore did not write {page}"
    return page


def inspect_step(camcov, run, step, folder, scene=SCENE):
    """`camcov inspect --json` at the recorded time and camera poses of `step` of `run`."""
    series = run["series"]
    poses = [{"x": camera[step][0], "y": camera[step][1], "yaw_deg": math.degrees(camera[step][2])}
             for camera in series["cameras"]]
    poses_file = pathlib.Path(folder) / f"poses-step{step}.json"
    poses_file.write_text(json.dumps(poses))
    result = camcov("inspect", scene, "--time", repr(series["time"][step]), "--cameras",
                    poses_file, "--json")
    assert result.returncode == 0, f"camcov inspect failed:\n{result.stderr}"
    return json.loads(result.stdout)


def step_nearest(run, t):
    """The index of the recorded step whose time is nearest t."""
    times = run["series"]["time"]
    return min(range(len(times)), key=lambda k: abs(times[k] - t))


def first_number(text):
    """The first decimal number in text ("t = 1.20 s" -> 1.2); fails if there is none."""
    match = re.search(r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?", text)
    assert match, f"no number in {text!r}"
    return float(match.group())


def assert_shows_fraction(text, recorded, what):
    """text is recorded.toFixed(4) (to within rounding)."""
    assert re.fullmatch(r"-?\d+\.\d{4}", text), f"{what}: {text!r} is not a number with 4 decimals"
    assert abs(float(text) - recorded) <= 5e-5, f"{what}: shows {text}, the run recorded {recorded}"


# ----------------------------------------------------------------------------- the browser

class Explorer:
    """A browser tab with the explorer page, driven through the page's DOM contract.

    Keeps every browser console entry read so far: Chromium hands each entry out once.
    """

    def __init__(self, driver):
        self.driver = driver
        self.console = []

    # -- waiting and reading

    def console_entries(self):
        self.console += self.driver.get_log("browser")
        return self.console

    def wait_for(self, read, ok, what):
        """Polls read() until ok(value) and returns the value; fails with the last one seen."""
        seen = []

        def probe(_):
            seen[:] = [read()]
            return ok(seen[0])

        try:
            WebDriverWait(self.driver, WAIT_SECONDS, poll_frequency=0.05,
                          ignored_exceptions=(NoSuchElementException,
                                              StaleElementReferenceException)).until(probe)
        except TimeoutException:
            last = repr(seen[0]) if seen else "nothing (the element was never there)"
            console = "\n".join(e["message"] for e in self.console_entries()) or "(empty)"
            pytest.fail(f"{what}: after {WAIT_SECONDS} s, got {last}\nbrowser console:\n{console}",
                        pytrace=False)
        return seen[0]

    def body(self, key):
        return self.driver.execute_script("return document.body.dataset[arguments[0]];", key)

    def step(self):
        return int(self.body("step"))

    def wait_for_step(self, step, why):
        self.wait_for(lambda: self.body("step"), lambda s: s == str(step),
                      f"{why}: body.dataset.step should become {step}")
        self.settle()

    def settle(self):
        """Returns after two animation frames, so that what the page drew is on screen."""
        self.driver.execute_async_script(
            "const done = arguments[0];"
            "requestAnimationFrame(() => requestAnimationFrame(() => done()));")

    def run(self, i):
        return self.driver.find_element(By.CSS_SELECTOR, f'section.run[data-run="{i}"]')

    def world(self, i):
        """Run i's svg.world, found afresh (the page may redraw it)."""
        return self.run(i).find_element(By.CSS_SELECTOR, "svg.world")

    def text(self, selector, within=None):
        """textContent of the first element matching selector, stripped."""
        element = (within or self.driver).find_element(By.CSS_SELECTOR, selector)
        return (element.get_attribute("textContent") or "").strip()

    def field(self, run, name):
        return self.text(f'.info [data-field="{name}"]', within=self.run(run))

    # -- acting

    def open(self, page):
        self.driver.get(pathlib.Path(page).as_uri())
        self.wait_for(lambda: self.body("ready"), lambda r: r == "1",
                      f"{page.name} never set body.dataset.ready to \"1\"")
        self.settle()

    def seek(self, step):
        """Moves #slider to step the way a user would: value, then an input event."""
        self.driver.execute_script(
            "const slider = document.querySelector('#slider');"
            "slider.value = String(arguments[0]);"
            "slider.dispatchEvent(new Event('input', {bubbles: true}));", step)
        self.wait_for_step(step, f"after seeking the slider to {step}")

    def press(self, key):
        """One key sent to the page's body (nothing else focused, so no control takes it)."""
        self.driver.execute_script("document.activeElement && document.activeElement.blur();")
        self.driver.find_element(By.TAG_NAME, "body").send_keys(key)

    def click(self, element):
        """A Selenium click; if something covers the element's centre, or chromedriver finds it
        not interactable (a horizontal SVG line has a box of height 0), a real mouse click at a
        point of the element that is on top (found along its outline and over its box)."""
        try:
            element.click()
            return
        except (ElementClickInterceptedException, ElementNotInteractableException):
            pass
        point = self.driver.execute_script(VISIBLE_POINT_JS, element)
        assert point, f"no visible point of {element.get_attribute('outerHTML')[:200]} to click"
        actions = ActionBuilder(self.driver)
        actions.pointer_action.move_to_location(point[0], point[1]).click()
        actions.perform()

    def screenshot(self, element=None):
        """PNG of the viewport, or of one element."""
        self.settle()
        if element is not None:
            return element.screenshot_as_png
        return self.driver.get_screenshot_as_png()


# A client point (integers) where the top element is arguments[0] or inside it, or null: tries
# points along its SVG shapes (a segment may be a thin line), then a grid over its box.
VISIBLE_POINT_JS = """
const element = arguments[0];
element.scrollIntoView({block: 'center', inline: 'center'});
const onTop = (x, y) => {
  const hit = document.elementFromPoint(x, y);
  return hit !== null && (hit === element || element.contains(hit));
};
const shapes = [element, ...element.querySelectorAll('*')]
    .filter((e) => typeof SVGGeometryElement !== 'undefined' && e instanceof SVGGeometryElement);
const points = [];
for (const shape of shapes) {
  const m = shape.getScreenCTM();
  let length = 0;
  try { length = shape.getTotalLength(); } catch (e) {}
  if (!m || !(length > 0)) continue;
  for (let i = 1; i < 40; ++i) {
    const p = shape.getPointAtLength(length * i / 40);
    points.push([p.x * m.a + p.y * m.c + m.e, p.x * m.b + p.y * m.d + m.f]);
  }
}
const box = element.getBoundingClientRect();
for (let i = 1; i < 12; ++i)
  for (let j = 1; j < 12; ++j)
    points.push([box.left + box.width * i / 12, box.top + box.height * j / 12]);
for (const [x, y] of points) {
  const p = [Math.round(x), Math.round(y)];
  if (onTop(p[0], p[1])) return p;
}
return null;
"""


@pytest.fixture
def explorer(request):
    """A fresh headless Chromium per test, quit when the test ends."""
    driver = start_chromium()
    request.addfinalizer(driver.quit)
    return Explorer(driver)


def assert_no_console_errors(explorer):
    """Nothing at level SEVERE in the browser console (console.error, uncaught exceptions,
    resources that failed to load) since the browser started."""
    severe = [e["message"] for e in explorer.console_entries() if e.get("level") == "SEVERE"]
    assert not severe, "the browser console has errors:\n" + "\n".join(severe)


def screenshots_folder(tmp_path):
    folder = pathlib.Path(os.environ.get("CAMCOV_EXPLORER_SCREENSHOTS") or tmp_path)
    folder.mkdir(parents=True, exist_ok=True)
    return folder


@pytest.fixture
def paper_page(camcov, tmp_path):
    """(page, run): the explorer page of one paper run of tiny_dynamic, and the run's JSON."""
    run_file, run = record_run(camcov, tmp_path / "runs", "paper")
    return write_explorer(camcov, [run_file], tmp_path / "explorer.html"), run


# ----------------------------------------------------------------------------- the harness itself

def test_the_console_check_catches_a_console_error(explorer, tmp_path):
    quiet = tmp_path / "quiet.html"
    quiet.write_text('<!doctype html><title>quiet</title><script>console.log("fine")</script>')
    explorer.driver.get(quiet.as_uri())
    assert_no_console_errors(explorer)

    noisy = tmp_path / "noisy.html"
    noisy.write_text('<!doctype html><title>noisy</title><script>console.error("boom")</script>')
    explorer.driver.get(noisy.as_uri())
    with pytest.raises(AssertionError, match="boom"):
        assert_no_console_errors(explorer)


# ----------------------------------------------------------------------------- the page

def test_seeking_shows_the_recorded_coverage_and_keys_move_one_step_or_to_the_ends(
        explorer, paper_page):
    page, run = paper_page
    series = run["series"]
    last = len(series["time"]) - 1
    k = step_nearest(run, 2.0)
    assert 0 < k < last
    # The test can tell neighbouring steps apart.
    assert min(abs(series["coverage"][k] - series["coverage"][k + d]) for d in (-1, 1)) > 1e-3

    explorer.open(page)
    assert explorer.step() == 0
    run0 = explorer.run(0)
    assert_shows_fraction(explorer.text(".coverage", run0), series["coverage"][0], "step 0")
    slider = explorer.driver.find_element(By.CSS_SELECTOR, "#slider")
    assert (slider.get_attribute("type"), slider.get_attribute("min"),
            slider.get_attribute("max")) == ("range", "0", str(last))

    explorer.seek(k)
    assert_shows_fraction(explorer.text(".coverage", run0), series["coverage"][k],
                          f"coverage at step {k}")
    assert_shows_fraction(explorer.text(".utilization", run0), series["utilization"][k],
                          f"utilization at step {k}")
    shown_time = first_number(explorer.text("#time"))
    assert abs(shown_time - series["time"][k]) <= 0.006, explorer.text("#time")

    explorer.press(Keys.ARROW_RIGHT)
    explorer.wait_for_step(k + 1, "ArrowRight")
    assert_shows_fraction(explorer.text(".coverage", run0), series["coverage"][k + 1],
                          f"coverage at step {k + 1}")
    explorer.press(Keys.ARROW_LEFT)
    explorer.wait_for_step(k, "ArrowLeft")
    explorer.press(Keys.END)
    explorer.wait_for_step(last, "End")
    assert_shows_fraction(explorer.text(".coverage", run0), series["coverage"][last],
                          "coverage at the last step")
    explorer.press(Keys.HOME)
    explorer.wait_for_step(0, "Home")
    explorer.press(Keys.ARROW_RIGHT)
    explorer.wait_for_step(1, "ArrowRight from step 0")

    explorer.click(explorer.driver.find_element(By.CSS_SELECTOR, "#step-forward"))
    explorer.wait_for_step(2, "#step-forward")
    explorer.click(explorer.driver.find_element(By.CSS_SELECTOR, "#step-back"))
    explorer.wait_for_step(1, "#step-back")
    assert_no_console_errors(explorer)


def test_space_and_the_play_button_start_and_stop_playback(explorer, paper_page):
    page, run = paper_page
    explorer.open(page)

    def plays_then_stops(toggle, how):
        start = explorer.step()
        toggle()
        explorer.wait_for(explorer.step, lambda s: s != start, f"{how} should start playback")
        toggle()
        time.sleep(0.3)  # a frame already scheduled may still land
        paused_at = explorer.step()
        time.sleep(1.0)
        assert explorer.step() == paused_at, f"{how} again should stop playback"

    plays_then_stops(lambda: explorer.press(Keys.SPACE), "Space")
    explorer.press(Keys.HOME)
    explorer.wait_for_step(0, "Home")
    plays_then_stops(lambda: explorer.click(explorer.driver.find_element(By.CSS_SELECTOR, "#play")),
                     "#play")
    assert_no_console_errors(explorer)


def test_clicking_the_timeline_seeks_to_the_time_under_the_pointer(explorer, paper_page):
    page, run = paper_page
    last = len(run["series"]["time"]) - 1
    explorer.open(page)
    timeline = explorer.driver.find_element(By.CSS_SELECTOR, "svg.timeline")
    explorer.driver.execute_script("arguments[0].scrollIntoView({block: 'center'});", timeline)
    width = timeline.rect["width"]
    assert width > 20, f"svg.timeline is {width} px wide"

    def click_at(fraction):
        """Clicks the timeline at this fraction of its width, on its horizontal midline."""
        timeline = explorer.driver.find_element(By.CSS_SELECTOR, "svg.timeline")
        actions = ActionBuilder(explorer.driver)
        actions.pointer_action.move_to(timeline, int(width * (fraction - 0.5)), 0).click()
        actions.perform()

    click_at(0.9)
    late = explorer.wait_for(explorer.step, lambda s: s > last / 2,
                             "a click at 90% of the timeline should seek a late step")
    click_at(0.1)
    explorer.wait_for(explorer.step, lambda s: s < last / 2,
                      f"a click at 10% of the timeline should seek an early step (was at {late})")
    assert_no_console_errors(explorer)


def test_a_clicked_segment_shows_who_sees_it_and_its_length_as_camcov_inspect_does(
        explorer, paper_page, camcov, tmp_path):
    page, run = paper_page
    k = step_nearest(run, 2.0)
    reference = inspect_step(camcov, run, k, tmp_path)
    # The reference is the state the run recorded at step k.
    assert abs(reference["coverage"] - run["series"]["coverage"][k]) <= 1e-6
    segments = reference["segments"]
    assert segments, "camcov inspect lists no segments"

    explorer.open(page)
    explorer.seek(k)
    shown = explorer.world(0).find_elements(By.CSS_SELECTOR, ".segment")
    assert len(shown) == len(segments), \
        f"run 0 draws {len(shown)} segments at step {k}, camcov inspect lists {len(segments)}"
    for i, segment in enumerate(segments):
        element = explorer.world(0).find_element(By.CSS_SELECTOR, f'.segment[data-segment="{i}"]')
        assert (element.get_attribute("data-target"), element.get_attribute("data-edge")) == \
            (str(segment["target"]), str(segment["edge"])), f"segment {i}"
        # The geometry drawn: the line's ends (SVG's y runs down) to the millimetre the page
        # keeps, plus the rounding of where along its edge a piece starts and ends.
        drawn = [(float(element.get_attribute(f"x{e}")), -float(element.get_attribute(f"y{e}")))
                 for e in (1, 2)]
        for end, expected in zip(drawn, (segment["a"], segment["b"])):
            assert math.dist(end, expected) <= 2e-3, \
                f"segment {i}: drawn from {drawn[0]} to {drawn[1]}, camcov inspect: " \
                f"{segment['a']} to {segment['b']}"

    # The longest seen segment, then the longest unseen one: the panel must tell them apart.
    seen = [i for i, s in enumerate(segments) if s["visibleBy"]]
    unseen = [i for i, s in enumerate(segments) if not s["visibleBy"]]
    chosen = [max(group, key=lambda i: segments[i]["length"]) for group in (seen, unseen) if group]
    for i in chosen:
        segment = segments[i]
        expected = ", ".join(map(str, segment["visibleBy"])) or "none"
        explorer.click(explorer.world(0).find_element(By.CSS_SELECTOR,
                                                      f'.segment[data-segment="{i}"]'))
        explorer.wait_for(lambda: explorer.field(0, "visibleBy"), lambda text: text == expected,
                          f"visibleBy of segment {i} (camcov inspect: {expected!r})")
        explorer.wait_for(lambda: explorer.field(0, "length"),
                          lambda text: abs(first_number(text) - segment["length"]) <= 1e-3,
                          f"length of segment {i} (camcov inspect: {segment['length']:.6f} m)")
        # Every camera that does not see it says why.
        reasons = explorer.run(0).find_elements(By.CSS_SELECTOR, ".info ul.reasons li")
        blind = [j for j in range(len(run["series"]["cameras"])) if j not in segment["visibleBy"]]
        assert [r.get_attribute("data-camera") for r in reasons] == [str(j) for j in blind]
        for r in reasons:
            assert re.search(r"behind its own target|outside the field of view|blocked by|"
                             r"inside|outside the boundary", r.text), r.text
    assert_no_console_errors(explorer)


def test_a_clicked_camera_shows_its_pose_and_its_own_coverage_term(explorer, paper_page, camcov,
                                                                   tmp_path):
    page, run = paper_page
    series = run["series"]
    cameras = len(series["cameras"])
    k = step_nearest(run, 2.0)
    reference = inspect_step(camcov, run, k, tmp_path)
    explorer.open(page)
    explorer.seek(k)
    assert len(explorer.world(0).find_elements(By.CSS_SELECTOR, "g.camera")) == cameras
    explorer.click(explorer.world(0).find_element(By.CSS_SELECTOR, 'g.camera[data-camera="0"]'))
    pose = explorer.wait_for(lambda: explorer.field(0, "pose"), lambda text: text != "",
                             "the pose of a clicked camera")
    x, y, yaw = (float(v) for v in re.findall(r"-?\d+\.\d+", pose)[:3])
    recorded = series["cameras"][0][k]
    assert abs(x - recorded[0]) <= 1e-3 and abs(y - recorded[1]) <= 1e-3, pose
    assert abs(yaw - math.degrees(recorded[2])) <= 0.06, pose
    # Its own coverage term, eq. (3): what camcov inspect says it sees over the boundary length.
    own = reference["cameras"][0]["visibleLength"] / reference["targetPerimeter"]
    assert_shows_fraction(explorer.field(0, "coverage"), own, "camera 0's own coverage")
    assert re.fullmatch(r"\d\.\d{4}", explorer.field(0, "utilization"))
    assert_no_console_errors(explorer)

def test_a_clicked_camera_shows_its_limits_and_range_as_camcov_state_describes_it(
        explorer, camcov, tmp_path):
    # tiny_dynamic with a sensing range on camera 0: one camera description serves the state
    # command and the explorer, so the panel shows what `camcov state` prints.
    scene = json.loads(SCENE.read_text())
    scene["cameras"][0]["sensingRange"] = 2.75
    scene_file = tmp_path / "ranged.json"
    scene_file.write_text(json.dumps(scene))
    state = camcov("state", scene_file)
    assert state.returncode == 0, state.stderr
    described = json.loads(state.stdout)["cameras"][0]
    assert described["sensingRange"] == 2.75
    run_file, _ = record_run(camcov, tmp_path / "runs", "local", scene=scene_file, duration=1)
    explorer.open(write_explorer(camcov, [run_file], tmp_path / "ranged.html"))
    explorer.click(explorer.world(0).find_element(By.CSS_SELECTOR, 'g.camera[data-camera="0"]'))
    limits = explorer.wait_for(lambda: explorer.field(0, "limits"), lambda text: text != "",
                               "the limits of a clicked camera")
    assert f"v ≤ {described['maxVelocity']:g} m/s" in limits, limits
    assert f"θ = {described['cameraFoV']:.1f}°" in limits, limits
    assert first_number(explorer.field(0, "sensingRange")) == 2.75
    assert_no_console_errors(explorer)


def test_the_first_and_last_steps_look_different(explorer, paper_page, tmp_path):
    page, run = paper_page
    cameras = run["series"]["cameras"]
    last = len(run["series"]["time"]) - 1
    assert any(math.dist(c[0][:2], c[last][:2]) > 0.1 for c in cameras), "no camera moved"
    folder = screenshots_folder(tmp_path)

    explorer.open(page)
    shots = {}
    for name, step in (("first", 0), ("last", last)):
        explorer.seek(step)
        explorer.driver.execute_script("window.scrollTo(0, 0);")
        page_png = explorer.screenshot()
        (folder / f"explorer-step-{name}.png").write_bytes(page_png)
        world_png = explorer.screenshot(explorer.world(0))
        shots[name] = (page_png, world_png)
    # Chromium encodes equal pixels to equal bytes: different bytes are different pictures.
    assert shots["first"][0] != shots["last"][0], "the page looks the same at both steps"
    assert shots["first"][1] != shots["last"][1], "run 0's svg.world looks the same at both steps"
    assert_no_console_errors(explorer)


def test_two_runs_side_by_side_each_show_their_own_coverage(explorer, camcov, tmp_path):
    paper_file, paper = record_run(camcov, tmp_path / "runs", "paper")
    local_file, local = record_run(camcov, tmp_path / "runs", "local")
    page = write_explorer(camcov, [paper_file, local_file], tmp_path / "explorer.html")
    runs = (paper, local)
    steps = min(len(r["series"]["coverage"]) for r in runs)
    # A step where the runs differ, so that showing one run's number twice fails.
    k = max(range(steps),
            key=lambda s: abs(paper["series"]["coverage"][s] - local["series"]["coverage"][s]))
    assert abs(paper["series"]["coverage"][k] - local["series"]["coverage"][k]) > 1e-3

    explorer.open(page)
    sections = explorer.driver.find_elements(By.CSS_SELECTOR, "section.run")
    assert [s.get_attribute("data-run") for s in sections] == ["0", "1"]
    explorer.seek(k)
    for i, run in enumerate(runs):
        section = explorer.run(i)
        assert section.find_elements(By.CSS_SELECTOR, "svg.world"), f"run {i} has no svg.world"
        assert_shows_fraction(explorer.text(".coverage", section), run["series"]["coverage"][k],
                              f"run {i} ({run['method']}) at step {k}")
        assert_shows_fraction(explorer.text(".utilization", section),
                              run["series"]["utilization"][k],
                              f"run {i} ({run['method']}) utilization at step {k}")
    assert_no_console_errors(explorer)


def test_a_comment_and_a_script_tag_in_the_data_leave_the_page_whole(explorer, camcov,
                                                                     tmp_path):
    # "<!--<script>" puts an HTML parser that meets it inside a script element into the
    # escaped state, where the element's own end tag no longer ends it: a scene description or
    # file name holding it used to leave the page empty.
    hostile = "<!--<script>alert(1)</script>"
    scene = json.loads(SCENE.read_text())
    scene["description"] = f"a hostile {hostile} description"
    scene_file = tmp_path / "evil<!--<script>.json"
    scene_file.write_text(json.dumps(scene))
    run_file, run = record_run(camcov, tmp_path / "runs", "paper", scene=scene_file)
    page = write_explorer(camcov, [run_file], tmp_path / "explorer.html")
    explorer.open(page)
    last = len(run["series"]["coverage"]) - 1
    explorer.seek(last)
    assert_shows_fraction(explorer.text(".coverage", explorer.run(0)),
                          run["series"]["coverage"][last], "the hostile scene's last step")
    assert "evil<!--<script>" in explorer.driver.find_element(By.TAG_NAME, "body").text
    assert_no_console_errors(explorer)


def test_the_page_loads_nothing_from_the_network(explorer, paper_page):
    page, run = paper_page
    explorer.open(page)
    resources = explorer.driver.execute_script(
        "return performance.getEntriesByType('resource').map((e) => e.name);")
    remote = [r for r in resources if not r.startswith(("file:", "data:", "blob:"))]
    assert not remote, f"the page fetches {remote}"
    assert_no_console_errors(explorer)


def test_dynamic9_side_by_side_with_an_edge_and_a_camera_explained(explorer, camcov, tmp_path):
    """The README's picture: both methods on dynamic9 at t = 12 s, an unseen edge clicked in
    one run and a camera in the other. Needs the published scenes (COVERAGE_SCENES_DIR)."""
    scenes = os.environ.get("COVERAGE_SCENES_DIR")
    if not scenes:
        pytest.skip("set COVERAGE_SCENES_DIR to the published coverage_scenes folder")
    scene = pathlib.Path(scenes) / "dynamic9.json"
    paper_file, paper = record_run(camcov, tmp_path / "runs", "paper", scene, 30)
    local_file, local = record_run(camcov, tmp_path / "runs", "local", scene, 30)
    page = write_explorer(camcov, [paper_file, local_file], tmp_path / "dynamic9.html")
    k = step_nearest(paper, 12.0)
    reference = inspect_step(camcov, local, k, tmp_path, scene)
    unseen = [i for i, s in enumerate(reference["segments"]) if not s["visibleBy"]]
    assert unseen, "every edge is seen: pick another instant"
    longest = max(unseen, key=lambda i: reference["segments"][i]["length"])

    explorer.driver.set_window_size(1400, 1450)
    explorer.open(page)
    explorer.seek(k)
    for i, run in enumerate((paper, local)):
        assert_shows_fraction(explorer.text(".coverage", explorer.run(i)),
                              run["series"]["coverage"][k], f"run {i} at step {k}")
    explorer.click(explorer.world(0).find_element(By.CSS_SELECTOR, 'g.camera[data-camera="0"]'))
    explorer.wait_for(lambda: explorer.field(0, "pose"), lambda text: text != "",
                      "the pose of camera 0 in run 0")
    explorer.click(explorer.world(1).find_element(By.CSS_SELECTOR,
                                                  f'.segment[data-segment="{longest}"]'))
    explorer.wait_for(lambda: explorer.field(1, "visibleBy"), lambda text: text == "none",
                      f"visibleBy of run 1's longest unseen segment {longest}")
    reasons = explorer.run(1).find_elements(By.CSS_SELECTOR, ".info ul.reasons li")
    assert len(reasons) == len(local["series"]["cameras"])
    explorer.driver.execute_script("window.scrollTo(0, 0);")
    (screenshots_folder(tmp_path) / "explorer-dynamic9.png").write_bytes(explorer.screenshot())
    assert_no_console_errors(explorer)


def test_recorded_targets_come_and_go_as_the_run_and_camcov_inspect_say(explorer, camcov,
                                                                         tmp_path):
    """Recorded tracks (tests/data/scenes_tracks): no target drawn before anyone enters, then
    the ones present, each edge named by the target's index in the scene."""
    scene = REPO / "tests" / "data" / "scenes_tracks" / "comes_and_goes.json"
    run_file, run = record_run(camcov, tmp_path / "runs", "paper", scene, 4)
    page = write_explorer(camcov, [run_file], tmp_path / "tracks.html")
    explorer.open(page)
    present = run["series"]["targetsPresent"]
    for t in (0.2, 0.7, 1.5, 2.8, 3.5):
        k = step_nearest(run, t)
        explorer.seek(k)
        world = explorer.world(0)
        drawn = world.find_elements(By.CSS_SELECTOR, "polygon[data-target]")
        assert len(drawn) == present[k], f"t = {t}: {len(drawn)} targets drawn, run: {present[k]}"
        reference = inspect_step(camcov, run, k, tmp_path, scene)
        segments = world.find_elements(By.CSS_SELECTOR, ".segment")
        assert [(s.get_attribute("data-target"), s.get_attribute("data-edge")) for s in segments] \
            == [(str(s["target"]), str(s["edge"])) for s in reference["segments"]], f"t = {t}"
    assert_no_console_errors(explorer)


def test_small_objects_are_drawn_enlarged_and_ringed_and_a_large_teams_views_lighter(
        explorer, camcov, tmp_path):
    """A 0.2 m target in a 60 m room is drawn at least 0.6 em across (em: 2.5 % of the room),
    its edges with it, and ringed with dots; eight cameras' views are lighter than one's, as
    in the frames (viz/palette.h, viewAlphaFor)."""
    cameras = [{"pos": f"POINT({-25 + 7 * j} -25)", "angle": 90, "maxVelocity": 1,
                "maxAngularVelocity": 1} for j in range(8)]
    scene = {"boundary": "POLYGON((-30 -30,30 -30,30 30,-30 30))",
             "targets": [{"shape": "POLYGON((-0.1 -0.1,0.1 -0.1,0.1 0.1,-0.1 0.1))",
                          "path": "POINT(0 0)"},
                         {"shape": "POLYGON((-3 -3,3 -3,3 3,-3 3))", "path": "POINT(15 15)"}],
             "cameraFoV": 30, "cameras": cameras}
    pages = {}
    for team in (1, 8):
        file = tmp_path / f"team{team}.json"
        file.write_text(json.dumps({**scene, "cameras": cameras[:team]}))
        run_file, _ = record_run(camcov, tmp_path / f"runs{team}", "local", file, 1)
        pages[team] = write_explorer(camcov, [run_file], tmp_path / f"team{team}.html")
    em = 0.025 * 60
    explorer.open(pages[8])
    world = explorer.world(0)
    small = world.find_element(By.CSS_SELECTOR, 'polygon[data-target="0"]')
    box = explorer.driver.execute_script("return arguments[0].getBBox();", small)
    assert min(box["width"], box["height"]) >= 0.6 * em - 1e-6, box
    large = world.find_element(By.CSS_SELECTOR, 'polygon[data-target="1"]')
    box = explorer.driver.execute_script("return arguments[0].getBBox();", large)
    assert box["width"] == pytest.approx(6.0, abs=1e-6), "an object large enough is as it is"
    rings = world.find_elements(By.CSS_SELECTOR, "circle.enlarged")
    assert len(rings) == 1
    assert float(rings[0].get_attribute("cx")) == pytest.approx(0.0, abs=1e-9)
    for segment in world.find_elements(By.CSS_SELECTOR, '.segment[data-target="0"]'):
        ends = [float(segment.get_attribute(k)) for k in ("x1", "y1", "x2", "y2")]
        assert max(abs(v) for v in ends) >= 0.25 * em, "the small target's edges are enlarged"
    opacity = {}
    opacity[8] = {float(v.get_attribute("fill-opacity"))
                  for v in world.find_elements(By.CSS_SELECTOR, "polygon.view")}
    explorer.open(pages[1])
    opacity[1] = {float(v.get_attribute("fill-opacity"))
                  for v in explorer.world(0).find_elements(By.CSS_SELECTOR, "polygon.view")}
    assert opacity[1] == {0.28}
    assert len(opacity[8]) == 1 and opacity[8].pop() == pytest.approx(1 - 0.17 ** (1 / 8))
    assert_no_console_errors(explorer)


def test_a_weighted_scene_shows_weighted_coverage_and_edges_as_wide_as_important(
        explorer, camcov, tmp_path):
    """tiny_dynamic with importance weights on its first target (docs/scene-format.md,
    "Importance weights"): the panel shows the run's weighted coverage beside the plain one, a
    clicked edge its weight as `camcov inspect --json` gives it, and the heavier edges are drawn
    wider, as the frames draw them."""
    scene = json.loads(SCENE.read_text())
    edges = scene["targets"][0]["shape"].count(",") + 1
    scene["targets"][0]["edgeWeights"] = [4] + [1] * (edges - 1)
    scene_file = tmp_path / "weighted.json"
    scene_file.write_text(json.dumps(scene))
    run_file, run = record_run(camcov, tmp_path / "runs", "paper", scene_file, 2)
    series = run["series"]
    assert "weightedCoverage" in series
    page = write_explorer(camcov, [run_file], tmp_path / "weighted.html")
    explorer.open(page)
    k = step_nearest(run, 1.0)
    explorer.seek(k)
    shown = explorer.text(".weighted-coverage", within=explorer.run(0))
    assert_shows_fraction(shown, series["weightedCoverage"][k], "weighted coverage")
    assert_shows_fraction(explorer.text(".coverage", within=explorer.run(0)),
                          series["coverage"][k], "plain coverage")
    assert "wider edge: more important" in explorer.driver.find_element(By.ID, "legend").text
    reference = inspect_step(camcov, run, k, tmp_path, scene_file)
    widths = {}
    for i, segment in enumerate(reference["segments"]):
        element = explorer.world(0).find_element(By.CSS_SELECTOR, f'.segment[data-segment="{i}"]')
        widths.setdefault(segment["weight"], set()).add(float(element.get_attribute("stroke-width")))
    # The heaviest edge (weight 4 of 4) 1.6 times the plain 5 px, the others (1 of 4) 0.7 times.
    assert [pytest.approx(w) for w in sorted(widths[1.0])] == [5 * 1.6], widths
    assert [pytest.approx(w) for w in sorted(widths[0.25])] == [5 * 0.7], widths
    heavy = next(i for i, s in enumerate(reference["segments"]) if s["weight"] == 1.0)
    explorer.click(explorer.world(0).find_element(By.CSS_SELECTOR,
                                                  f'.segment[data-segment="{heavy}"]'))
    explorer.wait_for(lambda: explorer.field(0, "weight"), lambda text: first_number(text) == 1.0,
                      "the importance weight of a clicked edge")
    assert_no_console_errors(explorer)


def resolution_scene(tmp_path, min_density):
    """tiny_dynamic with 640-pixel images and a required density (docs/scene-format.md,
    "Resolution")."""
    scene = json.loads(SCENE.read_text())
    scene["imageWidth"] = 640
    scene["resolution"] = {"minDensity": min_density}
    path = tmp_path / f"resolution-{min_density:g}.json"
    path.write_text(json.dumps(scene))
    return path


def drawn_lines(world, selector):
    """The end points of the lines `selector` draws, rounded to a millimetre, as a set."""
    lines = set()
    for line in world.find_elements(By.CSS_SELECTOR, selector):
        ends = [round(float(line.get_attribute(k)), 3) for k in ("x1", "y1", "x2", "y2")]
        lines.add(tuple(ends))
    return lines


def test_a_scene_with_a_resolution_shows_resolved_coverage_and_draws_what_no_camera_resolves(
        explorer, camcov, tmp_path):
    """Beside the plain coverage, the panel shows the run's resolved coverage at the step; the
    world draws, over the seen edges, the seen boundary no camera resolves. Checked at the two
    ends where the answer is known without camcov: a density no camera reaches (every seen
    edge is drawn unresolved, resolved coverage 0) and one every camera exceeds (nothing is)."""
    for min_density, everything_unresolved in ((1e9, True), (1e-6, False)):
        scene_file = resolution_scene(tmp_path, min_density)
        run_file, run = record_run(camcov, tmp_path / f"runs{min_density:g}", "paper",
                                   scene_file, 3)
        series = run["series"]
        page = write_explorer(camcov, [run_file], tmp_path / f"resolution{min_density:g}.html")
        explorer.open(page)
        k = step_nearest(run, 3.0)  # the cameras have turned to the targets by then
        explorer.seek(k)
        shown = explorer.text(".resolution-coverage", within=explorer.run(0))
        assert_shows_fraction(shown, series["resolutionCoverage"][k], "resolved coverage")
        assert_shows_fraction(explorer.text(".coverage", within=explorer.run(0)),
                              series["coverage"][k], "plain coverage")
        world = explorer.world(0)
        reference = inspect_step(camcov, run, k, tmp_path, scene_file)
        seen = set().union(*(drawn_lines(world, f'.segment[data-segment="{i}"]')
                             for i, segment in enumerate(reference["segments"])
                             if segment["visibleBy"]))
        assert seen, "nothing is seen at the step: the check would be empty"
        unresolved = drawn_lines(world, "line.unresolved")
        if everything_unresolved:
            assert float(shown) == 0.0
            assert unresolved == seen
        else:
            assert float(shown) == pytest.approx(series["coverage"][k], abs=5e-5)
            assert unresolved == set()
        legend = explorer.driver.find_element(By.ID, "legend").text
        assert "seen, not resolved" in legend
    assert_no_console_errors(explorer)


def test_under_limited_knowledge_the_world_draws_who_heard_whom_and_a_camera_says_whom_it_heard(
        explorer, camcov, tmp_path):
    # tiny_static's two cameras each send every 0.5 s (every fifth step) and are heard at once.
    scene = SCENE.parent / "tiny_static.json"
    result = camcov("run", scene, "--method", "local", "--seed", 1, "--set", "sim.duration=2",
                    "--set", "knowledge.limited=true", "--set", "comms.period=0.5",
                    "--out", tmp_path / "runs")
    assert result.returncode == 0, result.stderr
    page = write_explorer(camcov, [tmp_path / "runs" / "tiny_static-local-seed1.json"],
                          tmp_path / "explorer.html")
    explorer.open(page)
    pairs = {(line.get_attribute("data-from"), line.get_attribute("data-to"))
             for line in explorer.world(0).find_elements(By.CSS_SELECTOR, "line.heard")}
    assert pairs == {("0", "1"), ("1", "0")}
    explorer.click(explorer.world(0).find_element(By.CSS_SELECTOR, 'g.camera[data-camera="0"]'))
    assert explorer.wait_for(lambda: explorer.field(0, "heard"), lambda text: text != "",
                             "whom camera 0 heard") == "camera 1"
    explorer.seek(1)
    assert explorer.world(0).find_elements(By.CSS_SELECTOR, "line.heard") == []
    assert explorer.wait_for(lambda: explorer.field(0, "heard"), lambda text: text != "camera 1",
                             "whom camera 0 heard at step 1") == "nobody"
    assert_no_console_errors(explorer)


# ----------------------------------------------------------------------------- what a reader sees
# At 1400 × 900, as a reader opens the page: measured, not grepped.

# Every element whose box reaches past the window's right edge.
WIDER_THAN_WINDOW_JS = """
const room = document.documentElement.clientWidth;
return Array.from(document.querySelectorAll("body *"))
  .filter((e) => e.getBoundingClientRect().right > room + 0.5)
  .map((e) => `${e.tagName.toLowerCase()}#${e.id}.${e.className.baseVal ?? e.className}`)
  .slice(0, 10);
"""


def three_methods_page(camcov, tmp_path, playground=False):
    """The page of tiny_dynamic's paper, local and camcov runs side by side (camcov's
    description is the longest), optionally linked to a playground page."""
    runs = [record_run(camcov, tmp_path / "runs", method)[0] for method in ("paper", "local", "camcov")]
    extra = []
    if playground:
        play = tmp_path / "playground.html"
        result = camcov("playground", SCENE, "-o", play)
        assert result.returncode == 0, result.stderr
        extra = ["--playground", play]
    result = camcov("explore", *runs, "-o", tmp_path / "three.html", *extra)
    assert result.returncode == 0, result.stderr
    return tmp_path / "three.html"


def test_at_1400_by_900_every_world_is_in_view_and_nothing_is_wider_than_the_window(
        explorer, camcov, tmp_path):
    explorer.driver.set_window_size(1400, 900)
    explorer.open(three_methods_page(camcov, tmp_path))
    view = explorer.driver.execute_script(
        "return {width: document.documentElement.clientWidth, height: window.innerHeight,"
        " worlds: Array.from(document.querySelectorAll('svg.world'))"
        "   .map((w) => w.getBoundingClientRect().toJSON())}")
    assert len(view["worlds"]) == 3
    for world in view["worlds"]:
        assert world["top"] >= 0 and world["left"] >= 0, world
        assert world["bottom"] <= view["height"] + 0.5, f"below the fold: {world}, {view['height']}"
        assert world["right"] <= view["width"] + 0.5, world
        assert world["height"] >= 240, f"a world too small to read: {world}"
    assert explorer.driver.execute_script(WIDER_THAN_WINDOW_JS) == []
    (screenshots_folder(tmp_path) / "explorer-1400x900.png").write_bytes(explorer.screenshot())
    assert_no_console_errors(explorer)


def test_worlds_side_by_side_line_up_whatever_their_titles_and_numbers_take(
        explorer, camcov, tmp_path):
    explorer.driver.set_window_size(1400, 900)
    explorer.open(three_methods_page(camcov, tmp_path, playground=True))
    tops = explorer.driver.execute_script(
        "return Array.from(document.querySelectorAll('svg.world'))"
        ".map((w) => w.getBoundingClientRect().top)")
    titles = explorer.driver.execute_script(
        "return Array.from(document.querySelectorAll('section.run h2'))"
        ".map((h) => h.getBoundingClientRect().height)")
    assert max(titles) > min(titles) + 5, f"no title takes more lines than another: {titles}"
    assert max(tops) - min(tops) <= 0.5, f"worlds start at {tops}"
    assert_no_console_errors(explorer)


def test_the_reward_and_the_playground_link_are_set_apart(explorer, camcov, tmp_path):
    explorer.open(three_methods_page(camcov, tmp_path, playground=True))
    numbers = explorer.run(0).find_element(By.CSS_SELECTOR, ".numbers")
    assert re.search(r"reward -?\d+\.\d{4} · open this step", numbers.text), numbers.text
    gap = explorer.driver.execute_script(
        "const [r, a] = [arguments[0].querySelector('.reward'), arguments[0].querySelector('a.playground')]"
        ".map((e) => e.getClientRects()[0]);"
        "return Math.abs(r.top - a.top) > 2 ? null : a.left - r.right;", numbers)
    assert gap is None or gap >= 6, f"{gap} px between the reward and the link"
    assert_no_console_errors(explorer)


def test_a_legend_says_which_curve_is_coverage_and_which_utilization(explorer, paper_page):
    page, _ = paper_page
    explorer.driver.set_window_size(1400, 900)
    explorer.open(page)
    legend = explorer.driver.find_element(By.ID, "curve-legend")
    box = legend.rect
    assert box["height"] > 0 and box["y"] + box["height"] <= explorer.driver.execute_script(
        "return window.innerHeight"), f"the legend is not in view: {box}"
    dashes = explorer.driver.execute_script("""
      const dash = (e) => (e && e.getAttribute("stroke-dasharray")) || "";
      const sample = (word) => Array.from(document.querySelectorAll("#curve-legend .item"))
        .find((i) => i.textContent.trim() === word);
      return {coverage: [dash(sample("coverage")?.querySelector("line")),
                         dash(document.querySelector("svg.timeline .curve.coverage"))],
              utilization: [dash(sample("utilization")?.querySelector("line")),
                            dash(document.querySelector("svg.timeline .curve.utilization"))]};""")
    assert dashes["coverage"][0] == dashes["coverage"][1], dashes
    assert dashes["utilization"][0] == dashes["utilization"][1], dashes
    assert dashes["coverage"][0] != dashes["utilization"][0], dashes
    assert_no_console_errors(explorer)


def test_a_recording_leaves_a_gap_where_nobody_is_present(explorer, camcov, tmp_path):
    """Two people tracked for 2 s in a run of 3 s: after 2 s nobody is present and coverage is
    0 by definition; the curves end at 2 s instead of plunging to 0."""
    table = tmp_path / "walk.csv"
    table.write_text("id,t,x,y\n" + "".join(f"{i},{k * 0.5},{2 + k * 0.5 + 3 * i},{3 + i}\n"
                                            for i in range(2) for k in range(5)))
    scene = tmp_path / "walk.json"
    result = camcov("import", "csv", table, "--cameras", 2, "-o", scene)
    assert result.returncode == 0, result.stderr
    run_file, run = record_run(camcov, tmp_path / "runs", "paper", scene, 3)
    present = run["series"]["targetsPresent"]
    last = max(k for k, n in enumerate(present) if n > 0)
    assert present[-1] == 0 and last < len(present) - 2, present
    explorer.open(write_explorer(camcov, [run_file], tmp_path / "walk.html"))
    times = run["series"]["time"]
    layout = explorer.driver.execute_script("""
      const grid = document.querySelector("svg.timeline line").getBoundingClientRect();
      return {left: grid.left, right: grid.right,
              curves: Array.from(document.querySelectorAll("svg.timeline .curve"))
                .map((c) => c.getBoundingClientRect().right)};""")
    end = layout["left"] + (times[last] - times[0]) / (times[-1] - times[0]) * \
        (layout["right"] - layout["left"])
    assert len(layout["curves"]) == 2
    for right in layout["curves"]:
        assert right <= end + 2, f"a curve runs on to {right} px, past the last step with " \
            f"anyone present ({end:.1f} px)"
    assert "nobody present" in explorer.text("#curve-legend")
    assert_no_console_errors(explorer)


def test_two_runs_with_the_same_curves_both_show(explorer, camcov, tmp_path):
    """The same run twice, the second relabelled as the baseline (its own colour): both
    colours show along the curves, neither hidden behind the other."""
    run_file, run = record_run(camcov, tmp_path / "runs", "paper")
    twin = json.loads(run_file.read_text())
    twin["method"] = "local"
    twin_file = tmp_path / "runs" / "twin.json"
    twin_file.write_text(json.dumps(twin))
    explorer.open(write_explorer(camcov, [run_file, twin_file], tmp_path / "twins.html"))
    colours = explorer.driver.execute_script(
        "return Array.from(document.querySelectorAll('section.run .swatch'))"
        ".map((s) => getComputedStyle(s).backgroundColor)")
    rgb = [tuple(int(v) for v in re.findall(r"\d+", c)[:3]) for c in colours]
    assert len(set(rgb)) == 2, rgb
    timeline = explorer.driver.find_element(By.CSS_SELECTOR, "svg.timeline")
    image = Image.open(io.BytesIO(explorer.screenshot(timeline))).convert("RGB")
    near = lambda p, c: sum(abs(a - b) for a, b in zip(p, c)) < 60
    pixels = list(image.getdata())
    counts = [sum(1 for p in pixels if near(p, c)) for c in rgb]
    assert min(counts) >= 0.25 * max(counts) and min(counts) > 100, \
        f"pixels of each run's colour along the curves: {counts}"
    assert_no_console_errors(explorer)


# ----------------------------------------------------------------------------- zoom and pan

def view_box(explorer, run=0):
    return [float(v) for v in explorer.driver.execute_script(
        "return arguments[0].getAttribute('viewBox')", explorer.world(run)).split()]


def test_the_wheel_zooms_every_world_a_drag_pans_and_whole_scene_resets(explorer, camcov,
                                                                         tmp_path):
    runs = [record_run(camcov, tmp_path / "runs", m)[0] for m in ("paper", "local")]
    explorer.open(write_explorer(camcov, runs, tmp_path / "zoom.html"))
    home = view_box(explorer)
    world = explorer.world(0)
    target = lambda: explorer.world(0).find_element(By.CSS_SELECTOR, "polygon[data-target]")
    before = target().rect["width"]
    ActionChains(explorer.driver).scroll_from_origin(ScrollOrigin.from_element(world), 0, -500) \
        .perform()
    explorer.settle()
    zoomed = view_box(explorer)
    assert zoomed[2] < home[2] / 1.5, f"the wheel did not zoom in: {home} -> {zoomed}"
    assert view_box(explorer, 1) == zoomed, \
        "the worlds side by side show the same part of the scene"
    assert target().rect["width"] > before * 1.5, "the target is not drawn larger"
    # A drag on the world moves the view with the pointer: 100 px to the right shows what lay
    # 100 px to the left.
    scale = zoomed[2] / explorer.world(0).rect["width"]
    ActionChains(explorer.driver).move_to_element_with_offset(explorer.world(0), 10, 10) \
        .click_and_hold().move_by_offset(50, 0).move_by_offset(50, 0).release().perform()
    explorer.settle()
    panned = view_box(explorer)
    assert panned[0] == pytest.approx(zoomed[0] - 100 * scale, rel=0.05, abs=scale * 3), \
        (zoomed, panned)
    explorer.click(explorer.driver.find_element(By.ID, "zoom-reset"))
    explorer.settle()
    assert view_box(explorer) == pytest.approx(home)
    assert_no_console_errors(explorer)
