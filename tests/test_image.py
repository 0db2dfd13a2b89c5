"""Image representation: storage arithmetic, quantization, sampling and the notes' ramp.

The expected values are computed here independently of :mod:`scanconv.image` (bit counts by
doubling, levels from the quantizer's definition with exact fractions), or copied from the
course notes' own text (the 8 x 8 matrix and the 3-bit table).
"""

from __future__ import annotations

import csv
import io
import itertools
import json
import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.image_limits import MAX_CELLS
from scanconv.algorithms.quantize import Quantizer
from scanconv.algorithms.ramp import ramp
from scanconv.algorithms.sample import sample_levels
from scanconv.answers.image.ramp import ramp_solution
from scanconv.answers.image.storage import storage_solution
from scanconv.render import formats

from .helpers import run

# The notes' 8 x 8 example (IMAGE REPRESENTATION, 3(b), L = 8), as printed.
NOTES_MATRIX = """\
0	1	2	3	4	5	6	7
1	2	3	4	5	6	7	6
2	3	4	5	6	7	6	5
3	4	5	6	7	6	5	4
4	5	6	7	6	5	4	3
5	6	7	6	5	4	3	2
6	7	6	5	4	3	2	1
7	6	5	4	3	2	1	0
"""

# The notes' 3-bit quantization table (section 6), as printed.
NOTES_TABLE = """\
0	000	Black
1	001	Very Dark Gray
2	010	Dark Gray
3	011	Gray
4	100	Light Gray
5	101	Very Light Gray
6	110	Almost White
7	111	White
"""


def bits_needed(levels: int) -> int:
    """The smallest k with 2**k >= L, by doubling (independent of bit_length)."""
    k, capacity = 0, 1
    while capacity < levels:
        k, capacity = k + 1, capacity * 2
    return k


# --- ramp -------------------------------------------------------------------------------------


def test_ramp_is_the_notes_matrix():
    expected = [[int(v) for v in line.split("\t")] for line in NOTES_MATRIX.splitlines()]
    assert ramp(8, 8, 8).tolist() == expected


def test_ramp_cli_csv_is_the_notes_matrix():
    r = run("image", "ramp", "--size", "8", "--levels", "8", "--format", "csv")
    assert r.code == 0, r.err
    rows = list(csv.reader(io.StringIO(r.out)))
    assert rows[0] == ["i", *map(str, range(8))]
    assert [row[1:] for row in rows[1:]] == [line.split("\t") for line in NOTES_MATRIX.splitlines()]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(m=st.integers(1, 40), n=st.integers(1, 40), levels=st.integers(2, 20))
def test_ramp_is_a_triangle_wave(m, n, levels):
    a = ramp(m, n, levels).astype(int)
    assert a.min() >= 0 and a.max() <= levels - 1
    # walk from 0, turning around at 0 and L - 1 (independent of the modulo): walk[s] is the
    # value after s steps, each cell's value that at s = i + j (one walk for the whole matrix,
    # not one per cell)
    walk, v, d = [0], 0, 1
    for _ in range(m + n - 2):
        if not 0 <= v + d <= levels - 1:
            d = -d
        v += d
        walk.append(v)
    for i in range(m):
        for j in range(n):
            assert a[i, j] == walk[i + j]
    if n > 1:
        assert (np.abs(np.diff(a, axis=1)) == 1).all()


def test_ramp_solution_rows_match_ramp():
    sol = ramp_solution(5, 9, 4)
    rows = [list(r[1:]) for r in sol.tables[0].rows()]
    assert rows == ramp(5, 9, 4).tolist()
    assert [r[0] for r in sol.tables[0].rows()] == list(range(5))


# --- quantization -----------------------------------------------------------------------------


def test_quantize_3_bits_is_the_notes_table():
    r = run("quantize", "--bits", "3", "--format", "csv")
    assert r.code == 0, r.err
    rows = list(csv.reader(io.StringIO(r.out)))
    assert rows[0] == ["decimal", "binary", "gray_level"]
    assert rows[1:] == [line.split("\t") for line in NOTES_TABLE.splitlines()]


@st.composite
def quantizers(draw):
    integer = draw(st.booleans())
    levels = draw(st.integers(2, 64))
    lo = draw(st.integers(-1000, 1000))
    if integer:
        hi = lo + draw(st.integers(levels - 1, 5000))
    else:
        lo = Fraction(lo, draw(st.integers(1, 16)))
        hi = lo + Fraction(draw(st.integers(1, 5000)), draw(st.integers(1, 16)))
    recon = draw(st.sampled_from(["midpoint", "lower"]))
    return Quantizer.make(lo, hi, levels, integer=integer, recon=recon)


values = st.fractions(min_value=-3000, max_value=3000, max_denominator=64)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(q=quantizers(), v=values)
def test_level_in_range(q, v):
    assert 0 <= q.level(v) <= q.levels - 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(q=quantizers(), v=values)
def test_level_matches_definition(q, v):
    width = q.hi - q.lo + (1 if q.integer else 0)
    step = Fraction(width) / q.levels
    # the largest k in 0 .. L-1 whose cell starts at or below v (0 below the range)
    k = max([k for k in range(q.levels) if q.lo + k * step <= v] or [0])
    assert q.level(v) == k


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@given(q=quantizers(), vs=st.lists(values, min_size=2, max_size=30))
def test_level_is_monotonic(q, vs):
    vs = sorted(vs)
    levels = [q.level(v) for v in vs]
    assert levels == sorted(levels)
    arr = q.levels_of(np.array([float(v) for v in vs]))
    assert arr.tolist() == sorted(arr.tolist())
    assert arr.min() >= 0 and arr.max() <= q.levels - 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(q=quantizers())
def test_intervals_partition_the_range(q):
    cells = [q.interval(k) for k in range(q.levels)]
    assert cells[0][0] == q.lo
    assert cells[-1][1] == q.hi
    for (a, b), (c, _) in itertools.pairwise(cells):
        assert c == (b + 1 if q.integer else b)
        assert a <= b
    if q.integer:
        # every integer input falls in the interval of its own level
        for v in range(int(q.lo), int(q.hi) + 1, max(1, (int(q.hi) - int(q.lo)) // 50)):
            first, last = cells[q.level(v)]
            assert first <= v <= last
    for k in range(q.levels):
        r = q.reconstruction(k)
        start = q.lo + k * Fraction(q.hi - q.lo + (1 if q.integer else 0), q.levels)
        assert r == (start if q.recon == "lower" else start + Fraction(q.step) / 2)


def test_two_bit_reconstruction_of_8_bit_inputs():
    # The textbook exercise (peers.md [IM3]): 0-63, 64-127, ... reconstructed at 32, 96, ...
    r = run("quantize", "--bits", "2", "--range", "0", "255", "--format", "csv")
    rows = list(csv.reader(io.StringIO(r.out)))
    assert [row[3:] for row in rows[1:]] == [
        ["0", "63", "32"],
        ["64", "127", "96"],
        ["128", "191", "160"],
        ["192", "255", "224"],
    ]


# --- storage ----------------------------------------------------------------------------------


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=100)
@given(
    m=st.integers(1, 10**6),
    n=st.integers(1, 10**6),
    levels=st.integers(2, 2**24),
    frames=st.integers(1, 1000),
)
def test_storage_matches_direct_computation(m, n, levels, frames):
    sol = storage_solution(m, n, levels=levels, frames=frames)
    derived = {q.key: q.value for q in sol.derived}
    bits = m * n * bits_needed(levels) * frames
    assert derived["k"] == bits_needed(levels)
    assert derived["bits"] == bits
    assert derived["bytes"] == Fraction(bits, 8)
    sizes = sol.data["sizes"]
    assert sizes["KB"] == Fraction(bits, 8 * 1000)
    assert sizes["MB"] == Fraction(bits, 8 * 10**6)
    assert sizes["KiB"] == Fraction(bits, 8 * 1024)
    assert sizes["MiB"] == Fraction(bits, 8 * 1024 * 1024)
    table = {row[0]: row for row in sol.tables[0].rows()}
    for unit, divisor in (("KB", 8000), ("MB", 8 * 10**6), ("KiB", 8192), ("MiB", 8 * 2**20)):
        shown = table[unit][2]
        exact = Fraction(bits, divisor)
        if shown.startswith("~"):
            assert math.isclose(float(shown[1:]), exact, rel_tol=1e-3)
        else:
            assert Fraction(shown) == exact
    power = levels & (levels - 1) == 0
    assert any("not a power of two" in n for n in sol.notes) is not power


def test_storage_1024_768_256():
    r = run("storage", "1024", "768", "--levels", "256", "--format", "json")
    data = json.loads(r.out)
    assert data["derived"]["bits"] == 1024 * 768 * 8 == 6291456
    assert data["derived"]["bytes"] == 786432
    assert data["sizes"]["KiB"] == 768 and data["sizes"]["KB"] == 786.432


@pytest.mark.parametrize(
    ("option", "bits_per_pixel"),
    [(("--bits", "8"), 8), (("--binary",), 1), (("--color", "rgb24"), 24), (("-L", "100"), 7)],
)
def test_storage_depth_options(option, bits_per_pixel):
    r = run("storage", "640", "480", *option, "--format", "json")
    assert r.code == 0, r.err
    assert json.loads(r.out)["derived"]["bits"] == 640 * 480 * bits_per_pixel


# --- sampling ---------------------------------------------------------------------------------


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=60, deadline=None)
@given(m=st.integers(1, 12), n=st.integers(1, 12), levels=st.integers(2, 40))
def test_sample_x_plus_y_against_exact_levels(m, n, levels):
    s = sample_levels("x + y", m, n, levels, origin="top-left")
    assert s.levels.shape == (m, n)
    vmax = m - 1 + n - 1
    for i in range(m):
        for j in range(n):
            v = i + j  # default domain: x = j, y = i (top-left: row i is y = i)
            k = 0 if vmax == 0 else min(math.floor(Fraction(v * levels, vmax)), levels - 1)
            assert s.levels[i, j] == k


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=60, deadline=None)
@given(
    m=st.integers(1, 10),
    n=st.integers(1, 10),
    levels=st.integers(2, 300),
    lo=st.integers(-5, 5),
    width=st.integers(1, 10),
)
def test_sample_levels_in_range_and_monotonic(m, n, levels, lo, width):
    s = sample_levels("sin(3*x) * y + x", m, n, levels, value_range=(lo, lo + width))
    assert s.levels.min() >= 0 and s.levels.max() <= levels - 1
    f = np.sin(3 * s.x[None, :]) * s.y[:, None] + s.x[None, :]
    order = np.argsort(f, axis=None, kind="stable")
    assert (np.diff(s.levels.ravel()[order].astype(int)) >= 0).all()


def test_sample_bottom_left_puts_largest_y_on_top():
    s = sample_levels("y", 4, 2, 4)
    assert s.y.tolist() == [3, 2, 1, 0]
    assert s.levels[:, 0].tolist() == [3, 2, 1, 0]


def test_sample_constant_is_level_zero():
    s = sample_levels("2", 3, 3, 4)
    assert s.quantizer is None and not s.levels.any()


# --- bad input --------------------------------------------------------------------------------


BAD = [
    ("storage", "0", "768", "--levels", "256"),
    ("storage", "-5", "768", "--levels", "256"),
    ("storage", "10", "10", "--levels", "1"),
    ("storage", "10", "10", "--bits", "25"),
    ("storage", "10", "10", "--levels", str(2**24 + 1)),
    ("storage", "10", "10"),
    ("storage", "10", "10", "--binary", "--bits", "2"),
    ("storage", "10", "10", "--levels", "4", "--frames", "0"),
    ("quantize", "--bits", "0"),
    ("quantize", "--bits", "25"),
    ("quantize", "--bits", "3", "--range", "0", "1"),
    ("quantize", "--bits", "3", "--range", "9", "2"),
    ("sample", "x + y", "--size", "0x8", "--levels", "8"),
    ("sample", "x + y", "--size", "8x-1", "--levels", "8"),
    ("sample", "x + y", "--size", "8x8", "--levels", "1"),
    ("sample", "x + y", "--size", "8x8", "--levels", "33554432"),
    ("sample", "x + y", "--size", "100000x100000", "--levels", "8"),
    ("sample", "__import__('os').system('true')", "--size", "8x8", "--levels", "8"),
    ("sample", "x.real", "--size", "8x8", "--levels", "8"),
    ("sample", "log(x)", "--size", "8x8", "--levels", "8"),
    ("sample", "x + y", "--size", "8x8", "--levels", "8", "--domain", "0", "1", "2", "z"),
    ("image", "ramp", "--size", "0"),
    ("image", "ramp", "--size", "5000x5000"),
    ("image", "ramp", "--levels", "1"),
    ("image", "ramp", "--levels", "99999999"),
]


@pytest.mark.parametrize("args", BAD, ids=[" ".join(a) for a in BAD])
def test_bad_input_is_one_line_exit_2(args):
    r = run(*args, "--format", "plain")
    assert r.code == 2
    assert r.out == ""
    assert len(r.err.strip().splitlines()) == 1
    assert "Traceback" not in r.err


def test_too_large_is_refused_before_allocating(monkeypatch):
    def no_alloc(*args, **kwargs):
        raise AssertionError("allocated")

    monkeypatch.setattr(np, "zeros", no_alloc)
    monkeypatch.setattr(np, "empty", no_alloc)
    monkeypatch.setattr(np, "linspace", no_alloc)
    for fn in (
        lambda: sample_levels("x", 10**6, 10**6, 8),
        lambda: ramp(10**6, 10**6, 8),
    ):
        with pytest.raises(ValueError, match="at most 4096 x 4096 = 16,777,216 cells"):
            fn()
    assert MAX_CELLS == 4096 * 4096


# --- formats ----------------------------------------------------------------------------------

COMMANDS = [
    ("storage", "1024", "768", "--levels", "100", "--frames", "3"),
    ("quantize", "--bits", "3", "--range", "0", "1", "--input", "real"),
    ("sample", "sin(x)*cos(y)", "--size", "6x9", "-L", "12", "--domain", "0", "2*pi", "-1", "1"),
    ("image", "ramp", "--size", "5x7", "--levels", "4"),
]


@pytest.mark.parametrize("args", COMMANDS, ids=[a[0] for a in COMMANDS])
@pytest.mark.parametrize("fmt", formats("answer"))
def test_every_format(args, fmt):
    r = run(*args, "--format", fmt)
    assert r.code == 0, r.err
    assert r.out
    if fmt == "plain":
        assert r.out.isascii()
    if fmt == "json":
        data = json.loads(r.out)
        assert data["primitive"] == "image" and data["tables"][0]["rows"]
    if fmt == "csv":
        rows = list(csv.reader(io.StringIO(r.out)))
        assert len({len(row) for row in rows}) == 1 and len(rows) > 1


# --- frame-buffer depths in storage, quantize keeps its limit ---------------------------------


@pytest.mark.parametrize("bits", [32, 48, 64])
def test_storage_accepts_frame_buffer_depths(bits):
    from scanconv import _api

    sol = _api.storage(1024, 768, bits=bits)
    q = {q.key: q.value for q in sol.derived}
    assert q["k"] == bits and q["bits"] == 1024 * 768 * bits and q["bytes"] == 1024 * 96 * bits


@pytest.mark.parametrize("bits", ["25", "31", "65"])
def test_storage_refuses_other_depths_beyond_24(bits):
    from .helpers import assert_refused, run

    assert_refused(run("storage", "8", "8", "--bits", bits), "--bits", "at most 24", "32, 48 or 64")


def test_quantize_keeps_its_own_limit():
    from .helpers import assert_refused, run

    assert_refused(run("quantize", "--bits", "32"), "--bits", "at most 24")
