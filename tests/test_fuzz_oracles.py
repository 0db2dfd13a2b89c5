"""The fuzz with oracles: random lines, circles and clips through the command line, every
pixel and every clipped end compared with a plain implementation written here from the
notes' definitions (not scanconv's code), in each convention it states. The robustness
sweeps (test_fuzz, test_bad_input, test_files, test_signals) check exits, messages and files:
they passed with the rounding rule turned into round-half-down, which these catch.
"""

from __future__ import annotations

import csv
import io
import json
import math
from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from .helpers import run_limited

pytestmark = pytest.mark.slow


def sign(v):
    return (v > 0) - (v < 0)


def bresenham_ref(x1, y1, x2, y2, tie="step", start="swap"):
    steep = abs(y2 - y1) > abs(x2 - x1)
    if steep:
        a, b = (y1, x1), (y2, x2)
    else:
        a, b = (x1, y1), (x2, y2)
    if start == "swap" and a[0] > b[0]:
        a, b = b, a
    dM, dm = abs(b[0] - a[0]), abs(b[1] - a[1])
    sM, sm = sign(b[0] - a[0]) or 1, sign(b[1] - a[1]) or 1
    M, m = a
    p = 2 * dm - dM
    out = []
    for _ in range(dM + 1):
        out.append((m, M) if steep else (M, m))
        if p < 0 or (tie == "keep" and p == 0):
            p += 2 * dm
        else:
            m += sm
            p += 2 * dm - 2 * dM
        M += sM
    return out


RULES = {
    "half-up": lambda v: math.floor(v + F(1, 2)),
    "trunc": lambda v: int(v),
    "half-even": lambda v: round(v),
    "c-cast": lambda v: int(v + F(1, 2)),
    "half-away": lambda v: sign(v) * math.floor(abs(v) + F(1, 2)),
}


def dda_ref(x1, y1, x2, y2, rounding="half-up", start="given"):
    steep = abs(y2 - y1) > abs(x2 - x1)
    if start == "swap" and ((y1 > y2) if steep else (x1 > x2)):
        x1, y1, x2, y2 = x2, y2, x1, y1
    steps = max(abs(x2 - x1), abs(y2 - y1))
    r = RULES[rounding]
    if steps == 0:
        return [(r(F(x1)), r(F(y1)))]
    xi, yi = F(x2 - x1, steps), F(y2 - y1, steps)
    return [(r(x1 + k * xi), r(y1 + k * yi)) for k in range(steps + 1)]


def midpoint_circle_ref(r, tie="step", loop="strict"):
    """The octant from (0, r): p0 = 1 - r; E when p < 0 (or p <= 0 with tie keep), else SE;
    p += 2x + 1 (E) or 2x + 1 - 2y (SE) with the new x and y; the loop runs while x < y
    (strict) or x <= y (inclusive) before each step."""
    x, y, p = 0, r, 1 - r
    out = [(x, y)]
    while (x < y) if loop == "strict" else (x <= y):
        x += 1
        if p < 0 or (tie == "keep" and p == 0):
            p += 2 * x + 1
        else:
            y -= 1
            p += 2 * x + 1 - 2 * y
        out.append((x, y))
    return out


def liang_barsky_ref(x1, y1, x2, y2, xmin, ymin, xmax, ymax):
    """The exact clipped segment ((x, y), (x, y)) as Fractions, or None (outside)."""
    dx, dy = F(x2 - x1), F(y2 - y1)
    t0, t1 = F(0), F(1)
    for p, q in ((-dx, x1 - xmin), (dx, xmax - x1), (-dy, y1 - ymin), (dy, ymax - y1)):
        if p == 0:
            if q < 0:
                return None
            continue
        t = F(q) / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    if t0 > t1:
        return None
    return ((x1 + t0 * dx, y1 + t0 * dy), (x1 + t1 * dx, y1 + t1 * dy))


def _steps(out: str, fmt: str) -> list[tuple[int, int]]:
    """The plotted pixels of an answer, read back from its JSON or CSV."""
    if fmt == "json":
        return [tuple(s["pixel"]) for s in json.loads(out)["steps"]]
    rows = list(csv.DictReader(io.StringIO(out)))
    xk, yk = ("plot_x", "plot_y") if "plot_x" in rows[0] else ("x", "y")
    return [(int(r[xk]), int(r[yk])) for r in rows]


coord = st.integers(-40, 40) | st.integers(-3000, 3000)
FORMATS = st.sampled_from(["json", "csv"])


def _answer(*argv: str) -> str:
    r = run_limited(*argv)
    assert r.code == 0, (argv, r.err)
    return r.out


@settings(max_examples=150, deadline=None)
@given(
    coord,
    coord,
    coord,
    coord,
    st.sampled_from(["step", "keep"]),
    st.sampled_from(["swap", "given"]),
    FORMATS,
)
def test_every_bresenham_line_is_the_plain_one(x1, y1, x2, y2, tie, start, fmt):
    out = _answer("line", *map(str, (x1, y1, x2, y2)), "--tie", tie, "--start", start, "-f", fmt)
    assert _steps(out, fmt) == bresenham_ref(x1, y1, x2, y2, tie, start)


@settings(max_examples=150, deadline=None)
@given(
    coord,
    coord,
    coord,
    coord,
    st.sampled_from(sorted(RULES)),
    st.sampled_from(["swap", "given"]),
    FORMATS,
)
def test_every_dda_line_is_the_plain_one_in_each_rounding(x1, y1, x2, y2, rounding, start, fmt):
    argv = ("line", *map(str, (x1, y1, x2, y2)), "--algo", "dda", "--rounding", rounding)
    out = _answer(*argv, "--start", start, "-f", fmt)
    assert _steps(out, fmt) == dda_ref(x1, y1, x2, y2, rounding, start)


@settings(max_examples=60, deadline=None)
@given(
    st.integers(1, 400),
    st.sampled_from(["step", "keep"]),
    st.sampled_from(["strict", "inclusive"]),
    FORMATS,
)
def test_every_midpoint_circle_octant_is_the_plain_one(r, tie, loop, fmt):
    argv = ("circle", str(r), "--method", "midpoint", "--tie", tie, "--loop", loop, "-f", fmt)
    assert _steps(_answer(*argv), fmt) == midpoint_circle_ref(r, tie, loop)


small = st.integers(-30, 30)
METHODS = ["cohen-sutherland", "liang-barsky", "cyrus-beck", "nicholl-lee-nicholl"]


@settings(max_examples=150, deadline=None)
@given(
    small,
    small,
    small,
    small,
    small,
    small,
    st.integers(1, 20),
    st.integers(1, 20),
    st.sampled_from(METHODS),
)
def test_every_clipped_line_is_the_exact_liang_barsky_one(x1, y1, x2, y2, wx, wy, w, h, method):
    """Every method's clipped end points equal the exact ones (JSON writes the exact value's
    nearest float); a segment outside is reported as such."""
    window = (wx, wy, wx + w, wy + h)
    argv = ("clip", "line", *map(str, (x1, y1, x2, y2)), "--window", *map(str, window))
    r = run_limited(*argv, "-m", method, "-f", "json")
    if (x1, y1) == (x2, y2):
        return  # a point is not a line: refused or answered, each method as it says
    assert r.code == 0, (argv, r.err)
    got = json.loads(r.out).get("clipped")
    exact = liang_barsky_ref(x1, y1, x2, y2, *window)
    if exact is None:
        assert got is None, (argv, got)
        return
    assert got is not None, (argv, exact)
    as_floats = [[float(v) for v in p] for p in exact]
    assert sorted(map(tuple, got)) == sorted(map(tuple, as_floats)), (argv, got, exact)
