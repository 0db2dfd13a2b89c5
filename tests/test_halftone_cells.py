"""Halftone cells of any size (n x n for n = 1 .. 16, Bayer-ordered, clustered or given) and a
printer's halftone arithmetic (dpi, lpi, cell, levels): against independent computations and
the published figures."""

from __future__ import annotations

import itertools
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from scanconv.algorithms import dither as d
from scanconv.answers.image.dither import pattern_solution
from scanconv.answers.image.halftone import printer_solution
from scanconv.core.checks import InputError


def _closed_form_bayer(n: int) -> list[list[int]]:
    """Bayer's matrix of a power of 2 from its closed form (bit interleave of i XOR j and i)."""
    out = [[0] * n for _ in range(n)]
    for i in range(n):
        for j in range(n):
            v = 0
            for k in range(n.bit_length() - 1):
                v = (v << 2) | (((i ^ j) >> k & 1) << 1) | (i >> k & 1)
            out[i][j] = v
    return out


def _ranked_block(n: int) -> list[list[int]]:
    """The top-left n x n block of the next power of 2's Bayer matrix, its entries ranked."""
    side = 1
    while side < n:
        side *= 2
    block = [row[:n] for row in _closed_form_bayer(side)[:n]]
    order = sorted(v for row in block for v in row)
    return [[order.index(v) for v in row] for row in block]


@pytest.mark.parametrize("n", range(1, 17))
def test_the_bayer_order_of_any_cell_is_the_ranked_block_of_the_next_bayer_matrix(n: int) -> None:
    assert [list(r) for r in d.cell_order(n)] == _ranked_block(n)
    if n & (n - 1) == 0 and n > 1:
        assert [list(r) for r in d.cell_order(n)] == _closed_form_bayer(n)


@given(n=st.integers(1, 16), order=st.sampled_from(["bayer", "clustered"]))
def test_an_n_by_n_cell_gives_n_squared_plus_one_nested_levels(n: int, order: str) -> None:
    sol = pattern_solution(n, order=order)
    patterns = sol.data["patterns"]
    assert sol.data["levels"] == n * n + 1 == len(patterns)
    cells = [{(i, j) for i in range(n) for j in range(n) if patterns[lv][i][j]} for lv in patterns]
    assert [len(c) for c in cells] == list(range(n * n + 1))  # level l: l dots on
    assert all(a < b for a, b in itertools.pairwise(cells))  # each inside the next


@given(n=st.integers(1, 16))
def test_a_clustered_cell_grows_from_its_centre(n: int) -> None:
    ranks = d.cell_order(n, "clustered")
    c = Fraction(n - 1, 2)
    by_rank = sorted((ranks[i][j], (i - c) ** 2 + (j - c) ** 2) for i in range(n) for j in range(n))
    distances = [dist for _, dist in by_rank]
    assert distances == sorted(distances)


def test_a_cell_order_given_counts_from_0_or_1() -> None:
    # a 3 x 3 order written from 1 (the centre first) is the same cell as written from 0
    one = pattern_solution(3, matrix=[[7, 9, 5], [2, 1, 4], [6, 3, 8]])
    zero = pattern_solution(3, matrix=[[6, 8, 4], [1, 0, 3], [5, 2, 7]])
    assert one.data["patterns"] == zero.data["patterns"]
    assert zero.data["patterns"][1] == [[0, 0, 0], [0, 1, 0], [0, 0, 0]]
    with pytest.raises(InputError, match=r"0 \.\. 8 once each"):
        pattern_solution(3, matrix=[[0, 0, 1], [2, 3, 4], [5, 6, 7]])
    with pytest.raises(InputError, match="2 wide, not 3"):
        pattern_solution(3, matrix=[[0, 1], [2, 3]])


def test_halftone_5_is_answered_and_17_refused() -> None:
    assert pattern_solution(5).data["levels"] == 26
    with pytest.raises(InputError, match=r"1 \.\. 16"):
        pattern_solution(17)


# Stanford CS248, Winter 1996 midterm, question 2B (graphics.stanford.edu, with its answer): a
# 300 dpi laser printer with 10, 60 or 150 halftone cells per inch: 30 x 30 cells -> 901
# levels, 5 x 5 -> 26, 2 x 2 -> 5.
@pytest.mark.parametrize(("lpi", "n", "levels"), [(10, 30, 901), (60, 5, 26), (150, 2, 5)])
def test_the_stanford_1996_midterm(lpi: int, n: int, levels: int) -> None:
    data = printer_solution(300, lpi).data
    assert (data["n"], data["levels"]) == (n, levels)


def test_published_cell_figures() -> None:
    # T. Autiokari, "Printing halftones" (aim-dtp.net): an 8 x 8 cell gives 8 * 8 + 1 = 65
    # levels, levels = (dpi / lpi)^2 + 1; qualityinprint.blogspot.com (2009): 10 x 10 -> 101,
    # 16 x 16 -> 257, and 2400 dpi at 100 lpi -> 24 x 24 -> 577.
    assert printer_solution(800, 100).data["levels"] == 65
    assert printer_solution(1000, cell=10).data["levels"] == 101
    assert printer_solution(2400, 100).data["levels"] == 577
    # PCMag encyclopedia, "halftone": 300 dpi with an 8 x 8 cell: 64 shades (n^2) at 300 / 8
    # (printed as 38) lpi; 2400 dpi with 16 x 16: 256 shades at 150 lpi.
    pc = printer_solution(300, cell=8, count="n2").data
    assert (pc["levels"], pc["lpi"]) == (64, Fraction(75, 2))
    assert printer_solution(2400, cell=16, count="n2").data["lpi"] == 150
    # Erratum: the same table gives 150 lpi for a 4 x 4 cell at 300 dpi (300 / 4 = 75) and
    # 130 lpi for 8 x 8 at 1200 dpi (1200 / 8 = 150).
    assert printer_solution(300, cell=4).data["lpi"] == 75
    assert printer_solution(1200, cell=8).data["lpi"] == 150


@given(dpi=st.integers(1, 4096), lpi=st.integers(1, 4096))
def test_the_cell_from_dpi_and_lpi_is_the_whole_dots_and_inverts(dpi: int, lpi: int) -> None:
    if lpi > dpi:
        with pytest.raises(InputError, match="finer"):
            printer_solution(dpi, lpi)
        return
    data = printer_solution(dpi, lpi).data
    n = data["n"]
    assert n * lpi <= dpi < (n + 1) * lpi  # whole dots: floor
    assert data["levels"] == n * n + 1
    back = printer_solution(lpi=lpi, cell=n).data
    assert back["dpi"] == n * lpi and back["levels"] == data["levels"]
    assert printer_solution(dpi, cell=n).data["lpi"] == Fraction(dpi, n)


@given(levels=st.integers(2, 10**6), count=st.sampled_from(["n2+1", "n2"]))
def test_the_cell_for_a_number_of_levels_is_the_smallest(levels: int, count: str) -> None:
    extra = 1 if count == "n2+1" else 0
    n = printer_solution(600, levels=levels, count=count).data["n"]
    smallest = next(k for k in range(1, 2000) if k * k + extra >= levels)
    assert n == smallest


def test_bad_printer_questions_are_refused() -> None:
    with pytest.raises(InputError, match="two of"):
        printer_solution(300)
    with pytest.raises(InputError, match="two of"):
        printer_solution(300, 60, cell=5)
    with pytest.raises(InputError, match="not both"):
        printer_solution(300, cell=5, levels=26)
    with pytest.raises(InputError, match="count"):
        printer_solution(300, 60, count="n")
