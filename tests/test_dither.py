"""Halftoning and dithering (scanconv.algorithms.dither, scanconv.answers.image.dither): hand-worked
examples, and properties against independent computations."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms import dither as d
from scanconv.answers.image.dither import (
    diffusion_solution,
    ordered_solution,
    pattern_solution,
    threshold_solution,
)
from scanconv.core.checks import InputError


def _closed_form_bayer(n: int) -> list[list[int]]:
    """Bayer's matrix from its closed form (bit-reversed interleave of i XOR j and i), not
    from the recursion the library uses."""
    bits = n.bit_length() - 1
    out = [[0] * n for _ in range(n)]
    for i in range(n):
        for j in range(n):
            v = 0
            for k in range(bits):
                v = (v << 2) | (((i ^ j) >> k & 1) << 1) | (i >> k & 1)
            out[i][j] = v
    return out


@pytest.mark.parametrize("n", [2, 4, 8, 16])
def test_bayer_matches_its_closed_form(n: int) -> None:
    assert [list(r) for r in d.bayer(n)] == _closed_form_bayer(n)
    assert sorted(v for r in d.bayer(n) for v in r) == list(range(n * n))


def test_bayer_4_is_the_published_matrix() -> None:
    # Bayer (1973) / Hearn & Baker's D4
    assert d.bayer(4) == (
        (0, 8, 2, 10),
        (12, 4, 14, 6),
        (3, 11, 1, 9),
        (15, 7, 13, 5),
    )


@pytest.mark.parametrize("n", [0, 1, 3, 6, 32])
def test_bayer_refuses_other_sizes(n: int) -> None:
    with pytest.raises(InputError) as info:
        d.bayer(n)
    assert info.value.param == "matrix"


def test_ordered_dither_by_hand() -> None:
    # I on 0..255, D2 = [[0, 2], [3, 1]], raw thresholds d*255/4 = 0, 127.5, 191.25, 63.75:
    # (0,0) 10 > 0 on; (0,1) 200 > 127.5 on; (1,0) 60 > 191.25 off; (1,1) 90 > 63.75 on.
    sol = ordered_solution([[10, 200], [60, 90]], 2, 255)
    assert sol.data["output"] == [[1, 1], [0, 1]]
    assert [s.extra[3] for s in sol.steps()] == [
        0,
        Fraction(255, 2),
        Fraction(765, 4),
        Fraction(255, 4),
    ]


def test_ordered_conventions_change_the_numbers_as_stated() -> None:
    image = [[0, 1], [2, 3]]
    # raw, >: a value equal to its threshold stays off; >= turns it on
    assert ordered_solution(image, 2, 4).data["output"] == [[0, 0], [0, 1]]
    assert ordered_solution(image, 2, 4, compare=">=").data["output"] == [[1, 0], [0, 1]]
    # 1-based entries shift every threshold down by top/n^2 = 1
    assert ordered_solution(image, 2, 4, base="1").data["thresholds"] == [[-1, 1], [2, 0]]
    # the transposed reading swaps the off-diagonal thresholds
    assert ordered_solution(image, 2, 4, transpose=True).data["thresholds"] == [[0, 3], [2, 1]]
    centred = ordered_solution(image, 2, 4, scale="centered").data["thresholds"]
    assert centred == [[Fraction(1, 2), Fraction(5, 2)], [Fraction(7, 2), Fraction(3, 2)]]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=60)
@given(
    n=st.sampled_from([2, 4, 8]),
    rows=st.integers(1, 9),
    cols=st.integers(1, 9),
    seed=st.integers(0, 2**32 - 1),
    compare=st.sampled_from([">", ">="]),
)
def test_ordered_equals_a_tiled_numpy_comparison(n, rows, cols, seed, compare) -> None:
    rng = np.random.default_rng(seed)
    image = rng.integers(0, 256, size=(rows, cols))
    sol = ordered_solution(image.tolist(), n, 255, compare=compare)
    t = np.array(d.bayer(n), dtype=float) * 255 / (n * n)
    tiled = np.tile(t, (rows // n + 1, cols // n + 1))[:rows, :cols]
    expected = (image > tiled) if compare == ">" else (image >= tiled)
    assert sol.data["output"] == expected.astype(int).tolist()


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=60)
@given(n=st.sampled_from([2, 4]), level=st.integers(0, 255), centred=st.booleans())
def test_ordered_dither_preserves_the_mean_of_a_flat_tile(n, level, centred) -> None:
    """A flat region the size of the matrix: the share of pixels on is within 1/n² of the
    intensity (raw thresholds), within 1/(2n²) with centred thresholds."""
    image = [[level] * n for _ in range(n)]
    scale = "centered" if centred else "raw"
    out = ordered_solution(image, n, 255, scale=scale).data["output"]
    on = Fraction(sum(map(sum, out)), n * n)
    bound = Fraction(1, 2 * n * n) if centred else Fraction(1, n * n)
    assert abs(on - Fraction(level, 255)) <= bound


def test_threshold_by_hand() -> None:
    sol = threshold_solution([[10, 200], [128, 127]], 255, 128)
    assert sol.data["output"] == [[0, 1], [1, 0]]
    assert threshold_solution([[5]], 10, compare=">").data["output"] == [[0]]
    assert threshold_solution([[5]], 10).data["output"] == [[1]]


def test_floyd_steinberg_by_hand() -> None:
    # 2 x 2 of 100 on 0..255, on when I' >= 127.5:
    # (0,0) 100 -> 0, e = 100: +43.75 right, +31.25 below, +6.25 below right
    # (0,1) 143.75 -> 255, e = -111.25: -20.859375 below left, -34.765625 below
    # (1,0) 100 + 31.25 - 20.859375 = 110.390625 -> 0, e = 110.390625: +48.2958984375 right
    # (1,1) 100 + 6.25 - 34.765625 + 48.2958984375 = 119.7802734375 -> 0
    sol = diffusion_solution([[100, 100], [100, 100]], 255)
    rows = [s.extra for s in sol.steps()]
    assert [r[3] for r in rows] == [
        100,
        Fraction(575, 4),
        Fraction(7065, 64),
        Fraction(122655, 1024),
    ]
    assert sol.data["output"] == [[0, 1], [0, 0]]


def _oracle(image: list[list[int]], top: int, serpentine: bool) -> list[list[int]]:
    """Floyd–Steinberg as Wikipedia's pseudocode writes it, in place, with exact fractions."""
    px = [[Fraction(v) for v in row] for row in image]
    h, w = len(px), len(px[0])
    out = [[0] * w for _ in range(h)]
    for y in range(h):
        back = serpentine and y % 2 == 1
        s = -1 if back else 1
        for x in range(w - 1, -1, -1) if back else range(w):
            old = px[y][x]
            new = top if old >= Fraction(top, 2) else 0
            out[y][x] = int(new == top)
            err = old - new
            for dy, dx, wgt in ((0, s, 7), (1, -s, 3), (1, 0, 5), (1, s, 1)):
                if 0 <= y + dy < h and 0 <= x + dx < w:
                    px[y + dy][x + dx] += err * wgt / 16
    return out


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=60)
@given(
    rows=st.integers(1, 7),
    cols=st.integers(1, 7),
    seed=st.integers(0, 2**32 - 1),
    serpentine=st.booleans(),
)
def test_floyd_steinberg_equals_an_independent_implementation(rows, cols, seed, serpentine) -> None:
    image = np.random.default_rng(seed).integers(0, 256, size=(rows, cols)).tolist()
    order = "serpentine" if serpentine else "raster"
    sol = diffusion_solution(image, 255, order=order)
    assert sol.data["output"] == _oracle(image, 255, serpentine)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=40)
@given(rows=st.integers(1, 6), cols=st.integers(1, 6), seed=st.integers(0, 2**32 - 1))
def test_error_diffusion_loses_only_what_falls_off_the_image(rows, cols, seed) -> None:
    """Exact arithmetic: the input's total is the output's total plus the shares that fell
    outside the image (the carries of each step make up its error, less those shares)."""
    image = np.random.default_rng(seed).integers(0, 256, size=(rows, cols)).tolist()
    steps = list(d.error_diffusion(d.check_matrix(image, "image", "image"), 255))
    out_total = 255 * sum(s.extra[2] == 255 for s in steps)
    lost = sum(s.extra[3] - sum(c.amount for c in s.extra[4]) for s in steps)
    assert sum(map(sum, image)) == out_total + lost
    interior = [s for s in steps if 0 < s.pixel[0] < cols - 1 and s.pixel[1] < rows - 1]
    assert all(sum(c.amount for c in s.extra[4]) == s.extra[3] for s in interior)


def test_integer_arithmetic_truncates_each_share_toward_zero() -> None:
    # e = 100: 7/16 -> 43 (not 43.75), 5/16 -> 31, 1/16 -> 6; e < 0 truncates toward 0 too
    steps = list(d.error_diffusion(((100, 100), (100, 100)), 255, arithmetic="integer"))
    assert [c.amount for c in steps[0].extra[4]] == [43, 31, 6]
    # (0,1): 100 + 43 = 143 -> 255, e = -112: 3/16 -> -21, 5/16 -> -35 (exact here)
    assert [c.amount for c in steps[1].extra[4]] == [-21, -35]
    # (1,0): 100 + 31 - 21 = 110, e = 110: 7/16 = 48.125 -> 48
    assert [c.amount for c in steps[2].extra[4]] == [48]


def test_clamped_carries_drop_negative_errors() -> None:
    steps = list(d.error_diffusion(((200, 0),), 255, carry="clamped"))
    assert steps[0].extra[3] == -55 and steps[0].extra[4] == ()


@pytest.mark.parametrize("n", [2, 4, 8])
def test_patterns_grow_one_cell_a_level(n: int) -> None:
    previous = d.pattern(n, 0)
    assert sum(map(sum, previous)) == 0
    for level in range(1, n * n + 1):
        p = d.pattern(n, level)
        assert sum(map(sum, p)) == level
        assert all(
            a <= b for ra, rb in zip(previous, p, strict=True) for a, b in zip(ra, rb, strict=True)
        )
        previous = p


def test_pattern_answer_lists_every_level() -> None:
    sol = pattern_solution(2, bits=2)
    assert sol.data["levels"] == 4 * 3 + 1
    assert [r[0] for r in sol.tables[0].rows()] == [0, 1, 2, 3, 4]
    with pytest.raises(InputError):  # any n from 1 to 16 is a cell now; 17 is not
        pattern_solution(17)


@pytest.mark.parametrize(
    ("call", "param"),
    [
        (lambda: ordered_solution([], 2, 1), "image"),
        (lambda: ordered_solution([[1, 2], [3]], 2, 4), "image"),
        (lambda: ordered_solution([[1]], 2, 1, compare="<"), "compare"),
        (lambda: diffusion_solution([[1]], 1, kernel="atkinson"), "kernel"),
        (lambda: diffusion_solution([[0] * 65] * 64, 1), "image"),
    ],
)
def test_bad_input_names_its_parameter(call, param) -> None:
    with pytest.raises(InputError) as info:
        call()
    assert info.value.param == param


def test_a_one_row_image_and_a_one_value_matrix():
    # one row, one column: the smallest images are worked as any other (128 >= 128 on, 60 off)
    assert d.check_matrix([[128, 60]], "image", "image") == ((128, 60),)
    assert d.check_matrix([[7]], "matrix", "matrix") == ((7,),)
    for rows in ([], [[]], [[], [1]]):  # no first row, or an empty one
        with pytest.raises(InputError, match="has no values"):
            d.check_matrix(rows, "image", "image")
    with pytest.raises(InputError, match="every row of the image must have 2 values"):
        d.check_matrix([[1, 2], []], "image", "image")


def test_floyd_steinberg_carries_are_in_one_form() -> None:
    """The carried column printed ``43.75`` in one row and ``49455/1024`` in
    another. Every share is now in the form of the table's other values: 3 decimals (half up),
    a whole number as it is. The shares are worked by hand: e = 100 shares 7/16, 5/16, 1/16 as
    43.75, 31.25, 6.25; then e = 143.75 - 255 = -111.25; then 100 - 111.25 * 7/16."""
    from tests.helpers import run

    out = run(
        "dither", "floyd-steinberg", "--image", "100 100 100; 100 100 100", "--format", "csv"
    ).out
    import csv
    import io
    import re

    rows = list(csv.DictReader(io.StringIO(out)))
    carried = [r["carries"] for r in rows]
    assert carried[0] == "(0, 1) += 43.750, (1, 0) += 31.250, (1, 1) += 6.250"
    assert carried[1] == "(0, 2) += -48.672, (1, 0) += -20.859, (1, 1) += -34.766, (1, 2) += -6.953"
    e2 = Fraction(100) - Fraction(11125, 100) * Fraction(7, 16)
    assert e2 == Fraction(51328125, 10**6)
    assert carried[2] == "(1, 1) += 9.624, (1, 2) += 16.040"  # 3/16 and 5/16 of e2
    amounts = [a for c in carried for a in re.findall(r"\+= (\S+?)(?:,|$)", c)]
    assert amounts and all(re.fullmatch(r"-?\d+(\.\d{3})?", a) for a in amounts), amounts
