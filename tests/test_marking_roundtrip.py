"""Round trip: every step table scanconv writes, in csv, markdown, json and plain,
gets full marks from ``check`` against its own question, for every method and layout; every
CSV scanconv writes has unique column names. The marking runs in-process."""

from __future__ import annotations

import csv
import io
import shlex
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv import _api as api
from scanconv.core.checks import InputError
from scanconv.marking.mark import mark
from scanconv.marking.student_table import parse_text
from scanconv.render import Format, Options, render

from .helpers import run

GOLDEN = Path(__file__).resolve().parent.parent / "golden"


# --- 4. round trip: scanconv's own tables get full marks -----------------------------------------

FORMATS = {Format.csv: ".csv", Format.markdown: ".md", Format.json: ".json", Format.plain: ".txt"}


def _text(solution, fmt: Format) -> str:
    return "".join(c for c in render(solution, fmt, Options()) if isinstance(c, str))


_point = st.tuples(st.integers(-15, 15), st.integers(-15, 15))


@st.composite
def questions(draw):
    kind = draw(st.sampled_from(["line", "circle", "ellipse"]))
    layout = draw(st.sampled_from(["notes", "textbook"]))
    if kind == "line":
        a, b = draw(_point), draw(_point.filter(lambda p: True))
        if a == b:
            b = (b[0] + 1, b[1])
        algo = draw(st.sampled_from(["bresenham", "dda", "basic"]))
        return api.line(*a, *b, algo=algo, layout=layout)
    if kind == "circle":
        method = draw(
            st.sampled_from(
                ["midpoint", "bresenham", "general", "polynomial", "trig", "symmetric-dda"]
            )
        )
        r = draw(st.integers(2, 14))
        return api.circle(r, draw(_point), method=method, layout=layout)
    return api.ellipse(draw(st.integers(1, 10)), draw(st.integers(1, 10)))


@st.composite
def other_questions(draw):
    """The other commands with a step table (marked without follow-through)."""
    kind = draw(st.sampled_from(["wu", "bezier", "bspline", "parametric", "pipeline"]))
    a, b = draw(_point), draw(_point)
    if kind == "wu":
        return api.line(*a, a[0] + draw(st.integers(1, 12)), b[1], algo="wu")
    points = [a, b, draw(_point), draw(_point)]
    if kind == "bezier":
        return api.bezier(points, samples=draw(st.integers(2, 12)))
    if kind == "bspline":
        return api.bspline([*points, draw(_point)])
    if kind == "parametric":
        return api.parametric_line(*a, *b, samples=draw(st.integers(2, 12)))
    b = (a[0] + draw(st.integers(1, 20)), b[1])  # a line with steps, inside the window
    return api.pipeline_line(*a, *b, window=(-40, -40, 40, 40), viewport=(0, 0, 80, 80))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=150, deadline=None)
@given(questions() | other_questions(), st.sampled_from(list(FORMATS)), st.booleans())
def test_scanconv_own_table_gets_full_marks(solution, fmt, named):
    text = _text(solution, fmt)
    suffix = FORMATS[fmt] if named else ""
    m = mark(parse_text(text, "own" + suffix, suffix), solution)
    assert (m.right, m.first_error) == (m.total, ""), (solution.title, fmt)


# --- every CSV scanconv writes has unique column names -------------------------------------------


def _unique(header: list[str]) -> bool:
    return len(header) == len(set(header))


@pytest.mark.parametrize("path", sorted(GOLDEN.rglob("*.csv")), ids=lambda p: p.name)
def test_every_golden_csv_has_unique_column_names(path):
    body = path.read_text(encoding="utf-8").partition("\n")[2]
    header = next(csv.reader(io.StringIO(body)))
    assert _unique(header), header


COMMANDS = [
    "line 2 2 10 6 --algo dda",
    "line 2 2 10 6 --algo basic",
    "line 2 2 10 6 --algo wu",
    "line 2 2 10 6 --layout textbook",
    *(
        f"circle 8 --method {m}"
        for m in ("midpoint", "bresenham", "general", "polynomial", "trig", "symmetric-dda")
    ),
    "circle 8 --layout textbook",
    "ellipse 8 6",
    "bezier 0 0 1 2 3 3 4 0",
    "parametric circle 5",
]


@pytest.mark.parametrize("command", COMMANDS)
def test_every_command_csv_has_unique_column_names(command):
    r = run(*shlex.split(command), "-f", "csv")
    assert r.code == 0, r.err
    assert _unique(next(csv.reader(io.StringIO(r.out))))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=30, deadline=None)
@given(questions())
def test_every_step_table_csv_has_unique_column_names(solution):
    assert _unique(next(csv.reader(io.StringIO(_text(solution, Format.csv)))))


def test_a_table_of_two_different_columns_read_alike_is_refused():
    with pytest.raises(InputError, match="both read as x"):
        parse_text("x,x_k,y\n1,2,3\n", "two.csv")


@pytest.mark.slow
@pytest.mark.parametrize("solution", [api.circle(7000), api.ellipse(1200, 1200)], ids=["c", "e"])
def test_large_tables_of_scanconv_are_marked_in_full(solution):
    # attack report D17: the circle's CSV was refused (x twice), the ellipse's p beyond 10^9
    m = mark(parse_text(_text(solution, Format.csv), "big.csv", ".csv"), solution)
    assert (m.right, m.first_error) == (m.total, "") and m.total > 1000
