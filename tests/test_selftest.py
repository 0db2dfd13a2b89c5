"""The "Test yourself" data of the HTML page, without a browser.

The script interprets a descriptor (rules and rows, :mod:`scanconv.render.html.selftest`); here the
descriptor is applied by a small interpreter written in the test, apart from the program, and
must give back the step table the page prints: the parameter, the decision and the next pixel
of every row, in every layout, octant and convention these methods have. Pages whose method
has no rule get no button. ``tests/test_selftest_browser.py`` drives the script itself.
"""

from __future__ import annotations

import itertools
import json
import re
from fractions import Fraction
from typing import Any

import pytest

from scanconv.answers.primitives import circle, ellipse, line
from scanconv.core.records import Solution
from scanconv.document import StepTable, document
from scanconv.render import Options
from scanconv.render.html.selftest import selftest_data
from scanconv.render.html.stepper import stepping
from scanconv.render.mappings.html import answer_section, html_document, notebook_html

from .helpers import run


def line_solution(*args: Any, **knobs: Any) -> Solution:
    """As the CLI and the API answer: with the conventions recorded (``annotate``), which the
    marking model reads (without them the page offers no test: see the last test)."""
    return line.line_solution(*args, annotate=True, **knobs)


def circle_solution(*args: Any, **knobs: Any) -> Solution:
    return circle.circle_solution(*args, annotate=True, **knobs)


def ellipse_solution(*args: Any, **knobs: Any) -> Solution:
    return ellipse.ellipse_solution(*args, annotate=True, **knobs)


BUTTON = 'class="sc-testbtn"'
DATA = re.compile(r'<script type="application/json" class="sc-testdata">(.*?)</script>', re.S)


def descriptor(solution: Solution, options: Options | None = None) -> dict[str, Any] | None:
    doc = document(solution)
    return selftest_data(doc.get(StepTable), stepping(doc, options), options)


def rounded(v: Fraction, how: str) -> int:
    """The five roundings, written here from their definitions."""
    if how == "trunc":
        return int(v)
    if how == "c-cast":
        return int(v + Fraction(1, 2))
    if how == "half-even":
        return round(v)
    if how == "half-away":
        return -((-v + Fraction(1, 2)).__floor__()) if v < 0 else (v + Fraction(1, 2)).__floor__()
    assert how == "half-up"
    return (v + Fraction(1, 2)).__floor__()


def interpret(data: dict[str, Any], row: dict[str, Any]) -> tuple[str | None, list[int]]:
    """What the page's script does with a row: the decision for p_k's sign and the next
    pixel (the DDA: no decision, the pixel the rounding of the exact values gives)."""
    if data["kind"] == "dda":
        x, y = (Fraction(v) for v in row["nxy"])
        return None, [rounded(x, data["rounding"]), rounded(y, data["rounding"])]
    rule = data["rules"][row["rule"]]
    if row["p"] is None:
        (move,) = rule["moves"]
    else:
        p = Fraction(row["p"])
        move = rule["neg" if p < 0 else "zero" if p == 0 else "pos"]
    dx, dy = rule["moves"][move]
    return move, [row["at"][0] + dx, row["at"][1] + dy]


def table_steps(solution: Solution) -> list[tuple[Any, Any, Any]]:
    """The table's steps as the page prints them: (p_k, decision, next pixel), read from the
    step records: in the textbooks' layout (the pixel column is headed (x_{k+1}, y_{k+1})) row
    k holds the pixel the step reaches, in the notes' layout row k + 1 does."""
    records = list(solution.steps())
    heads = [c.tex for c in solution.columns if c.key == "pixel"]
    if heads and "k+1" in heads[0]:
        return [(r.p, r.decision, r.pixel) for r in records]
    return [(r.p, r.decision, n.pixel) for r, n in itertools.pairwise(records)]


def check_reproduces(solution: Solution, options: Options | None = None) -> dict[str, Any]:
    data = descriptor(solution, options)
    steps = table_steps(solution)
    if not steps:  # one row, no step (r = 1 with d0 = 3 - 2r): nothing to ask
        assert data is None
        return {}
    assert data is not None, solution.title
    assert len(data["rows"]) == len(steps) > 0
    previous = None
    for row, (p, decision, pixel) in zip(data["rows"], steps, strict=True):
        move, to = interpret(data, row)
        assert to == list(pixel) == row["to"], (solution.title, row)
        if data["kind"] == "dda":
            assert row["p"] is None
        else:
            assert (row["p"] is None) == (p is None)
            if p is not None:
                assert Fraction(row["p"]) == p
            if decision is not None:
                assert move == decision.value == row["d"]
        if previous is not None:  # each step starts where the one before went
            assert row["at"] == previous["to"]
            assert row["lit"] == previous["lit"] + 1 and row["row"] == previous["row"] + 1
        previous = row
    return data


OCTANTS = [(2, 2, 10, 6), (2, 2, 6, 10), (10, 6, 2, 2), (6, 10, 2, 2), (2, 6, 10, 2),
           (2, 10, 6, 2), (10, 2, 2, 6), (6, 2, 2, 10), (0, 0, 7, 0), (0, 0, 0, -5), (1, 1, 6, 6)]  # fmt: skip


@pytest.mark.parametrize("ends", OCTANTS)
@pytest.mark.parametrize("algo", ["bresenham", "midpoint"])
def test_the_line_rules_give_back_the_table_in_every_octant(algo, ends):
    data = check_reproduces(line_solution(algo, *ends))
    assert data["kind"] == "decide" and len(data["rules"]) == 1
    assert set(data["rules"][0]["moves"]) == set(data["rules"][0][s] for s in ("neg", "pos"))


@pytest.mark.parametrize("knobs", [{}, {"tie": "keep"}, {"start": "given"}, {"layout": "textbook"}])
def test_the_bresenham_rule_follows_the_conventions(knobs):
    data = check_reproduces(line_solution("bresenham", 2, 2, 10, 6, **knobs))
    rule = data["rules"][0]
    assert rule["neg"] == "E" and rule["pos"] == "NE"
    assert rule["zero"] == ("E" if knobs.get("tie") == "keep" else "NE")


@pytest.mark.parametrize("rounding", ["half-up", "trunc", "half-even", "c-cast", "half-away"])
@pytest.mark.parametrize("ends", [(0, 0, 5, 3), (Fraction(1, 2), 0, -4, 7), (3, -2, -5, 2)])
def test_the_dda_rounding_gives_back_the_pixels(ends, rounding):
    data = check_reproduces(line_solution("dda", *ends, rounding=rounding))
    assert data["kind"] == "dda" and data["rounding"] == rounding and data["rules"] == []


@pytest.mark.parametrize(
    "method, knobs",
    [
        ("midpoint", {}),
        ("midpoint", {"p0": "5/4-r"}),
        ("midpoint", {"tie": "keep", "loop": "inclusive"}),
        ("midpoint", {"layout": "notes"}),
        ("bresenham", {}),
        ("bresenham", {"xstep": "first", "tie": "keep"}),
        ("general", {}),
    ],
)
@pytest.mark.parametrize("r", [1, 5, 10, 17])
def test_the_circle_rules_give_back_the_table(method, knobs, r):
    data = check_reproduces(circle_solution(method, r, **knobs))
    if not data:
        return
    rule = data["rules"][0]
    assert (rule["neg"], rule["pos"]) == ("E", "SE")
    assert rule["moves"] == {"E": [1, 0], "SE": [1, -1]}


def test_a_circle_off_the_origin_keeps_its_octant_points_and_names_its_centre():
    data = check_reproduces(circle_solution("midpoint", 5, 3, -2, layout="notes"))
    assert data["centre"] == [3, -2] and data["rows"][0]["at"] == [0, 5]


@pytest.mark.parametrize(
    "axes, knobs",
    [((8, 6), {}), ((6, 8), {}), ((8, 2), {}), ((12, 1), {}), ((5, 3), {"p0": "rounded"}),
     ((8, 6), {"tie": "keep"}), ((7, 7), {"loop": "inclusive"}), ((1, 9), {})],
)  # fmt: skip
def test_the_ellipse_rules_give_back_both_regions(axes, knobs):
    data = check_reproduces(ellipse_solution(*axes, **knobs))
    names = {r["name"].rstrip("₀₁₂₃₄₅₆₇₈₉") for r in data["rows"]}
    assert names <= {"p1", "p2", "p"}
    regions = {r["reg"] for r in data["rows"]}
    assert regions <= {1, 2}
    for rule in data["rules"]:
        if set(rule["moves"]) == {"S", "SE"}:  # region 2: p2 > 0 steps down alone
            assert rule["pos"] == "S" and rule["neg"] == "SE"


def test_the_explained_numbers_are_the_tables():
    data = descriptor(line_solution("bresenham", 2, 2, 10, 6))
    row = data["rows"][3]
    assert (row["name"], row["p"], row["pt"], row["d"], row["at"], row["to"]) == (
        "p₃", "-8", "-8", "E", [5, 4], [6, 4],
    )  # fmt: skip
    circle = descriptor(circle_solution("bresenham", 5))
    assert circle["rows"][0]["name"] == "d₀"
    assert descriptor(line_solution("midpoint", 2, 2, 10, 6))["rows"][1]["name"] == "d₁"
    dda = descriptor(line_solution("dda", 0, 0, 5, 3))
    assert dda["rows"][1]["nxy"] == ["2", "6/5"] and dda["rows"][1]["nxyt"] == ["2.000", "1.200"]


def test_the_next_parameter_column_is_named_so_the_page_can_hide_it():
    s = line_solution("bresenham", 2, 2, 10, 6, layout="notes")
    keys = [c.key for c in s.columns]
    assert descriptor(s)["next"] == keys.index("p_next")
    assert descriptor(circle_solution("midpoint", 5))["next"] is None


# --- the page ---------------------------------------------------------------------------------


def page_data(*argv: str) -> tuple[str, dict[str, Any] | None]:
    r = run(*argv, "--format", "html")
    assert r.code == 0, r.err
    found = DATA.findall(r.out)
    assert len(found) <= 1
    return r.out, json.loads(found[0]) if found else None


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize(
    "argv",
    [
        ("line", "2", "2", "10", "6"),
        ("line", "2", "2", "10", "6", "--algo", "dda"),
        ("line", "2", "2", "10", "6", "--algo", "midpoint"),
        ("circle", "5"),
        ("circle", "5", "-m", "bresenham"),
        ("circle", "5", "-m", "general"),
        ("ellipse", "8", "6"),
    ],
)
def test_a_page_with_a_rule_has_the_button_and_its_rows_are_on_the_page(argv):
    page, data = page_data(*argv)
    assert data is not None and page.count(BUTTON) == 1
    assert ">Test yourself</button>" in page
    positions = {int(p) for p in re.findall(r'<tr data-pos="(\d+)"', page)}
    positions |= {int(p) for p in re.findall(r'<tr data-pos="(\d+)" class=', page)}
    for row in data["rows"]:
        assert row["row"] in positions  # the row the question hides and then reveals


@pytest.mark.parametrize(
    "argv",
    [
        ("line", "2", "2", "10", "6", "--algo", "basic"),
        ("circle", "5", "-m", "trig"),
        ("circle", "5", "-m", "polynomial"),
        ("circle", "5", "-m", "symmetric-dda"),
        ("line", "2", "2", "10", "6", "--algo", "wu"),
        ("polygon", "2", "3", "7", "1", "13", "5", "13", "11", "7", "7", "2", "9"),
        ("fill", "flood", "--rows", "#####/#...#/#.x.#/#####", "--seed", "1", "1"),
        ("bezier", "0", "0", "1", "2", "3", "3", "4", "0", "--samples", "8"),
    ],
)
def test_a_page_without_a_rule_has_no_button(argv):
    r = run(*argv, "--format", "html")
    if r.code != 0:
        pytest.fail(f"{argv}: {r.err}")
    assert BUTTON not in r.out
    assert DATA.findall(r.out) == []


def test_the_data_block_cannot_close_its_script():
    s = line_solution("bresenham", 2, 2, 10, 6)
    section = answer_section(s, "sc1")
    (body,) = DATA.findall(section)
    assert "<" not in body and ">" not in body and "&" not in body
    assert json.loads(body) == descriptor(s)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_every_answer_of_a_document_and_a_notebook_answer_get_their_own_test():
    doc = html_document(
        [("Q1", line_solution("bresenham", 0, 0, 5, 2)), ("Q2", circle_solution("trig", 4)),
         ("Q3", circle_solution("midpoint", 4))], "Key",
    )  # fmt: skip
    assert doc.count(BUTTON) == 2 and len(DATA.findall(doc)) == 2
    assert BUTTON in notebook_html(ellipse_solution(5, 3))


def test_an_answer_whose_table_is_not_the_models_gets_no_test():
    # the answer keeps its question, so an answer without its conventions in the JSON (no
    # annotate) is still tested by its own rule: tie = keep, p = 0 keeps y (E)
    bare = line.line_solution("bresenham", 2, 2, 10, 6, tie="keep")
    own = descriptor(bare)
    assert own is not None and own["rules"][0]["zero"] == "E"
    # a question that is not the table's (tie = step against a tie = keep table): the model
    # would not give this table, so the page offers no test rather than a wrong rule
    q = bare.question
    bare.question = q._replace(knobs=q.knobs._replace(tie="step"))
    assert descriptor(bare) is None
    assert BUTTON not in answer_section(bare, "sc1")


ARGV = {
    "line": lambda name: ("line", "2", "2", "10", "6", "--algo", name),
    "circle": lambda name: ("circle", "5", "-m", name),
    "ellipse": lambda name: ("ellipse", "8", "6"),
}


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_every_method_with_a_marking_model_has_the_test_and_no_other_of_its_command():
    from scanconv.answers.methods import METHODS

    with_model = set()
    for record in METHODS.values():
        # a walk's model (a pixel from a decision on p); a table's own model (clipping,
        # dithering, ...: scanconv.marking.table_models) marks columns, not steps to test
        walk = (record.model or "").startswith("scanconv.marking.models:")
        if record.command not in ARGV:
            assert not walk, record.key  # a new model: give it a page here
            continue
        _, data = page_data(*ARGV[record.command](record.name))
        assert (data is not None) == walk, record.key
        if walk:
            with_model.add(record.key)
    assert with_model == {
        "line/dda", "line/bresenham", "line/midpoint", "line/symmetric-dda", "circle/midpoint",
        "circle/bresenham", "circle/general", "ellipse/midpoint",
    }  # fmt: skip
