"""The report of a Python batch of two user methods and no baseline, read in a real browser:
it says what ran — the methods by their own names and descriptions, compared with the one the
batch chose as reference, the script that ran it and each method's code identity — and nothing
that assumes the default experiment (the paper's method against local optimization, "ours")."""
import numpy as np
import pytest

import camcov
from browser import start_chromium  # tests/support/browser.py

from selenium.webdriver.common.by import By


def spinner(rate, description, color):
    def make(scene, params, seed):
        return lambda o: np.tile([0.0, 0.0, rate], (len(o.cameras), 1))
    make.description = description
    make.color = color
    return make


@pytest.fixture
def browser():
    driver = start_chromium()
    yield driver
    driver.quit()


def test_a_python_batch_report_names_its_own_methods_and_nothing_else(tiny, tmp_path, browser):
    out = tmp_path / "batch"
    camcov.bench([tiny("tiny_static"), tiny("tiny_dynamic")], methods=["slow-spin", "fast-spin"],
                 seeds=4, out=str(out), params={"sim.duration": 2.0}, explorer="none",
                 controllers={"slow-spin": spinner(0.2, "turns slowly", "#123456"),
                              "fast-spin": spinner(1.0, "turns fast", "#654321")})
    browser.get((out / "report.html").as_uri())
    header = browser.find_element(By.CSS_SELECTOR, "header.report-header").text
    lede = browser.find_element(By.CSS_SELECTOR, "header .lede").text
    assert "slow-spin (turns slowly)" in lede and "fast-spin (turns fast)" in lede, lede
    assert "each compared with slow-spin" in lede, lede
    verdicts = [p.text for p in browser.find_elements(By.CSS_SELECTOR, "header .verdict")]
    assert any("turns fast against turns slowly" in v for v in verdicts), verdicts
    for wording in ("local optimization", "paper's method", "ours", "Hönig", "global + local"):
        assert wording not in header, f"the header assumes the default methods: {wording!r}"
    facts = {dt.text: dd.text for dt, dd in zip(browser.find_elements(By.CSS_SELECTOR, "dl.facts dt"),
                                                browser.find_elements(By.CSS_SELECTOR, "dl.facts dd"))}
    assert facts["Command"].startswith("python ") and "pytest" in facts["Command"], facts
    assert "slow-spin python " in facts["Code"] and "fast-spin python " in facts["Code"], facts
    severe = [e["message"] for e in browser.get_log("browser") if e.get("level") == "SEVERE"]
    assert not severe, severe
