"""The widely copied Bresenham circle (x stepped before d is updated; --xstep first), against
the code as it is copied (GeeksforGeeks' drawCircle loop), written here independently."""

from __future__ import annotations

import pytest

from scanconv.algorithms.circles import bresenham
from scanconv.answers.primitives.circle import circle_solution


def _copied(r: int) -> list[tuple[int, tuple[int, int]]]:
    # x = 0, y = r, d = 3 - 2r; plot; while (y >= x) { x++; if (d > 0) { y--;
    # d = d + 4 * (x - y) + 10; } else d = d + 4 * x + 6; plot; }
    x, y, d = 0, r, 3 - 2 * r
    out = [(d, (x, y))]
    while y >= x:
        x += 1
        if d > 0:
            y -= 1
            d = d + 4 * (x - y) + 10
        else:
            d = d + 4 * x + 6
        if x <= y:
            out.append((d, (x, y)))
    return out


def test_radius_10_as_published() -> None:
    assert [s.p for s in bresenham(10, xstep="first")][:4] == [-17, -7, 7, -7]


@pytest.mark.parametrize("r", [1, 2, 3, 5, 8, 10, 13, 20, 37, 50])
def test_equals_the_copied_code(r: int) -> None:
    # the copied code steps on d > 0, that is d >= 1: the tie rule "keep" at d = 0
    ours = [(s.p, s.pixel) for s in bresenham(r, tie="keep", xstep="first")]
    assert ours == _copied(r)


def test_the_default_is_bresenhams_own() -> None:
    sol = circle_solution("bresenham", 10)
    assert [s.p for s in sol.steps()][:4] == [-17, -11, -1, 13]
    assert "4x_{k+1}" in circle_solution("bresenham", 10, xstep="first").derived[2].tex


@pytest.mark.parametrize("r", [5, 10, 13, 37])
@pytest.mark.parametrize("tie", ["step", "keep"])
def test_the_marking_model_follows_the_x_first_generator(r: int, tie: str) -> None:
    from scanconv.marking.models import BresenhamCircle

    m = BresenhamCircle(r, tie, "first")
    s = m.start()
    got = [(s.p, s.point)]
    while (t := m.step(s, m.decide(s))) is not None and not m.done(s, t):
        got.append((t.p, t.point))
        s = t
    assert got == [(x.p, x.pixel) for x in bresenham(r, tie, "first")]


@pytest.mark.parametrize("r", [3, 10, 21])
def test_check_marks_the_x_first_table_with_its_own_model(r: int, tmp_path) -> None:
    """scanconv's own x-first table gets full marks; Bresenham's own table, checked against
    the x-first question, loses the rows where the two differ."""
    from .helpers import run

    own = tmp_path / "own.csv"
    assert run("circle", str(r), "--method", "bresenham", "--xstep", "first", "-f", "csv",
               "-o", str(own)).code == 0  # fmt: skip
    res = run("check", str(own), "-f", "json", "--", "circle", str(r), "--method", "bresenham",
              "--xstep", "first")  # fmt: skip
    assert res.code == 0, res.err
    import json

    doc = json.loads(res.out)
    assert doc["score"] == doc["out_of"]
