"""The renderer and escaper mutations that only a doctest killed, or that nothing killed
(``../shared/reference/mutation-report.md``), as tests against hand-worked values:

* R3, ``render/mappings/latex.py`` ``split_columns``: a table too wide for the page is set in parts,
  each repeating the first column; every other column is in exactly one part (``every[2:]``
  lost the second column);
* R6, ``render/documents/moodle.py`` ``_CLOZE_SPECIAL``: a Cloze blank's answer holding ``"`` or ``'``
  writes them as character references, and Moodle's reading gives the answer back;
* ST1, ``marking/student_table.py``: a student's number written to *n* decimals has *n* places
  (the marking's tolerance is one unit in the last place);
* NU3, ``core/numeric.py`` ``fmt_value``: an exact decimal of up to 8 characters is shown as
  a decimal (``2^-6 = 0.015625``), a longer one as a fraction with its rounding.
"""

from __future__ import annotations

import html
import re
from fractions import Fraction
from pathlib import Path

import pytest

from scanconv.core.numeric import fmt_value
from scanconv.core.records import Column
from scanconv.marking import student_table
from scanconv.render.documents import moodle
from scanconv.render.documents.lms import Gap
from scanconv.render.mappings import latex
from tests.helpers import run
from tests.references import midpoint_circle_ref

# --- R3: a wide table's parts -----------------------------------------------------------------


_HEAD = re.compile(r"\$\(x_c([+-])([xy]), y_c([+-])([xy])\)\$")


def _image(head: str, x: int, y: int) -> str:
    """The point a symmetry column's heading (``$(x_c-y, y_c+x)$``) names, about (0, 0)."""
    m = _HEAD.fullmatch(head)
    assert m, head
    value = {"x": x, "y": y}
    px = value[m[2]] * (1 if m[1] == "+" else -1)
    py = value[m[4]] * (1 if m[3] == "+" else -1)
    return f"({px}, {py})"


def test_wide_symmetry_table_parts_hold_every_column() -> None:
    """``circle 60`` as LaTeX sets its 8-way symmetry table (9 columns, 44 rows) in parts:
    together the parts hold each of the eight images once, each beside the octant point it
    comes from, and each cell is that image of the point (worked here from the heading)."""
    result = run("circle", "60", "-f", "latex")
    assert result.code == 0, result.err
    parts = result.out.split("8-way symmetry about the centre (0, 0), part ")[1:]
    assert len(parts) >= 2
    octant = midpoint_circle_ref(60)  # the notes' octant from (0, r)
    heads: list[str] = []
    for part in parts:
        lines = [ln for ln in part.split("\\end{longtable}")[0].splitlines() if " & " in ln]
        head, *rows = [[c.strip() for c in ln.removesuffix(" \\\\").split(" & ")] for ln in lines]
        assert head[0] == "$(x, y)$"
        heads += head[1:]
        assert [r[0] for r in rows] == [f"$({x}, {y})$" for x, y in octant]
        for r, (x, y) in zip(rows, octant, strict=True):
            assert [c.strip("$") for c in r[1:]] == [_image(h, x, y) for h in head[1:]]
    images = {f"$(x_c{a}{u}, y_c{b}{v})$" for a in "+-" for b in "+-" for u, v in ("xy", "yx")}
    assert sorted(heads) == sorted(images)


def test_split_columns_covers_each_column_once() -> None:
    """Straight from :func:`~scanconv.render.mappings.latex.split_columns`: with 2 to 12 wide columns
    after the first, each part starts with the first column, and the rest, in order, are
    each in exactly one part."""
    for n in range(2, 13):
        cols = [Column("k", "k", ""), *(Column(f"c{i}", "(xc + x, yc + y)", "") for i in range(n))]
        parts = [part for part, _ in latex.split_columns(cols, [])]
        assert all(part[0] == 0 for part in parts)
        assert [c for part in parts for c in part[1:]] == list(range(1, n + 1)), n


# --- R6: a Cloze blank's quotes ---------------------------------------------------------------


def read_cloze(blank: str) -> list[str]:
    """A SHORTANSWER blank as Moodle reads it: the answers part at a ``~`` (none is escaped
    here), each ``=`` answer then HTML-entity-decoded."""
    m = re.fullmatch(r"\{1:SHORTANSWER:(.*)\}", blank)
    assert m, blank
    return [html.unescape(a.removeprefix("=")) for a in m[1].split("~")]


@pytest.mark.parametrize(
    "answers",
    [('say "hi"',), ("it's", "it is"), ("a\"b'c", "'quoted'"), ("x & y <z>", "{1}~#")],
)
def test_cloze_answer_quotes_are_references(answers: tuple[str, ...]) -> None:
    """No raw quote, ``&``, ``<``, ``{``, ``~``, ``#`` or backslash inside the blank's answers
    (an attribute or a Cloze reader could end there); read back, the answers are the same."""
    blank = moodle.cloze(Gap("word", answers))
    inside = blank.removeprefix("{1:SHORTANSWER:").removesuffix("}")
    bare = re.sub(r"&#[0-9]+;", "", inside)  # the character references aside
    for char in "\"'&<>{}#\\":
        assert char not in bare, (char, blank)
    assert read_cloze(blank) == list(answers)


# --- ST1: a student's decimals ----------------------------------------------------------------


@pytest.mark.parametrize(
    ("cell", "places"),
    [("2.375", 3), ("2.4", 1), ("-0.50", 2), ("3", 0), ("$2.50$", 2), (" 7.0 ", 1), ("1e-3", 0)],
)
def test_student_number_places(cell: str, places: int) -> None:
    """The places of a number as written, counted by hand."""
    value = student_table._value(cell, "p", "a.csv", "line 2")
    assert value is not None
    assert value.places == places  # type: ignore[union-attr]


def _dda_table(tmp_path: Path, x: list[str]) -> Path:
    """A student's DDA table for (2, 2) to (5, 10) with the x column as given."""
    plot = [2, 2, 3, 3, 4, 4, 4, 5, 5]
    lines = ["k,plot_x,plot_y,x,y"]
    lines += [f"{k},{plot[k]},{k + 2},{x[k]},{k + 2}" for k in range(9)]
    path = tmp_path / "dda.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


X_EXACT = ["2", "2.375", "2.75", "3.125", "3.5", "3.875", "4.25", "4.625", "5"]


@pytest.mark.parametrize(
    ("x", "score"),
    [
        (X_EXACT, "8 of 8"),
        (["2", "2.38", "2.75", "3.13", "3.5", "3.88", "4.25", "4.63", "5"], "8 of 8"),
        (["2", "2.376", "2.75", "3.126", "3.5", "3.876", "4.25", "4.626", "5"], "8 of 8"),
        (["2", "2.377", "2.75", "3.127", "3.5", "3.877", "4.25", "4.627", "5"], "4 of 8"),
    ],
    ids=["exact", "two-places", "one-unit-off", "two-units-off"],
)
def test_decimals_are_marked_to_their_last_place(tmp_path: Path, x: list[str], score: str) -> None:
    """DDA x_k = 2 + 3k/8: written to 2 decimals (2.38 for 2.375) or to 3 one unit off (2.376)
    each is within one unit of its last place, so right; two units off (2.377) each is wrong
    (the exact ones, 2.75, 3.5 and 4.25, stay right). Counting one place too many would make
    the rounded ones wrong."""
    path = _dda_table(tmp_path, x)
    result = run("check", str(path), "-f", "plain", "--", *"line 2 2 5 10 --algo dda".split())
    assert result.code == 0, result.err
    assert f"Score: {score} steps right" in result.out


# --- NU3: fmt_value's 8 characters ------------------------------------------------------------


@pytest.mark.parametrize(
    ("value", "shown"),
    [
        (Fraction(1, 64), "0.015625"),  # 8 characters: a decimal
        (Fraction(-1, 64), "-1/64 ≈ -0.016"),  # 9 with its minus
        (Fraction(1, 128), "1/128 ≈ 0.008"),  # 9 characters
        (Fraction(12345, 1000), "12.345"),
        (Fraction(1234567, 1000), "1234.567"),  # 8
        (Fraction(12345678, 1000), "6172839/500 ≈ 12345.678"),  # 9
    ],
)
def test_fmt_value_eight_characters(value: Fraction, shown: str) -> None:
    """An exact decimal of at most 8 characters is shown as it is, a longer one as its
    fraction and its 3-decimal rounding."""
    assert fmt_value(value) == shown


@pytest.mark.parametrize(
    ("radius", "eps"), [(40, "2^-6 = 0.015625"), (100, "2^-7 = 1/128 ~ 0.008")], ids=["r40", "r100"]
)
def test_symmetric_dda_eps_in_the_working(radius: int, eps: str) -> None:
    """``circle 40 --method symmetric-dda``: ε = 2^-6 is 0.015625 (8 characters) in the
    working; at r = 100, 2^-7 = 0.0078125 is 9 and shown as 1/128."""
    result = run("circle", str(radius), "--method", "symmetric-dda", "-f", "plain")
    assert result.code == 0, result.err
    assert f"  eps = 2^-n = {eps}\n" in result.out
