"""Anti-aliasing: Wu's line (columns sum to 1, all octants, the bulk version, scikit-image's
line_aa), exact area sampling (intensities sum to the exact area, checked against clipping
each pixel square), supersampling, the ring of a circle, and bad input."""

from __future__ import annotations

import json
import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st
from skimage.draw import line_aa as sk_line_aa

from scanconv.algorithms import raster_fill
from scanconv.algorithms.coverage import (
    MAX_AA_CELLS,
    MAX_SAMPLES,
    area_coverage,
    line_strip,
    quantize,
    region_area,
    ring_area,
    ring_supersample,
    supersample_coverage,
)
from scanconv.algorithms.polygon import fill_pixels, polygon_area
from scanconv.algorithms.wu import wu
from scanconv.answers.process.antialias.sampling import antialias_solution, wu_solution
from scanconv.core.checks import InputError
from scanconv.render import Format, render

from .helpers import run

coord = st.integers(-12, 12)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(x1=coord, y1=coord, x2=coord, y2=coord)
def test_wu_columns_sum_to_one_in_every_octant(x1, y1, x2, y2):
    steps = list(wu(x1, y1, x2, y2))
    assert len(steps) == max(abs(x2 - x1), abs(y2 - y1)) + 1
    for s in steps:
        _, minor, lower, _, i_lo, i_up = s.extra
        assert i_lo + i_up == 1 and 0 <= i_up < 1
        assert math.floor(minor) in (lower[0], lower[1])
    # The end points are drawn at full intensity.
    first, last = steps[0].extra, steps[-1].extra
    assert {first[2], last[2]} == {(x1, y1), (x2, y2)} and first[4] == last[4] == 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(x1=coord, y1=coord, x2=coord, y2=coord)
def test_the_bulk_wu_line_is_the_table(x1, y1, x2, y2):
    xs, ys, v = raster_fill.line_aa(x1, y1, x2, y2)
    table = [
        (p, float(i))
        for s in wu(x1, y1, x2, y2)
        for p, i in ((s.extra[2], s.extra[4]), (s.extra[3], s.extra[5]))
    ]
    assert list(zip(zip(xs.tolist(), ys.tolist(), strict=True), v.tolist(), strict=True)) == table


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(x1=coord, y1=coord, x2=coord, y2=coord)
def test_skimage_line_aa_weights_the_perpendicular_distance(x1, y1, x2, y2):
    """skimage.draw.line_aa (Zingl) draws the same pixel pairs; its intensity is
    ``1 - d cos θ`` where Wu's is ``1 - d`` (d: the distance to the pixel centre along the
    minor axis), so ``1 - sk = (1 - wu) cos θ``."""
    assume((x1, y1) != (x2, y2))
    rr, cc, val = sk_line_aa(y1 + 20, x1 + 20, y2 + 20, x2 + 20)
    theirs = {
        (c - 20, r - 20): v for r, c, v in zip(rr.tolist(), cc.tolist(), val.tolist(), strict=True)
    }
    dmaj, dmin = max(abs(x2 - x1), abs(y2 - y1)), min(abs(x2 - x1), abs(y2 - y1))
    cos = dmaj / math.hypot(dmaj, dmin)
    for s in wu(x1, y1, x2, y2):
        for p, i in ((s.extra[2], s.extra[4]), (s.extra[3], s.extra[5])):
            if p in theirs:
                assert 1 - theirs[p] == pytest.approx((1 - float(i)) * cos, abs=1e-9)
            else:
                assert i == 0 or (1 - float(i)) * cos >= 1 - 1e-9


def test_wu_answer():
    sol = wu_solution(0, 0, 8, 3, levels=8)
    rows = list(sol.steps())
    assert rows[1].extra[1] == Fraction(3, 8)
    assert rows[1].extra[4:] == (Fraction(5, 8), Fraction(3, 8), (4, 3))
    text = "".join(c for c in render(sol, Format.plain) if isinstance(c, str))
    assert "Wu (1991)" in text and "g = dy / dx = 3 / 8 = 3/8" in text
    assert "shades:" in text and text.isascii()
    steep = wu_solution(1, 1, 3, 9)
    assert [c.key for c in steep.columns][1:3] == ["y", "x"]
    data = json.loads("".join(render(steep, Format.json)))
    assert data["algorithm"] == "wu" and data["steps"][0]["i_a"] == 1


# --- exact area sampling ----------------------------------------------------------------


def _clip(poly, axis, bound, keep_below):
    """One Sutherland-Hodgman pass against ``coordinate[axis] <= bound`` (or ``>=``)."""
    out = []
    n = len(poly)
    for i in range(n):
        p, q = poly[i], poly[(i + 1) % n]
        pin = p[axis] <= bound if keep_below else p[axis] >= bound
        qin = q[axis] <= bound if keep_below else q[axis] >= bound
        if pin:
            out.append(p)
        if pin != qin:
            t = Fraction(bound - p[axis]) / (q[axis] - p[axis])
            out.append(tuple(p[k] + t * (q[k] - p[k]) for k in range(2)))
    return out


def _square_area(poly, i, j):
    h = Fraction(1, 2)
    for axis, bound, below in (
        (0, i - h, False),
        (0, i + h, True),
        (1, j - h, False),
        (1, j + h, True),
    ):
        poly = _clip(poly, axis, bound, below)
        if not poly:
            return 0
    return abs(polygon_area(poly))


@pytest.mark.parametrize(
    "pts",
    [
        [(0, 0), (7, 2), (4, 6)],
        [(Fraction(1, 3), 0), (5, Fraction(1, 2)), (6, 5), (2, Fraction(9, 2)), (3, 2)],
        [(0, 0), (6, 0), (6, 5), (3, 2), (0, 5)],
    ],
)
def test_area_sampling_is_the_area_clipped_to_each_pixel_square(pts):
    """For a simple polygon, each pixel's intensity is exactly the area of the polygon
    clipped to the pixel's square (Sutherland-Hodgman, exact fractions)."""
    cov = area_coverage(pts)
    for i in range(-1, 8):
        for j in range(-1, 8):
            assert cov.get((i, j), 0) == _square_area(list(pts), i, j), (i, j)
    assert sum(cov.values()) == abs(polygon_area(pts)) == region_area(pts)


polygons = st.lists(st.tuples(st.integers(-5, 5), st.integers(-5, 5)), min_size=3, max_size=7)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(pts=polygons, rule=st.sampled_from(["even-odd", "nonzero"]))
def test_area_sampled_intensities_sum_to_the_exact_area(pts, rule):
    try:
        cov = area_coverage(pts, rule)
    except InputError:
        assume(False)
        return
    assert all(0 < v <= 1 for v in cov.values())
    assert sum(cov.values(), Fraction(0)) == region_area(pts, rule)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(pts=polygons, rule=st.sampled_from(["even-odd", "nonzero"]))
def test_one_sample_per_pixel_is_the_scan_line_fill(pts, rule):
    try:
        filled = fill_pixels(pts, rule)
    except InputError:
        assume(False)
        return
    cov = supersample_coverage(pts, 1, rule)
    assert set(cov) == set(filled) and set(cov.values()) <= {1}


def test_the_bow_tie_area_under_both_rules():
    bow = [(0, 0), (4, 4), (4, 0), (0, 4)]
    assert region_area(bow) == region_area(bow, "nonzero") == 8
    assert polygon_area(bow) == 0  # the shoelace cancels: why the fill rule is needed


def test_a_line_strip_covers_each_column_once():
    cov = area_coverage(line_strip(0, 0, 8, 3))
    for i in range(1, 8):
        assert sum(v for (x, _), v in cov.items() if x == i) == 1
    assert sum(cov.values()) == 8
    steep = area_coverage(line_strip(1, 1, 3, 9))
    assert sum(steep.values()) == 8


def test_supersampling_approaches_the_area():
    pts = [(0, 0), (7, 2), (4, 6)]
    area = region_area(pts)
    got = sum(supersample_coverage(pts, 16).values())
    assert abs(got - area) < Fraction(1, 4)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_ring_of_a_circle():
    cov = ring_area(5)
    assert sum(cov.values()) == pytest.approx(2 * math.pi * 5, abs=1e-9)
    assert all(0 < v <= 1 for v in cov.values())
    assert cov[(5, 0)] == pytest.approx(cov[(0, 5)]) == pytest.approx(cov[(-5, 0)])
    sup = ring_supersample(5, 8)
    assert abs(float(sum(sup.values())) - 2 * math.pi * 5) < 0.5
    assert set(sup) <= set(cov) | {p for p in sup if sup[p] == 0}


def test_quantize_is_round_half_up():
    assert [quantize(Fraction(k, 14), 8) for k in range(15)] == [
        0,
        1,
        1,
        2,
        2,
        3,
        3,
        4,
        4,
        5,
        5,
        6,
        6,
        7,
        7,
    ]


@pytest.mark.parametrize(
    ("shape", "params", "method"),
    [
        ("line", [0, 0, 8, 3], "area"),
        ("polygon", [0, 0, 7, 2, 4, 6], "supersample"),
        ("circle", [4, 1, 1], "area"),
    ],
)
def test_the_answers_render_in_every_text_format(shape, params, method):
    sol = antialias_solution(shape, params, method=method, samples=3, levels=5)
    for fmt in (Format.plain, Format.markdown, Format.latex, Format.json, Format.csv):
        text = "".join(c for c in render(sol, fmt) if isinstance(c, str))
        assert text
    plain = "".join(c for c in render(sol, Format.plain) if isinstance(c, str))
    assert "Intensities" in plain and "shades:" in plain and plain.isascii()


@pytest.mark.parametrize(
    ("call", "word", "param"),
    [
        (lambda: antialias_solution("line", [0, 0, 0, 0]), "length zero", "line"),
        (lambda: antialias_solution("line", [0, 0, 1]), "x1 y1 x2 y2", "line"),
        (
            lambda: antialias_solution("polygon", [0, 0, 4, 0, 2], method="supersample"),
            "odd",
            "vertices",
        ),
        (
            lambda: antialias_solution(
                "polygon", [0, 0, 4, 0, 2, 3], method="supersample", samples=MAX_SAMPLES + 1
            ),
            f"at most {MAX_SAMPLES}",
            "samples",
        ),
        (
            lambda: antialias_solution(
                "polygon", [0, 0, 4, 0, 2, 3], method="supersample", samples=0
            ),
            "at least 1",
            "samples",
        ),
        (lambda: antialias_solution("polygon", [0, 0, 200, 0, 0, 60]), "pixel cells", "shape"),
        (lambda: antialias_solution("circle", [50]), "pixel cells", "shape"),
        (lambda: antialias_solution("circle", [5], levels=1), "at least 2", "levels"),
        (lambda: antialias_solution("square", [5]), "unknown shape", "shape"),
    ],
)
def test_bad_input_is_refused(call, word, param):
    with pytest.raises(ValueError, match=word) as err:
        call()
    if param is not None:
        assert isinstance(err.value, InputError) and err.value.param == param


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_limits_at_their_edge():
    antialias_solution(
        "polygon", [0, 0, 99, 0, 0, 99], method="supersample", samples=1
    )  # 100 x 100
    assert MAX_AA_CELLS == 100 * 100
    assert len(supersample_coverage([(0, 0), (1, 0), (1, 1)], MAX_SAMPLES)) == 3
    assert np.isclose(sum(ring_area(48).values()), 2 * math.pi * 48)  # 99 x 99 cells


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_line_algo_wu_is_the_antialias_answer():
    """``scanconv line ... --algo wu`` (wu as a line method) prints exactly the Wu answer of
    ``antialias line --method wu``; the derivation and the pipeline refuse it by name."""
    via_line = run("line", "0", "0", "8", "3", "--algo", "wu", "-f", "json")
    via_aa = run("antialias", "line", "0", "0", "8", "3", "--method", "wu", "-f", "json")
    assert via_line.code == via_aa.code == 0 and via_line.out == via_aa.out
    refused = run("line", "0", "0", "8", "3", "--algo", "wu", "--derive")
    assert refused.code == 2 and "not wu" in refused.err and refused.out == ""
    wu_pipe = run(
        "pipeline", "line", "0", "0", "8", "3", "--window", "0", "0", "10", "10",
        "--viewport", "0", "0", "10", "10", "--algo", "wu",
    )  # fmt: skip
    assert wu_pipe.code == 2 and "not wu" in wu_pipe.err
