"""The symmetric DDA line (``line --algo symmetric-dda``) end to end.

The method (Rogers, *Procedural Elements for Computer Graphics*, the symmetric DDA): both
coordinates are stepped by ``ε Δx`` and ``ε Δy`` with ``ε = 2^-n``, where
``2^(n-1) <= max(|Δx|, |Δy|) < 2^n``, so that the walk takes ``2^n`` steps. No published table
of it for a line was found (the ``search`` corpora hold the simple DDA's only); the tables here
are worked by hand, and every other line is checked against the independent computation below
(powers of 2 counted by a loop, the points by repeated exact addition, rounding by
``floor(v + 1/2)``), never against the library's own arithmetic.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanconv
from scanconv.render.work import estimate

from .helpers import run

# (0, 0) to (5, 2) by hand: max(5, 2) = 5, 4 <= 5 < 8 so n = 3, ε = 1/8, 8 steps;
# x_inc = 5/8 = 0.625, y_inc = 2/8 = 0.25. Rows (k, x_k, y_k, pixel), pixels floor(v + 1/2).
HAND_5_2 = [
    (0, "0", "0", (0, 0)),
    (1, "5/8", "1/4", (1, 0)),
    (2, "5/4", "1/2", (1, 1)),  # y = 0.5 rounds up
    (3, "15/8", "3/4", (2, 1)),
    (4, "5/2", "1", (3, 1)),  # x = 2.5 rounds up
    (5, "25/8", "5/4", (3, 1)),
    (6, "15/4", "3/2", (4, 2)),
    (7, "35/8", "7/4", (4, 2)),
    (8, "5", "2", (5, 2)),
]

# (2, 2) to (10, 6) by hand (the notes' DDA line): max(8, 4) = 8, 8 <= 8 < 16 so n = 4,
# 16 steps of (1/2, 1/4): twice the simple DDA's 8, every pixel column visited twice.
HAND_10_6_PIXELS = [
    (2, 2), (3, 2), (3, 3), (4, 3), (4, 3), (5, 3), (5, 4), (6, 4), (6, 4),
    (7, 4), (7, 5), (8, 5), (8, 5), (9, 5), (9, 6), (10, 6), (10, 6),
]  # fmt: skip


def independent(x1: Fraction, y1: Fraction, x2: Fraction, y2: Fraction) -> list[tuple]:
    """The symmetric DDA from its definition: n by counting powers of 2, then 2^n additions."""
    longest = max(abs(x2 - x1), abs(y2 - y1))
    n = 0
    while 2**n <= longest:  # the least n with longest < 2^n (n = 0: shorter than a pixel)
        n += 1
    assert longest < 1 or 2 ** (n - 1) <= longest < 2**n
    steps = 0 if longest == 0 else 2**n
    ex, ey = ((x2 - x1) / steps, (y2 - y1) / steps) if steps else (0, 0)
    x, y, rows = x1, y1, []
    for k in range(steps + 1):
        rows.append((k, x, y, (math.floor(x + Fraction(1, 2)), math.floor(y + Fraction(1, 2)))))
        x, y = x + ex, y + ey
    return rows


def test_the_hand_worked_table() -> None:
    sol = scanconv.line(0, 0, 5, 2, algo="symmetric-dda")
    got = [(s.k, s.extra[0], s.extra[1], s.pixel) for s in sol.steps()]
    assert got == [(k, Fraction(x), Fraction(y), p) for k, x, y, p in HAND_5_2]
    derived = {q.key: q.value for q in sol.derived}
    assert (derived["steps"], derived["x_inc"], derived["y_inc"]) == (8, Fraction(5, 8), 0.25)


def test_the_notes_line_takes_twice_the_simple_ddas_steps() -> None:
    sol = scanconv.line(2, 2, 10, 6, algo="symmetric-dda")
    assert [s.pixel for s in sol.steps()] == HAND_10_6_PIXELS
    assert len(list(scanconv.line(2, 2, 10, 6, algo="dda").steps())) == 9


_COORD = st.fractions(min_value=-40, max_value=40, max_denominator=4)


@settings(max_examples=150, deadline=None)
@given(_COORD, _COORD, _COORD, _COORD)
def test_every_line_is_the_definitions_walk(x1, y1, x2, y2) -> None:
    sol = scanconv.line(x1, y1, x2, y2, algo="symmetric-dda")
    got = [(s.k, Fraction(s.extra[0]), Fraction(s.extra[1]), s.pixel) for s in sol.steps()]
    assert got == independent(x1, y1, x2, y2)
    # and the record's row estimate is exact (the budget counts what is printed)
    assert estimate("line", {"x1": x1, "y1": y1, "x2": x2, "y2": y2,
                             "algo": "symmetric-dda"}).rows == len(got)  # fmt: skip


def test_the_budget_refuses_what_the_per_command_estimate_let_through() -> None:
    """1,500,000 long: 2^20 <= 1,500,000 < 2^21, so 2^21 + 1 = 2,097,153 rows, past the
    2,000,000 that any format prints (the per-command estimate said 1,500,001)."""
    r = run("line", "0", "0", "1500000", "1", "--algo", "symmetric-dda", "-f", "csv")
    assert (r.code, r.out) == (2, "")
    assert "2,097,153 rows" in r.err and r.err.count("\n") == 1
    sizes = {"x1": 0, "y1": 0, "x2": 1500000, "y2": 1}
    assert estimate("line", {**sizes, "algo": "symmetric-dda"}).rows == 2**21 + 1
    assert estimate("line", {**sizes, "algo": "dda"}).rows == 1500001  # the simple DDA's
    # the pipeline's last stage is the same method, inside the viewport
    stage = {"x1": 0, "y1": 0, "x2": 1, "y2": 1, "window": (0, 0, 1, 1), "algo": "symmetric-dda"}
    assert estimate("pipeline_line", {**stage, "viewport": (0, 0, 1500000, 1)}).rows > 2**21


def test_every_format_answers() -> None:
    for fmt in ("plain", "markdown", "latex", "html", "csv"):
        r = run("line", "0", "0", "5", "2", "--algo", "symmetric-dda", "-f", fmt)
        assert r.code == 0 and r.out, (fmt, r.err)
    data = json.loads(run("line", "0", "0", "5", "2", "--algo", "symmetric-dda", "-f", "json").out)
    assert data["algorithm"] == "symmetric-dda"
    assert [tuple(s["pixel"]) for s in data["steps"]] == [p for *_, p in HAND_5_2]


def test_check_follows_through_a_slip(tmp_path: Path) -> None:
    """Row 2's y written 0.75 (y_inc added twice); each later row is the right step from the
    student's own previous row, so only row 2 loses its mark."""
    rows = ["k,x,y,round(x),round(y)"]
    y = [Fraction(0), Fraction(1, 4)] + [Fraction(1, 4) * (k + 1) for k in range(2, 9)]
    for k in range(9):
        x = Fraction(5 * k, 8)
        rows.append(f"{k},{float(x)},{float(y[k])},{math.floor(x + Fraction(1, 2))},"
                    f"{math.floor(y[k] + Fraction(1, 2))}")  # fmt: skip
    (tmp_path / "s.csv").write_text("\n".join(rows) + "\n", encoding="utf-8")
    r = run("check", str(tmp_path / "s.csv"), "--", "line", "0", "0", "5", "2", "--algo",
            "symmetric-dda", "-f", "json")  # fmt: skip
    result = json.loads(r.out)
    assert (result["score"], result["out_of"], result["follow_through"]) == (7, 8, True)
    assert result["first_error"].startswith("Row 2 ")
    right = "\n".join(
        f"{k},{float(Fraction(x))},{float(Fraction(yy))},{p[0]},{p[1]}" for k, x, yy, p in HAND_5_2
    )
    (tmp_path / "r.csv").write_text("k,x,y,round(x),round(y)\n" + right + "\n", encoding="utf-8")
    r = run("check", str(tmp_path / "r.csv"), "--", "line", "0", "0", "5", "2", "--algo",
            "symmetric-dda", "-f", "json")  # fmt: skip
    assert (json.loads(r.out)["score"], json.loads(r.out)["out_of"]) == (8, 8)


def test_compare_lists_it_and_says_why_it_differs() -> None:
    r = run("compare", "line", "0", "0", "5", "2", "-f", "json")
    data = json.loads(r.out)
    assert "symmetric-dda" in data["methods"]
    text = run("compare", "line", "0", "0", "5", "2").out
    # x = 1: the walk's points 5/8 and 5/4 round to y = 0 and y = 1 (HAND_5_2, rows 1 and 2)
    assert "SDDA repeats" in text and "sym. DDA" in text


def test_practice_offers_it() -> None:
    from scanconv.practice.notes import practice

    drawn = [q for q in practice("line-methods", 9, seed=3) if "symmetric-dda" in q.argv]
    assert drawn and all("symmetric DDA" in q.wording for q in drawn)


@pytest.mark.parametrize("piece", ["--derive", "--algorithm", "--rounding=trunc"])
def test_what_it_does_not_have_is_refused_by_name(piece: str) -> None:
    r = run("line", "0", "0", "5", "2", "--algo", "symmetric-dda", *piece.split("="))
    assert (r.code, r.out) == (2, "") and r.err.count("\n") == 1
    assert "symmetric-dda" in r.err
