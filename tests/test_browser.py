"""The ``html`` page in a real browser: Debian's headless Chromium, driven by Playwright.

Each page is written by the CLI (``-o answer.html``) and opened from ``file://``. The tests
read the DOM after key presses and clicks and compare it with the JSON answer of the same
command: at step k the highlighted row is row k and the lit pixels are those of the JSON
answer's first k steps (their mirror images too, for a circle or an ellipse), for a line in
every octant, a circle, an ellipse and a Bezier curve. Every page is also checked for network
requests (none but ``file:``/``data:``/``blob:``, with every host name unresolvable besides)
and console errors (none).

The browser is the system's (``chromium`` on PATH: Debian's package, installed by
``.ci/run``), never one Playwright downloads; without it, or without Playwright, the tests
skip and say why. One browser serves the whole session.
"""

from __future__ import annotations

import json
import shutil
import subprocess
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from .helpers import run

pytestmark = pytest.mark.external  # chromium (external tests are slow too: conftest)

CHROMIUM = shutil.which("chromium")
LOCAL = ("file:", "data:", "blob:", "about:")

STATE = """(root) => {
  const r = root ? document.getElementById(root) : document.querySelector("section.scanconv");
  const cur = r.querySelectorAll("tr.sc-cur");
  const on = [...r.querySelectorAll("svg.sc-stepgrid rect.sc-px.on")];
  const pick = (els) => els.map(e => [+e.getAttribute("data-x"), +e.getAttribute("data-y")]);
  return {
    pos: +r.getAttribute("data-pos"),
    rows: [...cur].map(t => +t.getAttribute("data-pos")),
    lit: pick(on),
    mirror: pick(on.filter(e => e.classList.contains("sc-m"))),
    region2: pick(on.filter(e => e.classList.contains("sc-r2"))),
    fresh: pick([...r.querySelectorAll("svg.sc-stepgrid rect.sc-px.sc-new")]),
    caption: r.querySelector(".sc-caption").textContent,
    slider: +r.querySelector(".sc-slider").value,
  };
}"""


_TABS: dict[int, list[Any]] = {}
"""The browser's open tabs that no test is using (by browser): a test takes one and loads its
page into it. A new tab is a new renderer process (0.6 s of CPU) before its page loads
(0.4 s); a page loaded into a used tab starts as fresh (a new document: no script, timer or
listener of the one before; these pages keep nothing in storage)."""


def take_tab(browser: Any, width: int = 1400) -> Any:
    """A tab of ``browser``, ``width`` × 900 px: a free one, or a new one."""
    free = _TABS.setdefault(id(browser), [])
    tab = free.pop() if free else browser.new_page()
    tab.set_viewport_size({"width": width, "height": 900})
    return tab


def give_back(tab: Any) -> None:
    """``tab`` free again, as a new one is: screen media, the pointer at the corner."""
    tab.emulate_media(media="null")
    tab.mouse.move(0, 0)
    _TABS[id(tab.context.browser)].append(tab)


class Opened:
    """A page open in the browser, with every request and console message it caused."""

    def __init__(self, browser: Any, path: Path, width: int = 1400) -> None:
        self.page = take_tab(browser, width)
        self.requests: list[str] = []
        self.errors: list[str] = []
        self._listeners = [
            ("request", lambda r: self.requests.append(r.url)),
            (
                "console",
                lambda m: self.errors.append(m.text) if m.type in ("error", "warning") else 0,
            ),
            ("pageerror", lambda e: self.errors.append(str(e))),
        ]
        for event, listener in self._listeners:
            self.page.on(event, listener)
        self.page.goto(path.as_uri())
        self.page.wait_for_selector("section.scanconv[data-ready]")

    def state(self, root: str | None = None) -> dict[str, Any]:
        return self.page.evaluate(STATE, root)

    def key(self, name: str, times: int = 1) -> None:
        for _ in range(times):
            self.page.keyboard.press(name)

    def close(self) -> None:
        """Check what every page must: no request off the machine, no console error."""
        for event, listener in self._listeners:
            self.page.remove_listener(event, listener)
        give_back(self.page)
        assert [u for u in self.requests if not u.startswith(LOCAL)] == []
        assert self.errors == []


@pytest.fixture
def opened(browser: Any, tmp_path: Path) -> Iterator[Any]:
    pages: list[Opened] = []

    def open_answer(*argv: str, width: int = 1400) -> tuple[Opened, dict[str, Any]]:
        target = tmp_path / f"answer{len(pages)}.html"
        r = run(*argv, "-o", str(target))
        assert r.code == 0, r.err
        answer = run(*argv, "--format", "json")
        assert answer.code == 0, answer.err
        page = Opened(browser, target, width)
        pages.append(page)
        return page, json.loads(answer.out)

    yield open_answer
    for page in pages:
        page.close()


def as_set(pixels: list[list[int]]) -> set[tuple[int, int]]:
    return {(x, y) for x, y in pixels}


def images(point: list[int], symmetry: int, center: tuple[int, int]) -> set[tuple[int, int]]:
    """The pixels a step's point plots, worked out here, apart from the program."""
    x, y = point
    xc, yc = center
    offsets = {(x, y)}
    if symmetry >= 4:
        offsets |= {(-x, y), (x, -y), (-x, -y)}
    if symmetry == 8:
        offsets |= {(y, x), (-y, x), (y, -x), (-y, -x)}
    return {(xc + a, yc + b) for a, b in offsets}


def expected_lit(
    answer: dict[str, Any], k: int, symmetry: int = 1, center: tuple[int, int] = (0, 0)
) -> set[tuple[int, int]]:
    """The JSON answer's first k steps, plus the pixels no step plots (a start pixel)."""
    plotted = as_set(answer["pixels"])
    stepped = [images(s["pixel"], symmetry, center) & plotted for s in answer["steps"]]
    never = plotted - set().union(*stepped)
    return never | set().union(*stepped[:k])


def check_every_step(page: Opened, answer: dict[str, Any], **mirror: Any) -> None:
    """Step forward with → through the whole answer and back with ←, checking each step."""
    n = len(answer["steps"])
    page.key("Home")
    before = page.state()["pos"]
    for k in [*range(n + 1), *range(n - 1, -1, -1)]:
        if before != k:
            page.key("ArrowRight" if before < k else "ArrowLeft")
        st = page.state()
        before = st["pos"]  # the page's own position, read once a step
        assert st["pos"] == st["slider"] == k
        assert st["rows"] == ([k] if k else [])
        assert as_set(st["lit"]) == expected_lit(answer, k, **mirror), k
        if k:
            assert f"k = {answer['steps'][k - 1]['k']}" in st["caption"]


OCTANTS = [(18, 13), (13, 18), (7, 18), (2, 13), (2, 7), (7, 2), (13, 2), (18, 7)]


@pytest.mark.parametrize("end", OCTANTS, ids=[f"to-{x}-{y}" for x, y in OCTANTS])
def test_a_line_in_every_octant_lights_the_first_k_steps(opened, end):
    page, answer = opened("line", "10", "10", str(end[0]), str(end[1]))
    check_every_step(page, answer)


def test_a_dda_line_steps_too(opened):
    page, answer = opened("line", "3", "9", "10", "2", "--algo", "dda")
    check_every_step(page, answer)


def test_a_circle_lights_each_point_and_its_8_images(opened):
    page, answer = opened("circle", "5", "--center", "1", "2")
    check_every_step(page, answer, symmetry=8, center=(1, 2))
    page.key("Home")
    for k, step in enumerate(answer["steps"], 1):
        page.key("ArrowRight")
        st = page.state()
        own = (1 + step["pixel"][0], 2 + step["pixel"][1])
        fresh = as_set(st["fresh"])
        assert fresh == images(step["pixel"], 8, (1, 2)) - expected_lit(answer, k - 1, 8, (1, 2))
        # The step's own point is drawn as such, its other new pixels as mirror images.
        assert {p for p in fresh if p in as_set(st["mirror"])} == fresh - {own}
    # The mirror images are painted lighter than the octant points.
    fills = page.page.evaluate(
        """() => {
          const r = document.querySelector("section.scanconv");
          const f = (sel) => getComputedStyle(r.querySelector(sel)).fill;
          return [f("rect.sc-px.on:not(.sc-m)"), f("rect.sc-px.on.sc-m")];
        }"""
    )
    assert fills[0] != fills[1]


def test_a_circle_of_radius_5_steps_through_its_5_octant_points(opened):
    """All 5 octant points, the 8 images lit in turn."""
    page, answer = opened("circle", "5")
    assert len(answer["steps"]) == 5
    page.key("Home")
    counts = []
    for _ in range(5):
        page.key("ArrowRight")
        counts.append(len(page.state()["lit"]))
    assert counts == sorted(counts) and counts[-1] == len(answer["pixels"])
    assert page.state()["pos"] == 5


def test_an_ellipse_shows_region_2_distinct(opened):
    page, answer = opened("ellipse", "8", "6")
    check_every_step(page, answer, symmetry=4, center=(0, 0))
    regions = [s["region"] for s in answer["steps"]]
    first_of_2 = regions.index(2) + 1
    page.key("Home")
    page.key("ArrowRight", first_of_2 - 1)
    assert page.state()["region2"] == []
    page.key("ArrowRight")
    st = page.state()
    assert st["region2"] and as_set(st["fresh"]) <= as_set(st["region2"])
    assert st["caption"].startswith("Region 2")
    fills = page.page.evaluate(
        """() => {
          const r = document.querySelector("section.scanconv");
          const f = (sel) => getComputedStyle(r.querySelector(sel)).fill;
          return [f("rect.sc-px.on:not(.sc-r2):not(.sc-m)"), f("rect.sc-px.on.sc-r2:not(.sc-m)")];
        }"""
    )
    assert fills[0] != fills[1]
    # The highlighted row is in the region 2 table.
    caption = page.page.evaluate(
        "() => document.querySelector('tr.sc-cur').closest('table').querySelector('caption')"
        ".textContent"
    )
    assert caption.startswith("Region 2")


def test_a_bezier_curve_lights_its_pixels_in_plotting_order(opened):
    page, answer = opened("bezier", "0", "0", "1", "2", "3", "3", "4", "0", "--samples", "8")
    pixels = [tuple(p) for p in answer["pixels"]]
    page.key("Home")
    assert page.state()["lit"] == []
    for k, step in enumerate(answer["steps"], 1):
        page.key("ArrowRight")
        st = page.state()
        through = pixels.index(tuple(step["pixel"]))
        assert as_set(st["lit"]) == set(pixels[: through + 1]), k
        assert st["rows"] == [k]


def test_buttons_slider_rows_play_and_keys(opened):
    page, answer = opened("line", "2", "2", "10", "6")
    n = len(answer["steps"])
    p = page.page
    p.click("button[data-act=end]")
    assert page.state()["pos"] == n
    p.click("button[data-act=prev]")
    assert page.state()["pos"] == n - 1
    p.click("button[data-act=reset]")
    assert page.state()["pos"] == 0
    p.click("button[data-act=next]")
    p.click("button[data-act=next]")
    assert page.state()["pos"] == 2
    p.fill(".sc-slider", "5")
    assert page.state()["pos"] == 5
    p.click("tr[data-pos='3']")
    st = page.state()
    assert st["pos"] == 3 and st["rows"] == [3]
    p.click("h2")  # the keyboard goes to the page, not a button
    page.key("End")
    assert page.state()["pos"] == n
    page.key("Home")
    assert page.state()["pos"] == 0
    page.key(" ")  # play ...
    p.wait_for_function(
        "() => +document.querySelector('section.scanconv').getAttribute('data-pos') >= 2"
    )
    assert p.get_attribute("button[data-act=play]", "aria-pressed") == "true"
    page.key(" ")  # ... and pause
    assert p.get_attribute("button[data-act=play]", "aria-pressed") == "false"
    stopped = page.state()["pos"]
    p.wait_for_timeout(900)
    assert page.state()["pos"] == stopped < n


def test_hovering_a_pixel_names_it_and_its_step(opened):
    page, answer = opened("line", "2", "2", "10", "6")
    page.key("End")
    x, y = answer["steps"][3]["pixel"]
    page.page.hover(f"svg.sc-stepgrid rect.sc-px[data-x='{x}'][data-y='{y}']")
    text = page.page.text_content(".sc-hover")
    assert text.startswith(f"({x}, {y}): plotted at step 4 (row k = {answer['steps'][3]['k']})")


def test_two_notebook_answers_do_not_interfere(browser, tmp_path):
    import scanconv

    line, circle = scanconv.line(2, 2, 10, 6), scanconv.circle(5)
    cells = [line._repr_html_(), circle._repr_html_()]
    target = tmp_path / "notebook.html"
    target.write_text(
        "<!DOCTYPE html><html><head><meta charset='utf-8'></head><body>"
        + "".join(f"<div class='cell'>{c}</div>" for c in cells)
        + "</body></html>",
        encoding="utf-8",
    )
    page = Opened(browser, target)
    ids = page.page.evaluate(
        "() => [...document.querySelectorAll('section.scanconv')].map(s => s.id)"
    )
    assert (
        len(ids) == 2
        and page.page.evaluate(
            "() => document.querySelectorAll('section.scanconv[data-ready]').length"
        )
        == 2
    )
    first, second = ids
    # A notebook answer is written at its last step: every pixel lit, even with no script.
    n_line, n_circle = len(line.rows()), len(circle.rows())
    assert page.state(first)["pos"] == n_line and page.state(second)["pos"] == n_circle
    assert as_set(page.state(second)["lit"]) == set(circle.pixels())
    page.page.click(f"#{first} h2")
    page.page.focus(f"#{first}")
    page.key("Home")
    page.key("ArrowRight", 3)
    assert page.state(first)["pos"] == 3 and page.state(second)["pos"] == n_circle
    page.page.click(f"#{second} button[data-act=reset]")
    assert page.state(second)["pos"] == 0 and page.state(first)["pos"] == 3
    page.page.evaluate("() => document.activeElement.blur()")  # focus in neither: keys do nothing
    page.key("End")
    assert page.state(first)["pos"] == 3 and page.state(second)["pos"] == 0
    page.close()


def test_printing_gives_the_plain_answer(opened):
    page, answer = opened("circle", "5")
    page.key("Home")
    page.page.emulate_media(media="print")
    shown = page.page.evaluate(
        """() => {
          const r = document.querySelector("section.scanconv");
          const rects = [...r.querySelectorAll("svg.sc-stepgrid rect.sc-px")];
          return {
            controls: getComputedStyle(r.querySelector(".sc-controls")).display,
            unfilled: rects.filter(e => getComputedStyle(e).fill === "none").length,
            rects: rects.length,
          };
        }"""
    )
    assert shown == {"controls": "none", "unfilled": 0, "rects": len(answer["pixels"])}


def test_math_is_set_in_a_math_font(opened):
    fonts = subprocess.run(["fc-list", ":", "family"], capture_output=True, text=True).stdout
    if "Latin Modern Math" not in fonts:
        pytest.skip("no Latin Modern Math font (Debian: fonts-lmodern; .ci/run installs it)")
    page, _ = opened("line", "2", "2", "10", "6")
    cdp = page.page.context.new_cdp_session(page.page)
    cdp.send("DOM.enable")
    cdp.send("CSS.enable")
    root = cdp.send("DOM.getDocument")["root"]["nodeId"]
    node = cdp.send("DOM.querySelector", {"nodeId": root, "selector": ".sc-working math mi"})
    used = cdp.send("CSS.getPlatformFontsForNode", {"nodeId": node["nodeId"]})["fonts"]
    cdp.detach()
    # Chromium 150's CSS domain re-reads the page's own file for the inspector and logs the
    # read as a console error ("Unsafe attempt to load URL <page> from frame with URL <page>");
    # the inspector's read of the page itself is dropped, any other message still fails.
    url = page.page.url
    own = f"Unsafe attempt to load URL {url} from frame with URL {url}."
    page.errors[:] = [e for e in page.errors if not e.startswith(own)]
    assert [f["familyName"] for f in used] == ["Latin Modern Math"]


def test_a_large_circle_opens_and_steps(opened):
    page, answer = opened("circle", "1000")  # how long it takes: benchmarks/bench_html.py
    page.key("End")
    st = page.state()
    assert st["pos"] == len(answer["steps"]) and len(st["lit"]) == len(answer["pixels"])
    page.key("Home")
    assert page.state()["lit"] == []


def test_a_comparison_steps_its_methods_together(opened):
    page, answer = opened("compare", "circle", "5")
    rows = answer["tables"][0]["rows"]
    page.key("Home")
    for k in range(1, len(rows) + 1):
        page.key("ArrowRight")
        st = page.page.evaluate(
            """() => {
              const r = document.querySelector("section.scanconv");
              const cur = r.querySelector("tr.sc-cur");
              return [+r.getAttribute("data-pos"), [...cur.cells].map(c => c.textContent),
                      r.querySelector(".sc-caption").textContent];
            }"""
        )
        assert st[0] == k
        assert st[1][0] == str(rows[k - 1][0])  # the row of x = x_k, every method in it
        assert st[2].startswith(f"Row {k}: x = {rows[k - 1][0]};")


def test_a_page_of_several_answers_steps_the_one_last_clicked(browser, tmp_path):
    """What ``scanconv sheet --format html`` builds on: several answers, one page, one keyboard."""
    from scanconv.answers.primitives.line import line_solution
    from scanconv.render.mappings.html import html_document

    target = tmp_path / "key.html"
    answers = [
        ("Question 1", line_solution("dda", 0, 0, 4, 2)),
        ("Question 2", line_solution("bresenham", 2, 2, 10, 6)),
    ]
    target.write_text(html_document(answers, "Answer key"), encoding="utf-8")
    page = Opened(browser, target)
    page.key("ArrowRight", 2)  # nothing clicked yet: the first answer
    assert page.state("sc1")["pos"] == 2 and page.state("sc2")["pos"] == 0
    page.page.click("#sc2 h3")
    page.key("End")
    n = len(list(answers[1][1].steps()))
    assert page.state("sc1")["pos"] == 2 and page.state("sc2")["pos"] == n
    page.page.click("#sc1 tr[data-pos='4']")
    page.key("ArrowLeft")
    assert page.state("sc1")["pos"] == 3 and page.state("sc2")["pos"] == n
    page.close()
