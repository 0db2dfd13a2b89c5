"""An answer's page on a phone: at 390 px nothing is wider than the screen. A working line too
long for it (a derivation, a fill's given grid) scrolls inside its own box, as wide tables do,
instead of making the whole page scroll sideways (it was 550 px wide for ``circle 5``)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from .helpers import run
from .test_browser import give_back, take_tab

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
    page = take_tab(browser, PHONE)
    try:
        page.goto(target.as_uri())
        page.wait_for_selector("section.scanconv[data-ready]")
        assert page.evaluate("document.documentElement.scrollWidth") <= PHONE
        wide = page.evaluate(WIDE)
        for line in wide:  # cut at the screen's edge, the rest a swipe away
            assert line["overflow"] == "auto" and line["right"] <= PHONE, line
        if argv == ANSWERS[0]:  # not vacuous: this page's working does not fit in 390 px
            assert [w["scroll"] > w["client"] for w in wide].count(True) >= 1
        # a cue where a formula is cut at its box's edge, and only there
        cues = page.evaluate(CUES)
        assert cues and all(c["cue"] == (c["scroll"] > c["client"] + 1) for c in cues), cues
        assert [c["cue"] for c in cues].count(True) == len(wide)
        if wide:
            page.screenshot(path=f"/tmp/site2-cue-{argv[0]}.png")
            # scrolled to its end, the cue moves to the left edge
            after = page.evaluate(SCROLLED)
            assert after == {"right": False, "left": True, "shadow": True}, after
    finally:
        give_back(page)


CUES = """() => [...document.querySelectorAll('.sc-working math, .sc-given math')].map(m => ({
  scroll: m.scrollWidth, client: m.clientWidth, cue: m.classList.contains('sc-clip'),
}))"""

SCROLLED = """async () => {
  const m = document.querySelector('math.sc-clip');
  m.scrollLeft = m.scrollWidth;
  await new Promise((done) => setTimeout(done, 100));
  return {right: m.classList.contains('sc-clip'), left: m.classList.contains('sc-clipl'),
          shadow: getComputedStyle(m).boxShadow !== 'none'};
}"""
