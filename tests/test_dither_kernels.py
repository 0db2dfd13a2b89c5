"""The error-diffusion kernels beyond Floyd-Steinberg, a threshold looked up by screen position
and a threshold matrix given in the image's units: each against the kernel tables as
published and an independent error diffusion written here."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms import dither as d
from scanconv.answers.image.dither import diffusion_solution, lookup_solution, ordered_solution
from scanconv.core.checks import InputError

# The kernels as T. Helland, "Image Dithering: Eleven Algorithms and Source Code" (2012) and
# L. Crocker's DHALF.TXT (1989) print them: rows from the current one down, columns j-2 .. j+2,
# "X" the current pixel (None: a pixel already visited, no share), over the divisor.
X = None
PUBLISHED: dict[str, tuple[int, list[list[int | None]]]] = {
    "floyd-steinberg": (16, [[X, X, X, 7, 0], [0, 3, 5, 1, 0]]),
    "jarvis-judice-ninke": (48, [[X, X, X, 7, 5], [3, 5, 7, 5, 3], [1, 3, 5, 3, 1]]),
    "stucki": (42, [[X, X, X, 8, 4], [2, 4, 8, 4, 2], [1, 2, 4, 2, 1]]),
    "burkes": (32, [[X, X, X, 8, 4], [2, 4, 8, 4, 2]]),
    "sierra": (32, [[X, X, X, 5, 3], [2, 4, 5, 4, 2], [0, 2, 3, 2, 0]]),
    "two-row-sierra": (16, [[X, X, X, 4, 3], [1, 2, 3, 2, 1]]),
    "sierra-lite": (4, [[X, X, X, 2, 0], [0, 1, 1, 0, 0]]),
    # the simple kernel taught as Floyd-Steinberg's, and the 1-D scheme (libcaca study, part 3:
    # "propagates 100% of the error to the next (right) pixel")
    "simple": (8, [[X, X, X, 3, 0], [0, 0, 3, 2, 0]]),
    "one-dimensional": (1, [[X, X, X, 1, 0]]),
}


def _published(name: str) -> dict[tuple[int, int], Fraction]:
    divisor, rows = PUBLISHED[name]
    return {
        (di, dj - 2): Fraction(w, divisor)
        for di, row in enumerate(rows)
        for dj, w in enumerate(row)
        if w
    }


def test_every_kernel_is_tabled_here() -> None:
    assert set(d.DITHER_KNOBS["kernel"]) == set(PUBLISHED) == set(d.KERNELS)
    assert all(k.name == name and k.source for name, k in d.KERNELS.items())


@pytest.mark.parametrize("name", sorted(PUBLISHED))
def test_kernel_weights_are_the_published_table(name: str) -> None:
    got = {(s.di, s.dj): s.weight for s in d.KERNELS[name].shares}
    assert got == _published(name)
    assert all(isinstance(w, Fraction) for w in got.values())
    assert sum(got.values()) == 1  # the error is moved, not lost
    assert all(di > 0 or dj > 0 for di, dj in got)  # only pixels not yet visited
    assert d.KERNELS[name].divisor == PUBLISHED[name][0]


def _oracle(image: list[list[int]], top: int, name: str, serpentine: bool) -> list[list[Fraction]]:
    """Error diffusion in place, from the published table, mirrored on reversed rows: the
    image of values (plus received error) each pixel is decided on, and its outputs."""
    weights = _published(name)
    px = [[Fraction(v) for v in row] for row in image]
    h, w = len(px), len(px[0])
    out = [[Fraction(0)] * w for _ in range(h)]
    for y in range(h):
        back = serpentine and y % 2 == 1
        for x in range(w - 1, -1, -1) if back else range(w):
            new = top if px[y][x] >= Fraction(top, 2) else 0
            out[y][x] = Fraction(new)
            err = px[y][x] - new
            for (dy, dx), wgt in weights.items():
                tx = x - dx if back else x + dx
                if 0 <= y + dy < h and 0 <= tx < w:
                    px[y + dy][tx] += err * wgt
    return out


_IMAGES = given(
    name=st.sampled_from(sorted(PUBLISHED)),
    rows=st.integers(1, 6),
    cols=st.integers(1, 6),
    seed=st.integers(0, 2**32 - 1),
    serpentine=st.booleans(),
)
"""A kernel, a random image of 1..6 x 1..6 gray levels (its seed) and the scan order."""


def _lost_weight(name: str, rows: int, cols: int, serpentine: bool) -> Fraction:
    """The kernel weight of every pixel's shares that fall outside the image, summed."""
    total = Fraction(0)
    for y in range(rows):
        sign = -1 if serpentine and y % 2 else 1
        for x in range(cols):
            for (dy, dx), wgt in _published(name).items():
                if not (0 <= y + dy < rows and 0 <= x + sign * dx < cols):
                    total += wgt
    return total


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=60)
@_IMAGES
def test_every_kernel_equals_the_published_table_applied_by_hand(
    name, rows, cols, seed, serpentine
) -> None:
    image = np.random.default_rng(seed).integers(0, 256, size=(rows, cols)).tolist()
    order = "serpentine" if serpentine else "raster"
    sol = diffusion_solution(image, 255, kernel=name, order=order)
    expected = _oracle(image, 255, name, serpentine)
    assert sol.data["output"] == [[int(v == 255) for v in row] for row in expected]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=60)
@_IMAGES
def test_every_kernel_preserves_the_mean_within_its_bound(
    name, rows, cols, seed, serpentine
) -> None:
    """The stated bound: each error is at most top/2 in size (inputs in 0..top, weights >= 0
    summing to 1), so the input's total less the output's is at most top/2 times the weight
    that falls off the image; and it is exactly the shares lost there."""
    image = np.random.default_rng(seed).integers(0, 256, size=(rows, cols)).tolist()
    order = "serpentine" if serpentine else "raster"
    steps = list(
        d.error_diffusion(d.check_matrix(image, "image", "image"), 255, kernel=name, order=order)
    )
    assert all(abs(s.extra[3]) <= Fraction(255, 2) for s in steps)
    out_total = 255 * sum(s.extra[2] == 255 for s in steps)
    lost = sum(s.extra[3] - sum(c.amount for c in s.extra[4]) for s in steps)
    assert sum(map(sum, image)) == out_total + lost
    bound = Fraction(255, 2) * _lost_weight(name, rows, cols, serpentine)
    assert abs(sum(map(sum, image)) - out_total) <= bound
    assert d.lost_weight(name, rows, cols, order) == _lost_weight(name, rows, cols, serpentine)


def test_one_dimensional_diffusion_of_half_grey_alternates() -> None:
    # Hocevar, libcaca study part 3: the 1-D scheme thresholds at 0.5 and carries all of the
    # error to the next pixel, so a row of 0.5 comes out 1 0 1 0 ...
    sol = diffusion_solution([[Fraction(1, 2)] * 6], 1, kernel="one-dimensional")
    assert sol.data["output"] == [[1, 0, 1, 0, 1, 0]]
    # each row starts afresh: no share reaches the next row
    two = diffusion_solution([[Fraction(1, 2)] * 3] * 2, 1, kernel="one-dimensional")
    assert two.data["output"] == [[1, 0, 1], [1, 0, 1]]


def test_a_kernels_answer_names_its_weights_and_source() -> None:
    sol = diffusion_solution([[100, 100, 100], [100, 100, 100]], 255, kernel="stucki")
    kernel = next(q for q in sol.derived if q.key == "kernel")
    assert "8/42 \\text{ to } (i+0, j+1)" in kernel.tex and "1/42" in kernel.tex
    assert any("Stucki" in n and "over 42" in n for n in sol.notes)


def test_an_unknown_kernel_is_refused_naming_the_choices() -> None:
    with pytest.raises(InputError, match="jarvis-judice-ninke"):
        diffusion_solution([[1]], 1, kernel="atkinson")


# Bayer's 4 x 4 matrix as Wikipedia ("Ordered dithering") prints it, and its rule: the
# threshold of the pixel at (x, y) is M(x mod n, y mod n), M indexed row y, column x.
BAYER4 = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]]


@given(x=st.integers(0, 200), y=st.integers(0, 200), one=st.booleans())
def test_a_lookup_is_the_published_matrix_at_the_position_mod_n(x, y, one) -> None:
    c = int(one)
    sol = lookup_solution([(x + c, y + c)], 4, 16, count=str(c))
    assert sol.data["lookups"] == [BAYER4[y % 4][x % 4]]
    row = next(iter(sol.steps())).extra
    assert row[:6] == (x + c, y + c, y, x, y % 4, x % 4)


def test_a_lookup_decides_the_pixel_by_the_comparison() -> None:
    # T = D * 255 / 16 with raw thresholds: (5, 2) -> D[2][1] = 11 -> 175.3125
    sol = lookup_solution([(5, 2), (0, 0)], 4, 255, value=100)
    assert sol.data["lookups"] == [Fraction(2805, 16), 0]
    assert sol.data["output"] == [0, 1]
    assert lookup_solution([(0, 0)], 4, 255, value=0, compare=">=").data["output"] == [1]


def test_a_position_before_the_first_is_refused() -> None:
    with pytest.raises(InputError, match="count from 1"):
        lookup_solution([(0, 3)], 4, 16, count="1")


def test_a_matrix_given_in_the_images_units_is_used_as_it_is() -> None:
    # thresholds given directly (on 0..255): no scaling, the base ignored
    given = [[32, 160], [224, 96]]
    sol = ordered_solution([[100, 100], [200, 100]], given, 255, scale="given")
    assert sol.data["thresholds"] == given
    assert sol.data["output"] == [[1, 0], [0, 1]]
    raw = ordered_solution([[100, 100], [200, 100]], given, 255)
    assert raw.data["thresholds"] != given


def _mark(tmp_path, text: str, question: str) -> dict:
    from scanconv.questions.marking import check

    path = tmp_path / "s.csv"
    path.write_text(text, encoding="utf-8")
    return check(path, question).data


def test_check_follows_a_slip_through_a_new_kernel(tmp_path) -> None:
    q = "dither floyd-steinberg --image '100 100 100' --top 255 --kernel one-dimensional"
    right = (
        "i,j,received,value,output,error\n0,0,0,100,0,100\n0,1,100,200,255,-55\n0,2,-55,45,0,45\n"
    )
    assert _mark(tmp_path, right, q)["score"] == 3
    # the first error written 90, not 100: the rest worked on from it (by hand: 90 carried,
    # 190 -> 255, e = -65; then 100 - 65 = 35 -> 0, e = 35) costs that one row only
    slip = "i,j,received,value,output,error\n0,0,0,100,0,90\n0,1,90,190,255,-65\n0,2,-65,35,0,35\n"
    data = _mark(tmp_path, slip, q)
    assert (data["score"], data["out_of"]) == (2, 3)


def test_check_marks_a_lookup_row_by_row(tmp_path) -> None:
    q = "dither lookup 5 2 6 3 --matrix 4 --value 100"
    # by hand: (5, 2) -> D[2][1] = 11 -> 11 x 255/16 = 2805/16; (6, 3) -> D[3][2] = 13 -> 3315/16
    right = "x,y,i mod 4,j mod 4,T,output\n5,2,2,1,2805/16,0\n6,3,3,2,3315/16,0\n"
    assert _mark(tmp_path, right, q)["score"] == 2
    wrong = right.replace("3,2,3315/16", "2,3,2295/16")  # rows and columns swapped
    assert _mark(tmp_path, wrong, q)["score"] == 1


def test_a_published_lookup_counted_from_one() -> None:
    # askfilo.com, question 3337323934393735 ("Question 4 (b)"): the 3 x 3 dither matrix
    # [5 2 7; 1 0 3; 6 8 4], the pixel at row 2, column 19 (counted from 1): i = ((2-1) mod 3)+1
    # = 2, j = ((19-1) mod 3)+1 = 1, T = M(2, 1) = 1; compared with the intensity directly.
    sol = lookup_solution(
        [(19, 2)], [[5, 2, 7], [1, 0, 3], [6, 8, 4]], 8, value=5, count="1", scale="given"
    )
    assert sol.data["lookups"] == [1] and sol.data["output"] == [1]
    row = next(iter(sol.steps())).extra
    assert row[4:6] == (1, 0)  # (i mod 3, j mod 3) from 0: the published (2, 1) from 1


def test_the_published_rule_indexed_by_x_first_is_the_transpose() -> None:
    # Georgia Tech's graphics notes (flpol05): i = x mod 4, j = y mod 4, on when
    # l(x, y) > D(i, j) with D(4) = BAYER4 (indexed row i): D read by x first.
    for x, y in [(5, 2), (1, 3), (7, 7), (2, 0)]:
        sol = lookup_solution([(x, y)], 4, 16, transpose=True)
        assert sol.data["lookups"] == [BAYER4[x % 4][y % 4]]
