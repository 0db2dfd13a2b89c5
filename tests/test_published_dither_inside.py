"""Published examples of dithering and of the inside-outside test, reproduced.
Each source states its own algorithm; where it gives numbers they are checked
as printed, where it gives only the rule (no numeric worked example was found for ordered
dither with the 4 x 4 Bayer matrix, nor for Floyd-Steinberg on a small matrix: docs/errata.md,
N2) the rule is applied by hand here to a small image and scanconv must agree.
"""

from __future__ import annotations

import json

import pytest

from .helpers import run

#: Georgia Tech's D(4), printed row by row (the same as Bayer's, scanconv's --matrix 4).
D4 = ((0, 8, 2, 10), (12, 4, 14, 6), (3, 11, 1, 9), (15, 7, 13, 5))
#: A 4 x 4 ramp on the 0..16 scale of D(4) (rows are y, columns x).
RAMP = ((1, 3, 5, 7), (2, 6, 10, 14), (4, 8, 12, 16), (0, 9, 11, 13))


def _json(*args: str) -> dict:
    r = run(*args, "--format", "json")
    assert r.code == 0, r.err
    return json.loads(r.out)


def _image(rows: tuple[tuple[int, ...], ...]) -> str:
    return "; ".join(" ".join(map(str, r)) for r in rows)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_gatech_ordered_dither_rule_and_matrix() -> None:
    """http://www.cc.gatech.edu/gvu/multimedia/nsfmmedia/cware/graphics/notes/ragra/flpol/flpol05.html
    "i = x mod 4, j = y mod 4; then if I(x, y) > D(i, j) the point (x, y) is
    turned on", with D(4) above. The matrix is indexed by x first, so a row-major image takes
    its transpose: scanconv's --transpose, thresholds raw on the 0..16 scale (--top 16)."""
    want = [[int(RAMP[y][x] > D4[x % 4][y % 4]) for x in range(4)] for y in range(4)]
    got = _json("dither", "ordered", "--image", _image(RAMP), "--top", "16", "--matrix", "4",
                "--transpose")["output"]  # fmt: skip
    assert got == want
    # the page's uniform levels: intensity k turns on exactly k of the 16 pixels
    for k in (0, 1, 5, 8, 15, 16):
        flat = _image(((k,) * 4,) * 4)
        out = _json("dither", "ordered", "--image", flat, "--top", "16", "--matrix", "4")["output"]
        assert sum(map(sum, out)) == k


def test_visgraf_one_based_bayer_rule() -> None:
    """https://www.visgraf.impa.br/Courses/ip00/proj/Dithering1/ordered_dithering.html
    Bayer's 4 x 4 pattern counted from 1 (1 9 3 11 / 13 5 15 7 / 4 12 2 10 /
    16 8 14 6); "if the value of the pixel (scaled into the range) is less than the number in
    the corresponding cell of the matrix, plot that pixel black, otherwise white": white when
    value >= entry (scanconv: the matrix given, raw thresholds at top 16, --compare >=)."""
    m = ((1, 9, 3, 11), (13, 5, 15, 7), (4, 12, 2, 10), (16, 8, 14, 6))
    want = [[int(not RAMP[y][x] < m[y][x]) for x in range(4)] for y in range(4)]
    got = _json("dither", "ordered", "--image", _image(RAMP), "--top", "16", "--matrix",
                _image(m), "--compare", ">=")["output"]  # fmt: skip
    assert got == want
    # the same as Bayer's 0-based matrix with --base 1 on whole-number values
    based = _json("dither", "ordered", "--image", _image(RAMP), "--top", "16", "--matrix", "4",
                  "--base", "1")["output"]  # fmt: skip
    assert based == [[int(RAMP[y][x] >= D4[y][x] + 1) for x in range(4)] for y in range(4)]


def test_wikipedia_floyd_steinberg_halfway_gives_a_checkerboard() -> None:
    """https://en.wikipedia.org/wiki/Floyd%E2%80%93Steinberg_dithering
    "if the original pixel values are exactly halfway in between the nearest
    available colors, the dithered result is a checkerboard pattern" (7/16, 3/16, 5/16, 1/16,
    left to right, top to bottom)."""
    for compare in (">=", ">"):
        out = _json("dither", "floyd-steinberg", "--image", _image(((1,) * 6,) * 4), "--top",
                    "2", "--compare", compare)["output"]  # fmt: skip
        assert all(out[i][j] != out[i][j + 1] for i in range(4) for j in range(5))
        assert all(out[i][j] != out[i + 1][j] for i in range(3) for j in range(6))


def test_york_acm_point_in_polygon_sample() -> None:
    """http://www.cse.yorku.ca/acm/Problems/2010-03-19/PointInAPolygon.txt
    the sample input "0 0 4 0 0 0 10 10 10 10 0", "5 5 4 ...", "11 10 4 ..." (the
    point, then the clockwise square (0,0) (0,10) (10,10) (10,0)) prints true, true, false:
    the vertex (0, 0) counts as within (scanconv's --boundary inside, the default)."""
    data = _json("inside", "0", "0", "0", "10", "10", "10", "10", "0", "--points", "0", "0", "5",
                 "5", "11", "10")  # fmt: skip
    for rule in ("even_odd", "nonzero"):
        assert [v[rule] for v in data["verdicts"]] == [True, True, False]


def test_checkio_inside_block_examples() -> None:
    """https://py.checkio.org/en/mission/inside-block/
    is_inside(((1,1),(1,3),(3,3),(3,1)), (2,2)) == True and (4,2) == False; the
    polygon ((2,1),(1,5),(5,7),(7,7),(7,2)) and the point (2,7): False; "if the point lies on
    the edge of the polygon then it should be considered inside"."""
    data = _json("inside", "1", "1", "1", "3", "3", "3", "3", "1", "--points", "2", "2", "4", "2",
                 "3", "2")  # fmt: skip
    assert [v["even_odd"] for v in data["verdicts"]] == [True, False, True]  # (3, 2): on an edge
    data = _json("inside", "2", "1", "1", "5", "5", "7", "7", "7", "7", "2", "--points", "2", "7")
    assert [v["even_odd"] for v in data["verdicts"]] == [False]
    assert [v["nonzero"] for v in data["verdicts"]] == [False]
