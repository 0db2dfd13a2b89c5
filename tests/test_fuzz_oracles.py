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

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.process_choices import LineClipMethod

from .helpers import run_limited
from .references import (
    RULES,
    bresenham_ref,
    dda_ref,
    liang_barsky_ref,
    midpoint_circle_ref,
)

pytestmark = pytest.mark.slow


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
ROUNDED = {
    "midpoint-subdivision": "rounds its midpoints: within one unit (tests/test_midpoint_clip.py)"
}
METHODS = [m.value for m in LineClipMethod if m.value not in ROUNDED]
"""Every line clipping method of ``clip line -m`` that finds the exact segment."""


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
