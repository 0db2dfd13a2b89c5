"""``bspline --basis --at t``: a B-spline basis given by its degree and knots alone, evaluated
at one t with every Cox–de Boor step worked; against a published table, an
independent recursive Cox–de Boor and the partition of unity."""

from __future__ import annotations

import json
from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv import _api as api
from scanconv.answers.curves.bspline_basis import bspline_basis_at_solution

from .helpers import run

SHENE = [F(0), F(1, 4), F(1, 2), F(3, 4), F(1)]
"""C.-K. Shene, "B-spline Basis Functions: Computation Examples", CS3621 notes, Michigan Tech
(https://pages.mtu.edu/~shene/COURSES/cs3621/NOTES/spline/bspline-ex-1.html): "Simple
Knots", U = {0, 0.25, 0.5, 0.75, 1}."""


def shene_degree_2(t: F) -> tuple[F, F]:
    """Shene's printed N_0,2 and N_1,2, piece by piece (the page's table), with N_1,2 on
    [0.5, 0.75) as -5.5 + 20u - 16u^2 (the page prints -1.5 + 8u - 8u^2: docs/errata.md, P2)."""
    if t < F(1, 4):
        return 8 * t * t, F(0)
    if t < F(1, 2):
        return F(-3, 2) + 12 * t - 16 * t * t, F(1, 2) - 4 * t + 8 * t * t
    if t < F(3, 4):
        return F(9, 2) - 12 * t + 8 * t * t, F(-11, 2) + 20 * t - 16 * t * t
    return F(0), 8 * (1 - t) ** 2


def shene_degree_1(t: F) -> tuple[F, F, F]:
    """Shene's printed N_0,1, N_1,1, N_2,1, with N_1,1 on [0.5, 0.75) as 3 - 4u (the page
    prints "3 - u": docs/errata.md, P1)."""
    if t < F(1, 4):
        return 4 * t, F(0), F(0)
    if t < F(1, 2):
        return 2 * (1 - 2 * t), 4 * t - 1, F(0)
    if t < F(3, 4):
        return F(0), 3 - 4 * t, 2 * (2 * t - 1)
    return F(0), F(0), 4 * (1 - t)


@pytest.mark.parametrize("t", [F(k, 16) for k in range(16)])
def test_shenes_simple_knots_table_is_reproduced(t):
    sol = api.bspline_at(None, t, 2, SHENE)
    assert tuple(sol.data["basis"]) == shene_degree_2(t)
    degree_1 = api.bspline_at(None, t, 1, SHENE)
    assert tuple(degree_1.data["basis"]) == shene_degree_1(t)


def test_shenes_printed_n11_is_a_typo():
    # "3 - u" would be 2.4 at u = 0.6, above 1; the recursion gives (0.75 - u)/0.25 = 3 - 4u
    value = api.bspline_at(None, F(3, 5), 1, SHENE).data["basis"][1]
    assert value == 3 - 4 * F(3, 5) != 3 - F(3, 5)


def test_shenes_printed_n12_middle_piece_is_wrong():
    # the printed -1.5 + 8u - 8u^2 is 0 at u = 0.75 where the next printed piece 8(1 - u)^2 is
    # 1/2: N_1,2 would jump; the recursion's piece is N_0,2's mirror image (u -> 1 - u)
    printed = lambda u: F(-3, 2) + 8 * u - 8 * u * u  # noqa: E731
    assert printed(F(3, 4)) == 0 != 8 * (1 - F(3, 4)) ** 2
    for k in range(9, 12):
        u = F(k, 16)
        ours = api.bspline_at(None, u, 2, SHENE).data["basis"]
        assert ours[1] == shene_degree_2(1 - u)[0] != printed(u)


def cox_de_boor(u: list[F], i: int, d: int, t: F) -> F:
    """The recursion as textbooks print it, evaluated naively (every term, 0/0 = 0), with the
    right end of the knot range in the last non-empty span (independent of the triangle)."""
    if d == 0:
        last = max(j for j in range(len(u) - 1) if u[j] < u[j + 1])
        if u[i] <= t < u[i + 1] or (t == u[-1] and i == last):
            return F(1)
        return F(0)
    left = (t - u[i]) / (u[i + d] - u[i]) * cox_de_boor(u, i, d - 1, t) if u[i + d] != u[i] else 0
    right = (
        (u[i + d + 1] - t) / (u[i + d + 1] - u[i + 1]) * cox_de_boor(u, i + 1, d - 1, t)
        if u[i + d + 1] != u[i + 1]
        else 0
    )
    return F(left + right)


@st.composite
def knots_and_t(draw):
    degree = draw(st.integers(1, 3))
    gaps = draw(st.lists(st.integers(0, 3), min_size=degree + 2, max_size=degree + 6))
    u = [F(0)]
    for g in gaps:
        u.append(u[-1] + g)
    if u[-1] == 0 or any(u.count(v) > degree + 1 for v in set(u)):
        u = list(range(len(u)))
    u = [F(v) for v in u]
    t = draw(st.fractions(min_value=u[0], max_value=u[-1], max_denominator=12))
    return degree, u, t


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=100)
@given(knots_and_t())
def test_every_value_equals_the_naive_recursion(case):
    degree, u, t = case
    sol = bspline_basis_at_solution(degree, u, t)
    n = len(u) - degree - 2
    assert list(sol.data["basis"]) == [cox_de_boor(u, i, degree, t) for i in range(n + 1)]
    for d, i, _, value in sol.tables[0].rows():
        assert value == cox_de_boor(u, i, d, t)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=100)
@given(knots_and_t())
def test_the_basis_sums_to_one_inside_the_domain(case):
    degree, u, t = case
    n = len(u) - degree - 2
    sol = bspline_basis_at_solution(degree, u, t)
    total = sum(sol.data["basis"])
    if u[degree] <= t <= u[n + 1] and u[degree] < u[n + 1]:
        assert total == 1
    else:
        assert 0 <= total <= 1


def test_the_working_shows_the_numbers_and_zero_over_zero():
    sol = bspline_basis_at_solution(2, [0, 0, 0, F(3, 10), F(1, 2), F(1, 2), F(3, 5), 1, 1, 1],
                                    F(1, 2))  # fmt: skip
    rows = {(d, i): (w, v) for d, i, w, v in sol.tables[0].rows()}
    assert rows[(1, 4)] == ("0 (u = 0.5 twice: 0/0 = 0) + (0.6 - 0.5)/(0.6 - 0.5)·1", 1)
    assert rows[(2, 3)][1] == 1


def test_the_cli_answers_without_control_points():
    r = run("bspline", "--basis", "--degree", "2", "--knots", "0,.25,.5,.75,1", "--at", "3/8",
            "-f", "json")  # fmt: skip
    assert r.code == 0, r.err
    out = json.loads(r.out)
    assert out["derived"]["basis"] == [0.75, 0.125]


@pytest.mark.parametrize(
    ("args", "word"),
    [
        (("--knots", "0,1,2,3", "--at", "5"), "knot range"),
        (("--at", "1"), "explicit knot list"),
        (("--knots", "0,1", "--at", "1/2"), "at least"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args, word):
    r = run("bspline", "--basis", "--degree", "2", *args)
    assert r.code == 2 and not r.out and word in r.err and len(r.err.splitlines()) == 1
