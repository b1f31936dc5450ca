"""How fast the visibility playground redraws while a camera is dragged, in Chromium.

Writes a playground page for each scene, opens it headless, and moves camera 0 by a small step
60 times the way a drag does (a pose changed, then the page's own recomputation: the engine's
answer and the SVG drawn from it), timing each redraw with performance.now() in the page. Prints
the median and the slowest redraw and the frames per second the median allows.

  PYTHONPATH=tests/support /usr/bin/python3 tests/bench/playground_speed.py \\
      build/src/cli/camcov ../shared/coverage_scenes/static1.json scenes/large/round_4000.json

A benchmark, not a test: the figures depend on the machine (docs/visibility.md gives them).
"""
import pathlib
import statistics
import subprocess
import sys
import tempfile

from browser import start_chromium  # tests/support/browser.py

MEASURE = """
const done = arguments[0];
const api = window.camcovPlayground, poses = api.poses(), times = [];
let k = 0;
function next() {
  if (k === 60) { done(times); return; }
  poses[0].x += (k % 2 ? -1 : 1) * 0.01;
  const t0 = performance.now();
  api.explain();
  times.push(performance.now() - t0);
  k += 1;
  requestAnimationFrame(next);
}
requestAnimationFrame(next);
"""


def main():
    camcov, scenes = sys.argv[1], sys.argv[2:]
    driver = start_chromium()
    try:
        with tempfile.TemporaryDirectory() as folder:
            for scene in scenes:
                page = pathlib.Path(folder) / (pathlib.Path(scene).stem + ".html")
                subprocess.run([camcov, "playground", scene, "-o", str(page)], check=True,
                               capture_output=True)
                driver.get(page.as_uri())
                for _ in range(600):
                    if driver.execute_script("return document.body.dataset.ready") == "1":
                        break
                    driver.execute_script("return 0")
                times = driver.execute_async_script(MEASURE)
                median = statistics.median(times)
                print(f"{pathlib.Path(scene).stem}: redraw median {median:.1f} ms, slowest "
                      f"{max(times):.1f} ms, {1000 / median:.0f} frames/s "
                      f"(page {page.stat().st_size / 1e6:.2f} MB)")
    finally:
        driver.quit()


if __name__ == "__main__":
    main()
