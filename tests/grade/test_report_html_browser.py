"""The class report in a real headless Chromium: it loads cleanly and draws what the JSON says.

Debian's Chromium and ChromeDriver come from scripts/system-packages.sh (run by
scripts/test.sh). The screenshot is kept in ``$PKGTOOL_TEST_ARTIFACTS`` (default
``.test-artifacts/`` in the checkout) for a human to look at.
"""

from __future__ import annotations

import json
import os
from collections.abc import Iterator
from pathlib import Path

import pytest
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By

from pkgtool.grade.report import render
from pkgtool.grade.report.html import BINS
from tests.grade.class_results import RUBRIC, results

ROOT = Path(__file__).resolve().parents[2]
ARTIFACTS = Path(os.environ.get("PKGTOOL_TEST_ARTIFACTS", ROOT / ".test-artifacts"))


@pytest.fixture(scope="module")
def browser(tmp_path_factory: pytest.TempPathFactory) -> Iterator[webdriver.Chrome]:
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1200,2400",
                     "--disable-dev-shm-usage", "--no-first-run",
                     f"--user-data-dir={tmp_path_factory.mktemp('chromium')}"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(options=options, service=Service("/usr/bin/chromedriver"))
    yield driver
    driver.quit()


def test_the_page_loads_with_no_console_error_and_bars_match_the_json(
        browser: webdriver.Chrome, tmp_path: Path) -> None:
    report = tmp_path / "report.html"
    report.write_text(render("html", results(), rubric=RUBRIC), encoding="utf-8")
    browser.get(report.as_uri())
    assert browser.title == f"{RUBRIC.title}: class report"
    errors = [entry for entry in browser.get_log("browser") if entry["level"] == "SEVERE"]
    assert errors == []
    document = json.loads(render("json", results(), rubric=RUBRIC))
    expected = [0] * BINS
    for submission in document["submissions"]:
        expected[min(BINS - 1, int(submission["score"] / document["max_score"] * BINS))] += 1
    bars = browser.find_elements(By.CSS_SELECTOR, "#histogram rect.bar")
    assert [int(bar.get_attribute("data-count")) for bar in bars] == expected
    heights = [bar.size["height"] for bar in bars]  # as laid out by the browser
    tallest = max(expected)
    assert [round(h * tallest / max(heights)) for h in heights] == expected
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    assert browser.save_screenshot(str(ARTIFACTS / "class-report.png"))


def test_a_student_link_scrolls_to_that_student_s_feedback(browser: webdriver.Chrome,
                                                           tmp_path: Path) -> None:
    report = tmp_path / "report.html"
    report.write_text(render("html", results(), rubric=RUBRIC), encoding="utf-8")
    browser.set_window_size(1200, 600)
    browser.get(report.as_uri())
    assert browser.execute_script("return window.scrollY") == 0
    browser.find_element(By.LINK_TEXT, "carol").click()
    assert browser.current_url.endswith("#s2")
    section = browser.find_element(By.ID, "s2")
    assert section.text.startswith("carol: ")
    top = browser.execute_script("return arguments[0].getBoundingClientRect().top", section)
    assert browser.execute_script("return window.scrollY") > 0
    assert -2 <= top < 600  # scrolled to it: the section is in view (sub-pixel layout)
