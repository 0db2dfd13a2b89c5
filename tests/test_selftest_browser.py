"""The "Test yourself" mode in a real browser (Debian's headless Chromium through Playwright).

Sequences of answers written by hand, right and wrong, are typed (or clicked on the grid) into
pages the CLI writes; the score and the explanations must be what ``check``'s follow-through
gives: a decision that follows from the student's own wrong p_k earns its mark, the pixel is
judged from the student's decision applied to the pixel before. Pages without a rule have no
button. The browser is the session's (``tests/conftest.py``); without chromium or Playwright
the tests skip.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest

from scanconv.algorithms.conventions import ROUNDINGS

from .helpers import run
from .test_browser import Opened, give_back, take_tab  # pages with their logs; tabs

pytestmark = pytest.mark.external  # chromium (external tests are slow too: conftest)

CELL = """([x, y]) => {
  // the centre of the grid's cell (x, y), found from two drawn pixels (y up or down)
  const rects = [...document.querySelectorAll("svg.sc-stepgrid rect.sc-px")];
  const ref = rects[0], b = ref.getBoundingClientRect();
  const other = rects.find(r => r.getAttribute("data-y") !== ref.getAttribute("data-y"));
  const up = (+other.getAttribute("data-y") > +ref.getAttribute("data-y")) ===
    (other.getBoundingClientRect().top < b.top) ? -1 : 1;
  const rx = +ref.getAttribute("data-x"), ry = +ref.getAttribute("data-y");
  return [b.left + (x - rx + 0.5) * b.width, b.top + (up * (y - ry) + 0.5) * b.height];
}"""


class Quiz(Opened):
    """A page open in the browser (with its requests and console messages), in test mode."""

    def __init__(self, browser: Any, path: Path, width: int = 1280) -> None:
        super().__init__(browser, path, width)

    def start(self) -> None:
        self.page.focus("[data-selftest]")
        self.page.keyboard.press("Enter")
        assert self.page.evaluate("document.activeElement.name") == "p"

    def answer(self, p: str | None, decision: str | None, pixel: str | tuple[int, int]) -> str:
        """Type one step (``pixel`` a tuple: click that pixel on the grid), press Enter, and
        return the feedback; then go on with Enter (the focus is on "Next step")."""
        pg = self.page
        if p is not None:
            pg.keyboard.type(p)
        if decision is not None:
            pg.select_option("select[name=decision]", decision)
        if isinstance(pixel, tuple):
            pg.mouse.click(*pg.evaluate(CELL, list(pixel)))
            assert pg.evaluate("document.activeElement.name") == "pixel"
        else:
            pg.fill("input[name=pixel]", pixel)
        pg.keyboard.press("Enter")
        feedback = pg.inner_text(".sc-tfeed")
        assert pg.evaluate("document.activeElement.textContent") in ("Next step", "Again")
        return feedback

    def next(self) -> None:
        self.page.keyboard.press("Enter")

    def score(self) -> str:
        return self.page.inner_text(".sc-tscore")


@pytest.fixture
def quiz(browser: Any, tmp_path: Path) -> Any:
    opened: list[Quiz] = []

    def open_quiz(*argv: str, width: int = 1280) -> Quiz:
        target = tmp_path / f"quiz{len(opened)}.html"
        r = run(*argv, "-o", str(target))
        assert r.code == 0, r.err
        q = Quiz(browser, target, width)
        opened.append(q)
        return q

    yield open_quiz
    for q in opened:
        q.close()


LINE = ("line", "2", "2", "10", "6")
LINE_RIGHT = [
    ("0", "NE", "3, 3"), ("-8", "E", "4, 3"), ("0", "NE", "5, 4"), ("-8", "E", "6, 4"),
    ("0", "NE", "7, 5"), ("-8", "E", "8, 5"), ("0", "NE", "9, 6"), ("-8", "E", "10, 6"),
]  # fmt: skip


def test_a_right_bresenham_line_scores_full_marks(quiz):
    q = quiz(*LINE)
    q.start()
    for i, (p, d, px) in enumerate(LINE_RIGHT):
        feedback = q.answer(p, d, px)
        assert "\u2717" not in feedback, (i, feedback)
        if i < len(LINE_RIGHT) - 1:
            assert q.score() == f"Score so far: {i + 1} / {i + 1} steps right"
            q.next()
    assert q.score() == "Score: 8 / 8 steps right (100 %)"
    assert "p\u2087 = \u22128 < 0, so the next pixel is E: (10, 6)." in feedback


def check_score(tmp_path: Path, question: tuple[str, ...], steps, header: str) -> str:
    """``check``'s score (``N of M``) of the same steps written as a student's CSV, a row a
    step in the textbooks' layout (p_k, the decision, the point it reaches)."""
    rows = [",".join([str(k), *(c for c in step if c is not None)]) for k, step in enumerate(steps)]
    path = tmp_path / "same.csv"
    path.write_text(header + "\n" + "\n".join(r.replace(", ", ",") for r in rows) + "\n")
    done = run("check", str(path), "--", *question, "-f", "json")
    assert done.code == 0, done.err
    import json

    data = json.loads(done.out)
    return f"{data['score']} / {data['out_of']}"


# Bresenham from (2, 2) to (10, 6) with p1 written 8 (it is -8): NE follows from 8 > 0 and
# (4, 4) from NE; then on from her own (4, 4) with p2 = 8 - 8 = 0 (her p and her move):
# 0, NE, (5, 5); -8, E, (6, 5); 0, NE, (7, 6); -8, E, (8, 6); 0, NE, (9, 7); -8, E, (10, 7).
# One slip, every later step followed through from it: 7 of 8 steps, as check marks it.
FOLLOWED = [("0", "NE", "3, 3"), ("8", "NE", "4, 4"), ("0", "NE", "5, 5"), ("-8", "E", "6, 5"),
            ("0", "NE", "7, 6"), ("-8", "E", "8, 6"), ("0", "NE", "9, 7"), ("-8", "E", "10, 7")]  # fmt: skip
# The same slip, then back on the answer's revealed rows with a wrong decision word and a
# wrong pixel: 5 of 8 as check marks it (its rows 3 and 4 judged from her own (4, 4))
MIXED = [("0", "NE", "3, 3"), ("8", "NE", "4, 4"), ("0", "E", "5, 3"), ("-8", "E", "6, 5"),
         *LINE_RIGHT[4:]]  # fmt: skip


def _typed(q: Quiz, steps) -> list[str]:
    feedback = []
    for i, (p, d, px) in enumerate(steps):
        feedback.append(q.answer(p, d, px))
        if i < len(steps) - 1:
            q.next()
    return feedback


@pytest.mark.parametrize(("steps", "score"), [(FOLLOWED, "7 / 8"), (MIXED, "5 / 8")])
def test_a_page_opened_from_file_follows_through_as_check_does(quiz, tmp_path, steps, score):
    q = quiz(*LINE)
    q.start()
    f = _typed(q, steps)
    assert check_score(tmp_path, LINE, steps, "k,p,decision,x,y") == score
    pct = round(100 * int(score.split(" / ")[0]) / 8 + 1e-9)
    assert q.score() == f"Score: {score} steps right ({pct} %)"
    assert (
        "\u2717 p\u2081 = \u22128, not 8 (p\u2081 = p\u2080 \u2212 8 = 0 \u2212 8 = \u22128)"
        in f[1]
    )
    assert "\u2713 decision NE: it follows from your p\u2081 = 8 > 0 (follow-through)" in f[1]
    assert "\u2713 next pixel (4, 4) (follow-through from your decision)" in f[1]
    assert "p\u2081 = \u22128 < 0, so the next pixel is E: (4, 3)." in f[1]
    if steps is FOLLOWED:  # each later step judged from her own state: all right
        assert all("\u2717" not in x for x in f[2:]), f[2:]
        assert "\u2713 p\u2082 = 0" in f[2] and "\u2713 next pixel (5, 5)" in f[2]


# The midpoint circle r = 8 with p1 written -5 (it is -4): her p2 = -5 + 2*1 + 3 = 0 chooses SE
# (3, 7), p3 = 0 + 2*2 - 2*8 + 5 = -7, E (4, 7), p4 = -7 + 2*3 + 3 = 2, SE (5, 6),
# p5 = 2 + 2*4 - 2*7 + 5 = 1, SE (6, 5): 5 of 6 steps (worked by hand; check agrees).
CIRCLE_SLIP = [("-7", "E", "1, 8"), ("-5", "E", "2, 8"), ("0", "SE", "3, 7"), ("-7", "E", "4, 7"),
               ("2", "SE", "5, 6"), ("1", "SE", "6, 5")]  # fmt: skip


def test_a_circles_slip_in_p_is_followed_through_as_check_does(quiz, tmp_path):
    q = quiz("circle", "8")
    q.start()
    f = _typed(q, CIRCLE_SLIP)
    header = 'k,p_k,decision,"(x_{k+1}, y_{k+1})"'
    steps = [(p, d, f'"({px})"') for p, d, px in CIRCLE_SLIP]
    assert check_score(tmp_path, ("circle", "8"), steps, header) == "5 / 6"
    assert q.score() == "Score: 5 / 6 steps right (83 %)"
    assert all("\u2717" not in x for x in f[2:]), f[2:]


def test_the_rules_own_pixel_after_a_wrong_decision_word_is_right(quiz):
    """The walkthrough's step: p0 = 0, decision E, and the right pixel
    (3, 3). The pixel is the rule's own step, so the decision word is the one slip, as
    ``check`` judges it: the pixel is not called wrong (it was: 1 of 3 marks)."""
    q = quiz(*LINE)
    q.start()
    f = q.answer("0", "E", "3, 3")
    assert "\u2717 decision: E; p\u2080 = 0 chooses NE" in f
    assert "\u2713 next pixel (3, 3) (the rule's step: the decision was the slip)" in f
    assert q.score() == "Score so far: 0 / 1 steps right"


def test_the_table_hides_from_the_current_row_on_and_the_stepper_keys_give_nothing_away(quiz):
    q = quiz(*LINE)
    q.start()
    for p, d, px in LINE_RIGHT[:3]:
        q.answer(p, d, px)
        q.next()
    visible = q.page.evaluate(
        """() => [...document.querySelectorAll("tr[data-pos]")]
              .filter(t => t.offsetParent !== null).map(t => +t.getAttribute("data-pos"))"""
    )
    assert visible == [1, 2, 3]  # rows k = 0, 1, 2; row k = 3 holds the p asked now
    # the p_{k+1} column of the last row shown is p_3 itself: hidden
    hidden = q.page.evaluate(
        """() => getComputedStyle(document.querySelector('tr[data-pos="3"] td.sc-hidcell')).color"""
    )
    assert hidden == "rgba(0, 0, 0, 0)"
    assert not q.page.is_visible(".sc-caption") and not q.page.is_visible(".sc-pixels")
    before = q.page.get_attribute("section.scanconv", "data-pos")
    q.page.focus(".sc-testpanel button[data-tact=stop]")
    q.page.keyboard.press("ArrowRight")
    q.page.keyboard.press("End")
    assert q.page.get_attribute("section.scanconv", "data-pos") == before
    q.page.keyboard.press("Enter")  # Stop: the whole table again
    assert q.page.evaluate("document.querySelectorAll('tr[data-pos]').length") == q.page.evaluate(
        """() => [...document.querySelectorAll("tr[data-pos]")]
              .filter(t => t.offsetParent !== null).length"""
    )
    assert q.page.get_attribute("[data-selftest]", "aria-expanded") == "false"


CIRCLE = ("circle", "5", "--center", "2", "3")


def test_a_right_midpoint_circle_clicked_on_the_grid_scores_full_marks(quiz):
    q = quiz(*CIRCLE)
    q.start()
    steps = [("-4", "E", (3, 8)), ("-1", "E", (4, 8)), ("4", "SE", (5, 7)), ("3", "SE", (6, 6))]
    for i, (p, d, px) in enumerate(steps):
        f = q.answer(p, d, px)
        assert "\u2717" not in f, f
        if i < 3:
            q.next()
    assert "p\u2083 = 3 > 0, so the next pixel is SE: (4, 3)." in f
    assert q.score() == "Score: 4 / 4 steps right (100 %)"


def test_a_wrong_midpoint_circle_is_marked_with_follow_through(quiz):
    q = quiz(*CIRCLE)
    q.start()
    assert "\u2717" not in q.answer("-4", "E", "1, 5")
    q.next()
    # p1 = 2 (it is -1): SE follows from 2 > 0; the click on (2, 4) (absolute (4, 7)) from SE
    f = q.answer("2", "SE", (4, 7))
    assert "\u2717 p\u2081 = \u22121, not 2 (p\u2081 = p\u2080 + 3 = \u22124 + 3 = \u22121)" in f
    assert "\u2713 decision SE: it follows from your p\u2081 = 2 > 0 (follow-through)" in f
    assert "\u2713 next pixel (2, 4)" in f
    assert "p\u2081 = \u22121 < 0, so the next pixel is E: (2, 5)." in f
    q.next()
    # her p2 = 2 + 2*1 - 2*5 + 5 = -1 from her (2, 4) (check's follow-through): E, (3, 4)
    f = q.answer("-1", "E", "3, 4")
    assert "\u2717" not in f and "\u2713 p\u2082 = \u22121 (follow-through" in f
    q.next()
    # p3 = -1 + 2*2 + 3 = 6 from (3, 4): SE (4, 3), written (4, 4): the pixel wrong
    f = q.answer("6", "SE", "4, 4")
    assert "\u2717 next pixel: SE from (3, 4) goes to (4, 3), not (4, 4)" in f
    assert q.score() == "Score: 2 / 4 steps right (50 %)"
    q.next()  # "Again" starts over
    assert "Step 1 of 4" in q.page.inner_text(".sc-tq") and q.score() == ""


def test_a_dda_line_asks_the_exact_values_and_rounds_the_students_own(quiz):
    q = quiz("line", "0", "0", "5", "3", "--algo", "dda")
    q.start()
    assert q.page.inner_text(".sc-tq").startswith("Step 1 of 5: from (0.000, 0.000), what are")
    f = q.answer("1, 0.6", None, "1, 1")
    assert "\u2717" not in f and "(x\u2081, y\u2081) = (1.000, 0.600)" in f
    q.next()
    # y2 written 1.5 (it is 1.2): wrong, but its pixel (2, 2) is rounded from it
    f = q.answer("2, 3/2", None, "2, 2")
    assert "\u2717 (x\u2082, y\u2082) = (2.000, 1.200), not 2, 3/2" in f
    assert "\u2713 pixel (2, 2), rounded from your values: follow-through" in f
    for xy, px in [("3, 9/5", "3, 2"), ("4, 2.4", "4, 2"), ("5, 3", "5, 3")]:
        q.next()
        assert "\u2717" not in q.answer(xy, None, px)
    assert q.score() == "Score: 4 / 5 steps right (80 %)"


def test_an_ellipse_asks_both_regions(quiz):
    q = quiz("ellipse", "8", "6")
    q.start()
    right = [("-332", "E", "1, 6"), ("-224", "E", "2, 6"), ("-44", "E", "3, 6"),
             ("208", "SE", "4, 5"), ("-108", "E", "5, 5"), ("288", "SE", "6, 4"),
             ("244", "SE", "7, 3"), ("-23", "SE", "8, 2"), ("361", "S", "8, 1"),
             ("297", "S", "8, 0")]  # fmt: skip
    for i, (p, d, px) in enumerate(right):
        if i == 7:  # region 2 starts: p2_0
            assert "p2\u2080 =" in q.page.inner_text("form.sc-tform")
        assert "\u2717" not in q.answer(p, d, px)
        if i < len(right) - 1:
            q.next()
    assert q.score() == "Score: 10 / 10 steps right (100 %)"


def test_the_script_rounds_as_the_library_does(quiz):
    q = quiz(*LINE)
    values = [Fraction(n, d) for d in (1, 2, 3, 4, 5, 10) for n in range(-13, 14)]
    for how, fn in ROUNDINGS.items():
        got = q.page.evaluate(
            """([vs, how]) => vs.map(v => Number(window.scanconvSelftest.round(
                 window.scanconvSelftest.num(v), how)))""",
            [[str(v) for v in values], how],
        )
        assert got == [fn(v) for v in values], how
    same = q.page.evaluate(
        """(pairs) => pairs.map(([a, b]) => window.scanconvSelftest.same(
             window.scanconvSelftest.num(a), window.scanconvSelftest.num(b)))""",
        [["0.33", "1/3"], ["0.3", "1/3"], ["-1.25", "-5/4"], ["\u22125/4", "-5/4"], ["2", "2.0"],
         ["0.667", "2/3"], ["0.665", "2/3"], ["x", "1"], ["1/0", "1"]],
    )  # fmt: skip
    assert same == [True, False, True, True, True, True, False, False, False]


def test_a_page_without_a_step_table_or_rule_has_no_button(browser, tmp_path):
    for i, argv in enumerate(
        [("polygon", "2", "3", "7", "1", "13", "5"), ("circle", "5", "-m", "trig")]
    ):
        target = tmp_path / f"plain{i}.html"
        assert run(*argv, "-o", str(target)).code == 0
        page = take_tab(browser)
        page.goto(target.as_uri())
        page.wait_for_selector("section.scanconv[data-ready]")
        assert page.locator("[data-selftest]").count() == 0
        assert page.get_by_role("button", name="Test yourself").count() == 0
        give_back(page)


def test_the_mode_fits_a_phone(quiz):
    q = quiz(*CIRCLE, width=390)
    q.start()
    box = q.page.locator(".sc-testpanel").bounding_box()
    assert box is not None and box["x"] >= 0 and box["x"] + box["width"] <= 390
    for sel in ("input[name=p]", "select[name=decision]", "input[name=pixel]"):
        b = q.page.locator(sel).bounding_box()
        assert b is not None and b["x"] + b["width"] <= 390, sel
    # targets of at least 24 CSS px (WCAG 2.2, 2.5.8): the grid's cells (13 px before) and the
    # controls; a grid too wide for the screen scrolls in its own box, never the page
    sizes = q.page.evaluate(TARGETS)
    assert len(sizes) > 10 and [s for s in sizes if min(s[1], s[2]) < 24] == []
    assert q.page.evaluate("document.documentElement.scrollWidth") <= 390
    q.page.screenshot(path="/tmp/site2-selftest-phone.png")
    q.answer("-4", "E", (3, 8))


TARGETS = """() => [...document.querySelectorAll(`svg.sc-stepgrid rect.sc-px, .sc-testpanel input,
  .sc-testpanel select, .sc-testpanel button, .sc-selftest button`)]
  .filter(e => e.getClientRects().length)
  .map(e => { const r = e.getBoundingClientRect(); return [e.tagName, r.width, r.height]; })"""
"""The tag, width and height of every target of the test on the screen."""


def test_the_tip_of_a_flat_ellipse_asks_the_pixel_only(quiz):
    q = quiz("ellipse", "12", "1")
    q.start()
    n = int(q.page.inner_text(".sc-tq").split(" of ")[1].split(":")[0])
    for _ in range(n - 1):  # every step but the last left blank: no mark
        q.page.keyboard.press("Enter")
        q.next()
    assert q.page.inner_text(".sc-tq") == f"Step {n} of {n}: from (11, 0), the pixel only"
    assert not q.page.is_visible("input[name=p]") and not q.page.is_visible("select")
    assert q.page.evaluate("document.activeElement.name") == "pixel"
    f = q.answer(None, None, "12, 0")
    assert "\u2713 next pixel (12, 0)" in f and "the next pixel is E: (12, 0)." in f
    assert q.score().startswith("Score: 1 / ")


def test_a_click_on_a_grid_with_y_down_names_the_right_pixel(quiz):
    q = quiz(*LINE, "--origin", "top-left")
    q.start()
    for i, (p, d, px) in enumerate(LINE_RIGHT[:3]):
        x, y = (int(v) for v in px.split(", "))
        assert "\u2717" not in q.answer(p, d, (x, y))
        assert q.page.input_value("input[name=pixel]") == f"{x}, {y}"
        if i < 2:
            q.next()
    assert q.score() == "Score so far: 3 / 3 steps right"


def test_two_notebook_answers_test_apart(browser, tmp_path):
    import scanconv

    cells = [scanconv.line(2, 2, 10, 6)._repr_html_(), scanconv.circle(5)._repr_html_()]
    target = tmp_path / "notebook.html"
    target.write_text(
        "<!DOCTYPE html><html><head><meta charset='utf-8'></head><body>"
        + "".join(f"<div class='cell'>{c}</div>" for c in cells)
        + "</body></html>",
        encoding="utf-8",
    )
    page = take_tab(browser)
    errors: list[str] = []

    def error(e: Any) -> None:
        errors.append(str(e))

    page.on("pageerror", error)
    page.goto(target.as_uri())
    page.wait_for_selector("section.scanconv[data-st-ready]")
    line, circle = page.locator("section.scanconv").all()
    assert page.locator("section.scanconv[data-st-ready]").count() == 2
    line.locator("[data-selftest]").click()
    assert line.evaluate("r => r.classList.contains('sc-testing')")
    assert not circle.evaluate("r => r.classList.contains('sc-testing')")
    line.locator("input[name=p]").fill("0")
    line.locator("select[name=decision]").select_option("NE")
    line.locator("input[name=pixel]").fill("3, 3")
    page.keyboard.press("Enter")
    assert "\u2717" not in line.locator(".sc-tfeed").inner_text()
    pos = line.get_attribute("data-pos")
    page.keyboard.press("ArrowRight")  # the focus is in the test: the stepper stays
    assert line.get_attribute("data-pos") == pos
    circle.locator("button[data-act=reset]").click()
    page.keyboard.press("ArrowRight")  # the other answer still steps
    assert circle.get_attribute("data-pos") == "1"
    page.remove_listener("pageerror", error)
    give_back(page)
    assert errors == []
