"""Headless Chromium for the browser tests (the explorer page, the report), driven by Selenium
through Debian's chromedriver: no Selenium Manager, no network (name resolution is disabled, so
a page that reaches for the network fails). Tests fail, rather than skip, without the Debian
packages chromium, chromium-driver and python3-selenium (scripts/install_deps.sh installs them).
"""
import os

import pytest

try:
    from selenium import webdriver
    from selenium.common.exceptions import WebDriverException
    from selenium.webdriver.chrome.service import Service
except ImportError:  # reported by start_chromium, so that every test fails
    webdriver = None

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
INSTALL_HINT = ("install the Debian packages chromium chromium-driver python3-selenium "
                "(scripts/install_deps.sh does) and run with /usr/bin/python3")


def start_chromium(width=1400, height=1000):
    """A headless Chromium whose console log the test can read (driver.get_log("browser"))."""
    missing = [name for name, present in (("python3-selenium", webdriver is not None),
                                          (CHROMIUM, os.access(CHROMIUM, os.X_OK)),
                                          (CHROMEDRIVER, os.access(CHROMEDRIVER, os.X_OK)))
               if not present]
    if missing:
        pytest.fail(f"missing {', '.join(missing)}: {INSTALL_HINT}", pytrace=False)
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu",
                     f"--window-size={width},{height}", "--disable-dev-shm-usage",
                     "--no-first-run", "--disable-sync", "--disable-background-networking",
                     "--disable-component-update",
                     "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE localhost"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    try:
        driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    except WebDriverException as error:
        pytest.fail(f"Chromium did not start through chromedriver: {error.msg}\n({INSTALL_HINT})",
                    pytrace=False)
    driver.set_page_load_timeout(60)
    driver.set_script_timeout(30)
    return driver
