"""The site on a phone, as a student uses it, in Debian's headless
Chromium through Playwright: the site built and served as in ``tests/test_site_browser.py``
(its fixtures), one page at 390 x 844 px for the module (one cold start of Pyodide).

* **Test yourself marks as check does.** The same answers with one slip are typed into the
  test-yourself mode of the site's answer and written as a student writes a CSV for
  ``scanconv check`` (run as a subprocess): the page's score and the expected step it shows
  for every step are check's (its score and its "expected" column), the steps after the slip
  right by follow-through. Before, the page judged each step from the right row: the slip
  cost the next step's p as well (7/8 in check, 22 of 24 marks on the page).
* **The answer is scrolled into view** once shown: its top is on the screen (it was more
  than a screen below, under the question box, the examples and the forms).
* **Form labels are words with the flag beside**, read off the command line's help (the
  words are in ``scanconv line --help``).
* **Targets of at least 24 CSS px** in test yourself (the grid's cells were 13 px), and no
  console error, in the page or its frame.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from .helpers import run, run_process
from .test_site_browser import LOAD, Site, _link, origin, site  # noqa: F401 - the fixtures

pytestmark = [pytest.mark.slow, pytest.mark.external]  # chromium, Pyodide

PHONE = {"width": 390, "height": 844}

LINE = "line 2 2 10 6"
SLIPPED = [  # p1 = 8 (it is -8): NE and (4, 4) follow from it, and the rest from (4, 4)
    ("0", "NE", "3, 3"), ("8", "NE", "4, 4"), ("0", "NE", "5, 5"), ("-8", "E", "6, 5"),
    ("0", "NE", "7, 6"), ("-8", "E", "8, 6"), ("0", "NE", "9, 7"), ("-8", "E", "10, 7"),
]  # fmt: skip


class Phone(Site):
    """A page of the site on a 390 x 844 phone screen, with every console error it logs (its
    frame's too), from its load on (the page is loaded again once the log is listened to)."""

    def __init__(self, browser: Any, at: str, hash: str = "") -> None:
        super().__init__(browser, at, hash, width=PHONE["width"])
        self.console: list[str] = []
        self.page.on("console", lambda m: self.console.append(m.text) if m.type == "error" else 0)
        self.page.set_viewport_size(PHONE)
        self.page.reload()

    def close(self) -> None:
        super().close()
        assert self.console == []


@pytest.fixture(scope="module")
def phone(browser: Any, origin: str) -> Iterator[Site]:  # noqa: F811 - the fixture imported
    """The module's phone page, Python loaded."""
    opened = Phone(browser, origin)
    opened.page.wait_for_function("document.body.dataset.state === 'ready'", timeout=LOAD)
    yield opened
    opened.close()


def _check(tmp_path: Path, steps: list[tuple[str, str, str]]) -> tuple[list[str], str]:
    """``check``'s expected column and score for ``steps`` written as a student's CSV (the
    textbooks' layout: p_k, the decision, the pixel it reaches)."""
    csv = tmp_path / "student.csv"
    lines = ["k,p_k,decision,x_{k+1},y_{k+1}"]
    lines += [f"{k},{p},{d},{px}" for k, (p, d, px) in enumerate(steps)]
    csv.write_text("\n".join(lines).replace(", ", ",") + "\n")
    r = run_process("check", str(csv), "-f", "json", "--", *LINE.split())
    assert r.code == 0, r.err
    data = json.loads(r.out)
    rows = data["tables"][0]["rows"]
    return [row[3] for row in rows if row[0] > 0], f"{data['score']} / {data['out_of']}"


def test_the_answer_is_scrolled_to_the_top_of_a_phone_screen(phone: Site) -> None:
    page = phone.page
    phone.ask(LINE)
    frame = page.frame_locator("#answer")
    frame.locator("section.scanconv[data-ready]").wait_for()
    page.wait_for_function("document.getElementById('answer').style.height !== ''")
    top = page.evaluate("document.getElementById('answer').getBoundingClientRect().top")
    assert 0 <= top < 5  # at the top of the screen
    # not vacuous: unscrolled, the answer starts below the upper half of the screen
    assert page.evaluate("document.getElementById('answer').offsetTop") > PHONE["height"] / 2
    page.screenshot(path="/tmp/site2-phone-answer.png")


def test_test_yourself_on_the_site_marks_one_slip_as_check_does(
    phone: Site, tmp_path: Path
) -> None:
    expected, score = _check(tmp_path, SLIPPED)
    assert score == "7 / 8"  # check: the slip costs one step
    page = phone.page
    phone.ask(LINE + " --tie step")  # the default tie: the same table, in a frame of its own
    frame = page.frame_locator("#answer")
    frame.locator("section.scanconv[data-ready]").wait_for()
    frame.locator("[data-selftest]").click()
    shown, feedback = [], []
    for i, (p, d, px) in enumerate(SLIPPED):
        frame.locator("input[name=p]").fill(p)
        frame.locator("select[name=decision]").select_option(d)
        frame.locator("input[name=pixel]").fill(px)
        frame.get_by_role("button", name="Check").click()
        said = frame.locator(".sc-tfeed .sc-texp")
        said.wait_for(timeout=120_000)
        text = frame.locator(".sc-tfeed").inner_text()
        feedback.append(text)
        shown.append(said.inner_text().replace("\u2212", "-").split(": ", 1)[1])
        if i == 1:
            page.screenshot(path="/tmp/site2-phone-slip.png")
        if i + 1 < len(SLIPPED):
            frame.get_by_role("button", name="Next step").click()
    assert shown == expected
    assert frame.locator(".sc-tscore").inner_text() == f"Score: {score} steps right (88 %)"
    assert "\u2717 p\u2081 = \u22128, not 8" in feedback[1]
    assert "Why: p should be \u22128, not 8 (the step from (2, 2) with p = 0)." in feedback[1]
    assert "\u2713 decision NE (follow-through" in feedback[1]
    assert "\u2717" not in "".join(feedback[2:])  # judged from the student's own (4, 4)
    assert "\u2713 next pixel (10, 7) (follow-through" in feedback[7]


def test_the_walkthroughs_slip_is_one_mark_and_no_right_cell_is_called_wrong(
    phone: Site, tmp_path: Path
) -> None:
    """The walkthrough's row: p0 = 0, E, and the right pixel (3, 3). Check calls the decision
    wrong and the pixel right (the expected column shows (3, 3)); the page says the same."""
    steps = [("0", "E", "3, 3")]
    expected, _ = _check(tmp_path, steps)
    page = phone.page
    phone.ask(LINE + " --algo bresenham")  # a new frame, a new test
    frame = page.frame_locator("#answer")
    frame.locator("section.scanconv[data-ready]").wait_for()
    frame.locator("[data-selftest]").click()
    frame.locator("input[name=p]").fill("0")
    frame.locator("select[name=decision]").select_option("E")
    frame.locator("input[name=pixel]").fill("3, 3")
    frame.get_by_role("button", name="Check").click()
    frame.locator(".sc-tfeed .sc-texp").wait_for()
    text = frame.locator(".sc-tfeed").inner_text()
    assert expected[0] == "p = 0, NE, (3, 3)"
    assert f"Expected (as check marks it): {expected[0]}" in text
    assert "\u2713 next pixel (3, 3)" in text and "\u2717 decision NE, not E" in text
    assert frame.locator(".sc-tscore").inner_text() == "Score so far: 0 / 1 steps right"


def test_test_yourself_targets_are_at_least_24_css_px(phone: Site) -> None:
    page = phone.page
    phone.ask("circle 8")
    frame = page.frame_locator("#answer")
    frame.locator("section.scanconv[data-ready]").wait_for()
    frame.locator("[data-selftest]").click()
    sizes = frame.locator("body").evaluate(
        """() => [...document.querySelectorAll(`svg.sc-stepgrid rect.sc-px, .sc-testpanel input,
          .sc-testpanel select, .sc-testpanel button, .sc-selftest button`)]
          .filter(e => e.getClientRects().length)
          .map(e => { const r = e.getBoundingClientRect();
                      return [e.tagName, r.width, r.height]; })"""
    )
    assert len(sizes) > 10
    small = [s for s in sizes if min(s[1], s[2]) < 24]
    assert small == []
    assert page.evaluate("document.documentElement.scrollWidth") <= PHONE["width"]
    page.screenshot(path="/tmp/site2-phone-targets.png")


def test_form_labels_are_words_from_the_help_with_the_flag_beside(phone: Site) -> None:
    page = phone.page
    page.click("#forms summary")
    page.select_option("#sc-command", "line")
    labels = page.locator(".sc-form[data-command='line'] label").all_inner_texts()
    assert "Line algorithm (--algo)" in labels
    assert "x of the first end point P1 (X1)" in labels
    help_text = " ".join(run("line", "--help").out.split())
    for label in labels:
        words, flag = re.fullmatch(r"(.+) \((\S+)\)", label.strip()).groups()  # type: ignore[union-attr]
        assert flag in help_text or flag.lower() in help_text, label
        if ", for " not in words:  # the words are the help's, in its order (an aside left out)
            pattern = r"\b" + r"\b.*?\b".join(map(re.escape, words.lower().split())) + r"\b"
            assert re.search(pattern, help_text.lower()), label
    assert all(not re.fullmatch(r"--?\S+", label.strip()) for label in labels)
    page.screenshot(path="/tmp/site2-phone-form.png", full_page=False)


def test_a_shared_link_to_the_answer_scrolls_too(browser: Any, origin: str) -> None:  # noqa: F811
    """A link opened on a phone (a new page: the whole cold start) shows the answer at the
    top of the screen, with no console error."""
    opened = Phone(browser, origin, _link("circle 5"))
    try:
        opened.wait(1)
        opened.page.frame_locator("#answer").locator("section.scanconv[data-ready]").wait_for()
        opened.page.wait_for_function("document.getElementById('answer').style.height !== ''")
        top = opened.page.evaluate("document.getElementById('answer').getBoundingClientRect().top")
        assert 0 <= top < 5
    finally:
        opened.close()


@pytest.mark.parametrize("question", ["line 0 0 6 3 --algo dda", "ellipse 6 4", "circle 6"])
def test_every_marked_method_on_the_site_scores_a_slip_as_check(
    phone: Site, tmp_path: Path, question: str
) -> None:
    """The DDA (exact values and the pixel), an ellipse (both regions, its tip) and a circle:
    every step typed, the second with a slip, as check marks the same CSV."""
    from .test_marking_steps import _csv, _slip, _typed

    steps, dda = _typed(question)
    first = "exact" if dda else "p"
    steps[1][first] = _slip(steps[1][first], first)
    csv = tmp_path / "student.csv"
    csv.write_text(_csv(steps, dda))
    r = run_process("check", str(csv), "-f", "json", "--", *question.split())
    assert r.code == 0, r.err
    data = json.loads(r.out)
    expected = [row[3] for row in data["tables"][0]["rows"] if row[0] > 0]
    phone.ask(question)
    frame = phone.page.frame_locator("#answer")
    frame.locator("section.scanconv[data-ready]").wait_for()
    frame.locator("[data-selftest]").click()
    shown = []
    for i, step in enumerate(steps):
        # the step's form, shown once the page has the step (a hang guard: the site's Python
        # can take a while to judge the first step on a loaded machine)
        frame.locator("input[name=pixel]").wait_for(state="visible", timeout=120_000)
        if frame.locator("input[name=p]").is_visible():
            frame.locator("input[name=p]").fill(step["exact"] if dda else step["p"])
        if frame.locator("select[name=decision]").is_visible():
            frame.locator("select[name=decision]").select_option(step["decision"])
        frame.locator("input[name=pixel]").fill(step["pixel"])
        frame.get_by_role("button", name="Check").click()
        said = frame.locator(".sc-tfeed .sc-texp")
        said.wait_for()
        shown.append(said.inner_text().replace("\u2212", "-").split(": ", 1)[1])
        if i + 1 < len(steps):
            frame.get_by_role("button", name="Next step").click()
    assert shown == expected
    score = frame.locator(".sc-tscore").inner_text()
    assert score.startswith(f"Score: {data['score']} / {data['out_of']} steps right")
    assert data["score"] < data["out_of"]  # the slip cost a step
