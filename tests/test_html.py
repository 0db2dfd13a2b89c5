"""The ``html`` format without a browser: the page's structure, its data against the JSON
answer, escaping, no network reference, every command's page, files, and the notebook repr.

What a person sees (stepping, keys, clicks, console errors, network) is tested in a real
Chromium by ``tests/test_browser.py``.
"""

from __future__ import annotations

import json
import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

from scanconv.core.records import Column, Plot, Quantity, Solution, Step, Table, Walk
from scanconv.render import Format, Options, render
from scanconv.render.html import stepper
from scanconv.render.html.page_assets import CSS, JS
from scanconv.render.mappings import html as htmlmod

from .cli_vocabulary import VOCABULARY, annotation, commands, options
from .helpers import assert_refused, run

NAMESPACES = {"http://www.w3.org/1998/Math/MathML", "http://www.w3.org/2000/svg"}
VOID = {"meta", "input", "br", "img", "link", "hr", "col", "wbr", "area", "source"}


class Page(HTMLParser):
    """The elements of a page: tags in order, attributes, script bodies, balance."""

    def __init__(self, text: str) -> None:
        super().__init__(convert_charrefs=True)
        self.tags: list[str] = []
        self.attrs: list[dict[str, str | None]] = []
        self.scripts: list[tuple[dict[str, str | None], str]] = []
        self.stack: list[str] = []
        self._script: dict[str, str | None] | None = None
        self.text: list[str] = []
        self.feed(text)
        self.close()

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append(tag)
        self.attrs.append(dict(attrs))
        if tag == "script":
            self._script = dict(attrs)
        if tag not in VOID:
            self.stack.append(tag)

    def handle_startendtag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append(tag)
        self.attrs.append(dict(attrs))

    def handle_endtag(self, tag: str) -> None:
        assert self.stack and self.stack[-1] == tag, (tag, self.stack[-5:])
        self.stack.pop()

    def handle_data(self, data: str) -> None:
        if self._script is not None:
            self.scripts.append((self._script, data))
            self._script = None
        else:
            self.text.append(data)

    def elements(self, tag: str, cls: str | None = None) -> list[dict[str, str | None]]:
        return [
            a
            for t, a in zip(self.tags, self.attrs, strict=True)
            if t == tag and (cls is None or cls in (a.get("class") or "").split())
        ]


def page_of(*argv: str) -> str:
    r = run(*argv, "--format", "html")
    assert r.code == 0, r.err
    return r.out


def data_of(page: str) -> dict:
    found = re.findall(r'<script type="application/json" class="sc-data">(.*?)</script>', page)
    assert len(found) == 1
    return json.loads(found[0])


def json_answer(*argv: str) -> dict:
    r = run(*argv, "--format", "json")
    assert r.code == 0, r.err
    return json.loads(r.out)


# --- structure --------------------------------------------------------------------------------


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_line_page_holds_the_answer_and_its_steps():
    page = page_of("line", "2", "2", "10", "6")
    answer = json_answer("line", "2", "2", "10", "6")
    assert page.startswith("<!DOCTYPE html>\n") and page.endswith("</html>\n")
    doc = Page(page)
    assert doc.stack == []
    assert len(doc.elements("section", "scanconv")) == 1
    data = data_of(page)
    steps = answer["steps"]
    assert data["n"] == len(steps) >= 8
    assert len(data["captions"]) == len(data["heads"]) == len(steps) + 1
    # The rows are the JSON answer's steps, each with its position.
    rows = [a for a in doc.elements("tr") if "data-pos" in a]
    assert [int(a["data-pos"] or 0) for a in rows] == list(range(1, len(steps) + 1))
    # The pixels drawn are the JSON answer's, in plotting order, with the step that lights each
    # (a pixel no row plots, Bresenham's start in a table of (x_{k+1}, y_{k+1}), at the start).
    rects = doc.elements("rect", "sc-px")
    assert [[int(a["data-x"] or 0), int(a["data-y"] or 0)] for a in rects] == answer["pixels"]
    assert [int(a["data-i"] or 0) for a in rects] == list(range(len(rects)))
    lit_by: dict[tuple[int, int], int] = {}
    for k, s in enumerate(steps, 1):
        lit_by.setdefault(tuple(s["pixel"]), k)
    assert data["pos"] == [lit_by.get((x, y), 0) for x, y in answer["pixels"]]
    # The caption of each step gives its decision with the numbers.
    sub = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
    for k, s in enumerate(steps, 1):
        caption = data["captions"][k]
        assert caption.startswith(f"Row k = {s['k']}: ")
        x, y = s["pixel"]
        assert f"plot ({x}, {y})" in caption
        if s["decision"]:
            sign = " < 0" if s["p"] < 0 else " > 0" if s["p"] > 0 else ""
            said = f"p{str(s['k']).translate(sub)} = {str(s['p']).replace('-', '−')}{sign}"
            assert f"{said}, so {s['decision']}" in caption, caption
    assert data["captions"][0].startswith("Start: ")
    # Working and headings are MathML; the controls are there.
    assert page.count("<math ") > 10 and 'mathvariant="normal">&#x00394;' in page
    acts = [a.get("data-act") for a in doc.elements("button") if "data-selftest" not in a]
    assert acts == ["reset", "prev", "play", "next", "end"]
    assert len(doc.elements("input", "sc-slider")) == 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_circle_lights_each_octant_point_and_its_images_together():
    answer = json_answer("circle", "5")
    data = data_of(page_of("circle", "5"))
    pixels = [tuple(p) for p in answer["pixels"]]
    assert data["n"] == len(answer["steps"]) == 5
    for k, step in enumerate(answer["steps"], 1):
        x, y = step["pixel"]
        images = {(x, y), (-x, y), (x, -y), (-x, -y), (y, x), (-y, x), (y, -x), (-y, -x)}
        mine = {pixels[i] for i, p in enumerate(data["pos"]) if p == k}
        earlier = {pixels[i] for i, p in enumerate(data["pos"]) if p < k}
        assert mine == images - earlier
        own = [data["kind"][i] for i, p in enumerate(data["pos"]) if p == k and pixels[i] == (x, y)]
        assert own in ([0], [])
    assert min(data["pos"]) == 1  # the circle's row 0 plots its own point: nothing at the start


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_ellipse_regions_are_told_apart_and_its_region_tables_step():
    page = page_of("ellipse", "8", "6")
    answer = json_answer("ellipse", "8", "6")
    doc = Page(page)
    data = data_of(page)
    regions = [s["region"] for s in answer["steps"]]
    rows = [a for a in doc.elements("tr") if "data-pos" in a]
    # No duplicate step table: the region tables' rows carry the positions.
    assert [int(a["data-pos"] or 0) for a in rows] == list(range(1, len(regions) + 1))
    assert [("sc-r2" in (a.get("class") or "")) for a in rows] == [r == 2 for r in regions]
    second = [a for a in doc.elements("rect", "sc-px") if "sc-r2" in (a["class"] or "")]
    first_of_2 = regions.index(2) + 1
    assert second
    assert min(data["pos"][int(a["data-i"] or 0)] for a in second) == first_of_2
    first = [a for a in doc.elements("rect", "sc-px") if "sc-r2" not in (a["class"] or "")]
    assert max(data["pos"][int(a["data-i"] or 0)] for a in first) < first_of_2
    assert "Region 2, row k = 0" in data["captions"][first_of_2]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_bezier_curve_steps_its_samples_and_draws_the_control_polygon():
    page = page_of("bezier", "0", "0", "1", "2", "3", "3", "4", "0", "--samples", "8")
    answer = json_answer("bezier", "0", "0", "1", "2", "3", "3", "4", "0", "--samples", "8")
    data = data_of(page)
    assert data["n"] == len(answer["steps"]) == 9
    pos = dict(zip(map(tuple, answer["pixels"]), data["pos"], strict=True))
    for k, step in enumerate(answer["steps"], 1):
        assert pos[tuple(step["pixel"])] <= k  # a sample's pixel is lit by its step at the latest
    assert sorted(data["pos"]) == data["pos"]  # plotting order is stepping order
    assert 'class="sc-control"' in page and page.count('class="sc-cpoint"') == 4


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_an_answer_without_steps_steps_its_pixels_and_one_without_pixels_has_no_stepper():
    argv = ("fill", "flood", "2", "0", "4", "2", "2", "4", "0", "2", "--seed", "2", "2")
    page = page_of(*argv)
    fill = data_of(page)
    assert fill["pos"] == list(range(1, fill["n"] + 1))
    # The trace's rows light with the pixel they take.
    trace = json_answer(*argv)["tables"][0]
    taken = [row[trace["columns"].index("pixel")] for row in trace["rows"]]
    rows = [a for a in Page(page).elements("tr") if "data-pos" in a]
    pixels = [f"({x}, {y})" for x, y in json_answer(*argv)["pixels"]]
    assert [taken.index(p) for p in pixels] == sorted(taken.index(p) for p in pixels)
    assert [int(a["data-pos"] or 0) for a in rows] == list(range(1, len(pixels) + 1))
    storage = page_of("storage", "1024", "768", "--levels", "256")
    assert 'class="sc-data"' not in storage and "data-stepper>" not in storage
    assert "<table" in storage


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_comparison_steps_through_its_methods_side_by_side():
    page = page_of("compare", "line", "2", "8", "10", "4")
    answer = json_answer("compare", "line", "2", "8", "10", "4")
    side = answer["tables"][0]
    data = data_of(page)
    assert data["n"] == len(side["rows"]) == 9 and data["pos"] == []
    rows = [a for a in Page(page).elements("tr") if "data-pos" in a]
    assert [int(a["data-pos"] or 0) for a in rows] == list(range(1, 10))
    # Each caption names every method's pixel in its row: x = 3 is the tie.
    assert data["captions"][2].startswith("Row 2: x = 3; ")
    assert "basic = 8; DDA = 8; Bresenham = 7; " in data["captions"][2]
    assert data["captions"][2].endswith("; differ = tie.")
    # The figure sits in the stepper, beside the table, not under the answer.
    stepper = page[page.index('<div class="sc-stepper">') : page.index('<div class="sc-controls"')]
    assert "<figure>" in stepper


@pytest.mark.parametrize(
    "argv",
    [("image", "ramp", "--size", "4", "--levels", "4"), ("compare", "line", "2", "8", "10", "4")],
)
def test_figures_are_drawn(argv):
    doc = Page(page_of(*argv))
    figures = doc.elements("figure")
    assert figures and doc.elements("svg", "sc-grid")


# --- every command, every format option -------------------------------------------------------


def _html_commands() -> list[tuple[tuple[str, ...], tuple[str, ...]]]:
    found = []
    for path, command in commands():
        if path not in VOCABULARY:
            continue
        fmt = [p for p in options(command) if "--format" in p.opts]
        if not fmt or annotation(fmt[0]) is not Format:  # sheet, exam: their own formats
            continue
        for argv in VOCABULARY[path].valid:
            if "--format" not in argv:
                found.append((path, argv))
    return found


HTML_COMMANDS = _html_commands()


def test_the_answer_commands_offer_html():
    names = {" ".join(p) for p, _ in HTML_COMMANDS}
    assert {"line", "circle", "ellipse", "bezier", "fill flood", "sample", "compare line"} <= names


@pytest.mark.parametrize(("path", "argv"), HTML_COMMANDS, ids=lambda v: " ".join(v))
def test_every_command_produces_a_self_contained_page(path, argv):
    page = page_of(*path, *argv)
    doc = Page(page)
    assert doc.stack == [], doc.stack
    assert doc.tags[:3] == ["html", "head", "meta"]
    assert len(doc.elements("section", "scanconv")) == 1
    # No network, of any kind: no URL but the two XML namespace names, nothing loaded.
    assert set(re.findall(r"https?://[^\s\"'<>)]+", page)) <= NAMESPACES
    for tag, attrs in zip(doc.tags, doc.attrs, strict=True):
        assert not {"src", "href", "srcset", "action", "formaction"} & set(attrs), tag
        assert tag not in ("link", "iframe", "img", "object", "embed", "base", "form")
    assert "url(" not in page and "@import" not in page
    # Exactly the page's own scripts: the stepper (once) and its data (if it steps).
    scripts = [a for a in doc.elements("script") if a.get("class") != "sc-testdata"]  # selftest
    assert len(scripts) in (1, 2)
    assert [a.get("type") for a in scripts][:-1] in ([], ["application/json"])
    if len(scripts) == 2:
        data = data_of(page)
        assert len(data["captions"]) == data["n"] + 1
        assert len(data["pos"]) == len([a for a in doc.elements("rect", "sc-px") if "data-i" in a])


# --- escaping -----------------------------------------------------------------------------------

HOSTILE = "</script><script>alert(1)</script><img src=x onerror=alert(1)>&amp;"


def hostile_solution() -> Solution:
    cols = (Column("k", "k", "k"), Column("pixel", "pixel", r"\text{" + HOSTILE + "}"))
    return Solution(
        "line",
        "bresenham",
        HOSTILE,
        given=(Quantity("a", 1, HOSTILE, r"a = \text{" + HOSTILE + "}"),),
        derived=(Quantity("b", 2, HOSTILE, r"\text{" + HOSTILE + r"} < 2 \& 3"),),
        notes=(HOSTILE, f"${HOSTILE}$ and $x$"),
        walk=Walk(
            columns=cols,
            steps=lambda: iter([Step(0, None, None, (0, 0)), Step(1, None, None, (1, 1))]),
            tables=(Table(HOSTILE, (Column("w", HOSTILE, HOSTILE),), lambda: iter([(HOSTILE,)])),),
        ),
        plot=Plot(
            pixels=lambda: iter([(0, 0), (1, 1)]),
            bbox=(0, 0, 1, 1),
            marks_label=HOSTILE,
            outline=((0, 1),),
            outline_name=HOSTILE,
        ),
    )


def test_hostile_text_is_escaped_everywhere():
    page = "".join(c for c in render(hostile_solution(), Format.html) if isinstance(c, str))
    doc = Page(page)
    assert doc.stack == []
    assert "img" not in doc.tags
    assert len(doc.elements("script")) == 2  # the data and the stepper, nothing injected
    assert page.count("</script>") == 2
    assert "onerror" not in " ".join(str(v) for a in doc.attrs for v in a)
    assert HOSTILE in "".join(doc.text)  # shown as text, intact
    data = data_of(page)  # the JSON holds no "<" that could end its script
    assert "<" not in re.findall(r'class="sc-data">(.*?)</script>', page)[0]
    assert data["n"] == 2


def test_hostile_mathml_tags_and_attributes_are_escaped():
    out = htmlmod.tex_math(r'\text{<mi onclick="x">a</mi><script>}')
    doc = Page(out)
    assert "script" not in doc.tags
    assert all(set(a) <= {"xmlns", "display", "stretchy"} for a in doc.attrs), doc.attrs
    assert '<mi onclick="x">a</mi><script>' in "".join(doc.text).replace("\xa0", " ")


def test_json_data_cannot_close_its_script():
    text = htmlmod.json_script({"a": "</script><!-- <script>", "b": "&"})
    body = text[len('<script type="application/json" class="sc-data">') : -len("</script>")]
    assert "<" not in body and ">" not in body and "&" not in body
    assert json.loads(body) == {"a": "</script><!-- <script>", "b": "&"}


# --- large answers --------------------------------------------------------------------------------


def test_a_long_answer_is_capped_and_says_so(monkeypatch):
    monkeypatch.setattr(stepper, "MAX_STEPS", 10)
    monkeypatch.setattr(stepper, "MAX_TABLE_ROWS", 5)
    monkeypatch.setattr(htmlmod, "MAX_PIXEL_LIST", 7)
    r = run("line", "0", "0", "30", "7", "--format", "html")
    assert r.code == 0
    data = data_of(r.out)
    assert data["n"] == 10
    steps = len(json_answer("line", "0", "0", "30", "7")["steps"])
    assert f"The table shows the first 5 of {steps} rows" in r.out
    assert f"the stepper goes through the first 10 of {steps} steps" in r.out
    assert "(24 more)" in r.out  # 31 pixels, 7 listed
    assert f"stepper goes through the first 10 of {steps} steps" in r.err  # a notice too
    assert max(data["pos"]) == 10  # the later pixels light at the last step


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_page_for_a_large_circle_holds_every_step():
    """(How long it takes to build is measured by benchmarks/bench_html.py, not asserted.)"""
    page = page_of("circle", "1000")
    assert data_of(page)["n"] == len(json_answer("circle", "1000")["steps"])


# --- files and bad input --------------------------------------------------------------------------


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_output_html_file_takes_its_format_from_the_name(tmp_path: Path):
    for name in ("a.html", "b.HTM"):
        r = run("line", "2", "2", "10", "6", "-o", str(tmp_path / name))
        assert r.code == 0 and r.out == ""
        assert (tmp_path / name).read_text(encoding="utf-8").startswith("<!DOCTYPE html>")


def test_html_against_a_file_of_another_format_is_refused(tmp_path: Path):
    for name, fmt in (("a.tex", "html"), ("a.html", "markdown"), ("a.json", "html")):
        r = run("line", "2", "2", "10", "6", "--format", fmt, "-o", str(tmp_path / name))
        assert_refused(r, "by its extension")
        assert not (tmp_path / name).exists()


def test_bad_input_writes_no_page(tmp_path: Path):
    r = run("line", "2", "2", "1e10", "6", "-o", str(tmp_path / "x.html"))
    assert_refused(r, "out of range")
    assert list(tmp_path.iterdir()) == []


# --- notebook --------------------------------------------------------------------------------------


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_notebook_repr_is_a_scoped_stepper_with_a_unique_id():
    import scanconv

    a, b = scanconv.line(2, 2, 10, 6), scanconv.circle(5)
    first, second, again = a._repr_html_(), b._repr_html_(), a._repr_html_()
    ids = [re.findall(r'<section class="scanconv" id="([^"]+)"', t) for t in (first, second, again)]
    assert all(len(i) == 1 for i in ids)
    assert len({i[0] for i in ids}) == 3  # even the same answer shown twice
    for text in (first, second):
        doc = Page(text)
        assert doc.stack == []
        assert doc.tags[0] == "div" and "html" not in doc.tags and "body" not in doc.tags
        (section,) = doc.elements("section", "scanconv")
        assert section["data-keys"] == "root"  # keys only while the answer has the focus
        # Written at its last step: an untrusted notebook (no script) shows the whole answer.
        rects = [a for a in doc.elements("rect", "sc-px") if "data-i" in a]
        assert rects and all("on" in (a["class"] or "").split() for a in rects)
        assert section["data-pos"] == str(data_of(text)["n"])
    assert data_of(first)["n"] == len(a.rows()) and data_of(second)["n"] == len(b.rows())


def test_the_style_is_scoped_and_the_script_finds_elements_inside_each_answer():
    body = re.sub(r"@media[^{]*\{", "", CSS)
    selectors = [
        s.strip() for rule in body.split("}") if "{" in rule for s in rule.split("{")[0].split(",")
    ]
    assert selectors and all(s.startswith(".scanconv") for s in selectors), [
        s for s in selectors if not s.startswith(".scanconv")
    ]
    assert "getElementById" not in JS
    # Elements are looked up from the answer's root; the document only to find the roots.
    lookups = re.findall(r"(\w+)\.querySelector(?:All)?\(", JS)
    assert set(lookups) <= {"root", "document"}
    # the roots: those with a stepper (the stepper, test yourself), every answer (the cue on a
    # working formula cut at its box's edge)
    assert re.findall(r"document\.querySelectorAll\(([^)]*)\)", JS) == [
        '".scanconv[data-stepper]"',
        '".scanconv"',
    ]


def test_print_gives_the_plain_answer():
    printing = CSS[CSS.index("@media print") :]
    assert ".sc-controls" in printing and "display:none" in printing
    assert ".sc-scroll{max-height:none" in printing  # the whole table
    assert "sc-px:not(.on){fill:var(--sc-px)!important" in printing  # every pixel


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_options_reach_the_page():
    from scanconv.answers.primitives.line import line_solution

    sol = line_solution("dda", 0, 0, 3, 1)
    exact = "".join(c for c in render(sol, Format.html, Options(exact=True)) if isinstance(c, str))
    assert "<td>1/3</td>" in exact or '<td class="sc-num">1/3</td>' in exact
    top = "".join(
        c for c in render(sol, Format.html, Options(origin="top-left")) if isinstance(c, str)
    )
    assert "y \u2193" in top


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize(
    "args",
    [
        ("antialias", "line", "0", "0", "9", "4"),
        ("antialias", "circle", "4", "--levels", "4"),
        ("line", "0", "0", "7", "3", "--algo", "wu"),
    ],
)
def test_anti_aliased_pages_draw_each_pixel_in_its_grey(args):
    """The page shows intensities as grey levels, the level the JSON answer gives."""
    from scanconv.render.figures.figure import grey_of

    data = json.loads(run(*args, "--format", "json").out)
    levels: dict[tuple[int, int], int] = {}
    for table in data.get("tables") or []:
        cols = table["columns"]
        for row in table["rows"]:
            levels[tuple(row[cols.index("pixel")])] = row[cols.index("level")]
    for step in data.get("steps") or []:
        a, b = step["levels"]
        levels[tuple(step["pixel_a"])] = a
        levels[tuple(step["pixel_b"])] = max(levels.get(tuple(step["pixel_b"]), 0), b)
    page = Page(run(*args, "--format", "html").out)
    cells = {
        (int(a["data-x"] or 0), int(a["data-y"] or 0)): a.get("style")
        for a in page.attrs
        if "data-x" in a and "data-i" in a
    }
    assert set(cells) == {tuple(p) for p in data["pixels"]}
    for pixel, style in cells.items():
        assert style == f"fill:{grey_of(levels[pixel], data['given']['L'])}", pixel


@pytest.mark.parametrize(
    "argv",
    [
        ("bezier", "0", "0", "1", "2", "999999999", "999999999", "1000000", "0", "--at", "1/2"),
        (
            "bezier",
            "-1000000000",
            "-1000000000",
            "1000000000",
            "1000000000",
            "-1000000000",
            "1000000000",
            "--at",
            "1/2",
        ),
        (
            "bspline",
            "0",
            "0",
            "1",
            "2",
            "999999999",
            "999999999",
            "1000000",
            "0",
            "5",
            "5",
            "--degree",
            "2",
            "--at",
            "1/2",
        ),
        ("line", "0", "0", "9999", "1"),
    ],
    ids=["bezier-wide", "bezier-2e9", "bspline-wide", "line-long"],
)
def test_a_page_over_a_huge_extent_stays_a_page(argv):
    """A control polygon 10^9 pixels across (attack report N5: a 200 MB page of 520,004 axis
    labels) gives a grid as wide as the page with a few dozen labels on each axis."""
    r = run(*argv, "-f", "html")
    assert r.code == 0, r.err
    svg = re.search(r'<svg class="sc-grid sc-stepgrid".*?</svg>', r.out, re.S)
    assert svg is not None
    size = re.search(r'width="([0-9.]+)" height="([0-9.]+)"', svg[0])
    assert size is not None and float(size[1]) < 800 and float(size[2]) < 800
    labels = re.findall(r'font-size="11" text-anchor="(?:middle|end)">(-?[0-9]+)<', svg[0])
    assert 2 <= len(labels) <= 200
    assert len(r.out) < 3_000_000


def test_a_questions_wording_and_command_are_escaped():
    from scanconv.document.blocks import Question
    from scanconv.render.mappings.html import question_html

    q = Question(2, 3, wording="Is p < 0 & x > y?", command="scanconv sheet '<q>.txt'")
    assert question_html(q) == (
        '<h2 class="sc-q">Question 2 (3 marks)</h2>\n'
        '<p class="sc-wording">Is p &lt; 0 &amp; x &gt; y?</p>\n'
        "<p><code>scanconv sheet &#x27;&lt;q&gt;.txt&#x27;</code></p>\n"
    )


@pytest.mark.parametrize("linked", [True, False])
def test_the_contents_escape_sections_and_wordings(linked):
    from scanconv.document.blocks import Contents, Entry
    from scanconv.render.mappings.html import contents_html

    block = Contents((Entry(1, "p < 0?", "Lines & <b>circles</b>"),), linked=linked)
    html = contents_html(block)
    assert "<li>Lines &amp; &lt;b&gt;circles&lt;/b&gt;<ol>" in html
    wording = '<a href="#q1">p &lt; 0?</a>' if linked else "p &lt; 0?"
    assert f'<li value="1">{wording}</li>' in html
    assert "<b>" not in html


def test_an_answer_sections_id_and_keys_are_attribute_escaped():
    from scanconv.answers.primitives.line import line_solution
    from scanconv.render.mappings.html import answer_section

    html = answer_section(line_solution("dda", 2, 2, 4, 3), 'a"b<c', keys='p"q')
    assert html.startswith('<section class="scanconv" id="a&quot;b&lt;c" data-keys="p&quot;q"')
