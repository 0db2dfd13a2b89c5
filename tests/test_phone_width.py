"""An answer's page on a phone: at 390 px nothing is wider than the screen. A working line too
long for it (a derivation, a fill's given grid) scrolls inside its own box, as wide tables do,
instead of making the whole page scroll sideways (it was 550 px wide for ``circle 5``)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from .helpers import run

pytestmark = [pytest.mark.external, pytest.mark.slow]  # chromium

PHONE = 390

ANSWERS = [
    ("circle", "5", "--method", "midpoint"),
    ("line", "2", "2", "10", "6", "--algo", "bresenham", "--derive"),
    ("ellipse", "8", "6", "--derive"),
    ("fill", "flood", "0", "0", "8", "0", "8", "6", "0", "6", "--seed", "3", "3"),
]

WIDE = """() => [...document.querySelectorAll('.sc-working math, .sc-given math')]
  .filter(m => m.scrollWidth > m.clientWidth + 1)
  .map(m => ({scroll: m.scrollWidth, client: m.clientWidth,
              right: m.getBoundingClientRect().right, overflow: getComputedStyle(m).overflowX}))"""


@pytest.mark.parametrize("argv", ANSWERS, ids=lambda a: "-".join(a[:2]))
def test_the_page_fits_a_phone_and_long_working_lines_scroll(
    browser: Any, tmp_path: Path, argv: tuple[str, ...]
) -> None:
    target = tmp_path / "answer.html"
    r = run(*argv, "-o", str(target))
    assert r.code == 0, r.err
    page = browser.new_page(viewport={"width": PHONE, "height": 800})
    try:
        page.goto(target.as_uri())
        page.wait_for_selector("section.scanconv[data-ready]")
        assert page.evaluate("document.documentElement.scrollWidth") <= PHONE
        for line in page.evaluate(WIDE):  # cut at the screen's edge, the rest a swipe away
            assert line["overflow"] == "auto" and line["right"] <= PHONE, line
    finally:
        page.close()


def test_circle_5_has_a_working_line_wider_than_a_phone(browser: Any, tmp_path: Path) -> None:
    # the case above is not vacuous: this page's working does not fit in 390 px
    target = tmp_path / "answer.html"
    assert run(*ANSWERS[0], "-o", str(target)).code == 0
    page = browser.new_page(viewport={"width": PHONE, "height": 800})
    try:
        page.goto(target.as_uri())
        page.wait_for_selector("section.scanconv[data-ready]")
        assert [w["scroll"] > w["client"] for w in page.evaluate(WIDE)].count(True) >= 1
    finally:
        page.close()
