"""The named conventions (knobs and presets), the notes' layout, and the notes' own
computational examples run by their stated algorithms."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from scanconv import _api as api
from scanconv.algorithms import circles, ellipses, lines
from scanconv.algorithms.conventions import KNOBS, PRESETS, ROUNDINGS, resolve
from scanconv.core.checks import InputError

from .helpers import assert_refused, run

coord = st.integers(-40, 40)

# --- each knob changes only what it should ----------------------------------------------------


@given(coord, coord, coord, coord)
def test_line_tie_changes_pixels_only_where_p_is_zero(x1, y1, x2, y2):
    step = list(lines.bresenham(x1, y1, x2, y2, "step"))
    keep = list(lines.bresenham(x1, y1, x2, y2, "keep"))
    assert len(step) == len(keep)
    first = next((i for i, (a, b) in enumerate(zip(step, keep, strict=True)) if a != b), None)
    if first is None:
        assert all(s.p != 0 for s in step)
    else:  # the walks agree up to the first tie, which the two rules decide differently
        assert step[first].p == keep[first].p == 0
        assert step[first].decision != keep[first].decision
    if step:
        assert step[-1].pixel == keep[-1].pixel  # both end on the end point


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(st.integers(0, 300))
def test_circle_tie_changes_points_only_where_p_is_zero(r):
    for gen in (circles.midpoint, circles.bresenham, circles.general):
        step, keep = list(gen(r, "step")), list(gen(r, "keep"))
        first = next((i for i, (a, b) in enumerate(zip(step, keep, strict=False)) if a != b), None)
        if first is None:
            assert len(step) == len(keep)
            assert all(s.p != 0 for s in step if s.decision is not None)
        else:
            assert step[first].p == keep[first].p == 0


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@given(st.integers(0, 500))
def test_p0_five_quarters_decides_as_one_minus_r_with_strict_ties(r):
    a = list(circles.midpoint(r, p0="1-r"))
    b = list(circles.midpoint(r, p0="5/4-r"))
    assert [s.pixel for s in a] == [s.pixel for s in b]
    assert all(sb.p - sa.p == Fraction(1, 4) for sa, sb in zip(a, b, strict=True))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@given(st.integers(0, 500))
def test_update_changes_the_working_only(r):
    assert list(circles.midpoint(r, update="old")) == list(circles.midpoint(r, update="new"))
    new = api.circle(r, update="new")
    old = api.circle(r, update="old")
    assert list(new.pixels()) == list(old.pixels())
    assert [q.tex for q in new.derived] != [q.tex for q in old.derived]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(st.integers(0, 300))
def test_inclusive_loop_only_extends_the_strict_walk(r):
    for gen in (circles.midpoint, circles.general):
        strict = list(gen(r, loop="strict"))
        inclusive = list(gen(r, loop="inclusive"))
        if gen is circles.general:  # its last row is the stop point, with no decision
            strict = strict[:-1]
        assert inclusive[: len(strict)] == strict
    sol = api.circle(r, loop="inclusive")
    px = list(sol.pixels())
    assert len(px) == len(set(px))


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(st.integers(0, 40), st.integers(0, 40))
def test_ellipse_loop_changes_region_one_only_on_an_equal_boundary(rx, ry):
    strict = list(ellipses.midpoint_ellipse(rx, ry, "strict"))
    inclusive = list(ellipses.midpoint_ellipse(rx, ry, "inclusive"))
    region1 = [s for s in strict if s.extra[0] == 1]
    # the loop test is made after each step, on 2ry²x and 2rx²y as the step leaves them
    tx, ty = (region1[-1].extra[1], region1[-1].extra[2]) if region1 else (0, 2 * rx * rx * ry)
    if strict != inclusive:
        assert tx == ty and ry > 0
    assert ellipses.region1_end(rx, ry, "inclusive") == (
        next((s.pixel for s in reversed(inclusive) if s.extra[0] == 1), (0, ry))
    )


halves = st.fractions(min_value=-30, max_value=30, max_denominator=4)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(halves, halves, halves, halves, st.sampled_from(sorted(ROUNDINGS)))
def test_dda_rounding_changes_pixels_only_at_halves_or_negatives(x1, y1, x2, y2, rounding):
    base = list(lines.dda(x1, y1, x2, y2))
    other = list(lines.dda(x1, y1, x2, y2, rounding))
    for a, b in zip(base, other, strict=True):
        assert a.extra[:2] == b.extra[:2]  # the exact values never change
        for v, pa, pb in zip(a.extra[:2], a.pixel, b.pixel, strict=True):
            if pa != pb:
                frac = Fraction(v) - int(Fraction(v))
                assert frac.denominator == 2 or v < 0 or rounding == "trunc"


# --- presets -------------------------------------------------------------------------------


def test_every_preset_sets_only_knobs_that_exist():
    for preset in PRESETS.values():
        for knobs in preset.values():
            for name, value in knobs.items():
                assert value in KNOBS[name].values


def test_presets_reproduce_their_sources_tables():
    # Hearn & Baker, the midpoint circle, r = 10: p_k = -9, -6, -1, 6, -3, 8, 5
    hb = api.circle(10, convention="hearn-baker", layout="textbook")
    assert [s.p for s in hb.steps()] == [-9, -6, -1, 6, -3, 8, 5]
    # Foley: p0 = 5/4 - r, increments with the old x; the same decisions
    fo = api.circle(10, convention="foley", layout="textbook")
    assert [s.p - Fraction(1, 4) for s in fo.steps()] == [-9, -6, -1, 6, -3, 8, 5]
    assert any("2x_k + 3" in q.tex for q in fo.derived)
    # The widely copied "if D > 0 step y" (Wikipedia, Foley's MidpointLine): ties keep y
    wk = api.line(0, 0, 4, 2, convention="wikipedia")
    assert list(wk.pixels()) == [(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)]
    nt = api.line(0, 0, 4, 2, convention="notes")
    assert list(nt.pixels()) == [(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)]


def test_an_explicit_knob_overrides_the_preset():
    assert resolve("line", "bresenham", "wikipedia", {"tie": "step"}) == {
        "tie": "step",
        "start": "swap",
    }


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_answers_state_their_conventions_in_every_format():
    for fmt in ("plain", "markdown", "latex", "json", "rich"):
        r = run("line", "2", "2", "10", "6", "--convention", "foley", "-f", fmt)
        assert r.code == 0 and "foley" in r.out.lower() and "tie" in r.out, fmt


# --- the notes' layout ---------------------------------------------------------------------


def test_notes_layout_keeps_every_value_and_pixel():
    a = json.loads(run("line", "2", "8", "10", "4", "-f", "json").out)
    b = json.loads(run("line", "2", "8", "10", "4", "--layout", "textbook", "-f", "json").out)
    assert a["pixels"] == b["pixels"]
    assert [s["p"] for s in a["steps"][:-1]] == [s["p"] for s in b["steps"]]
    assert [s["pixel"] for s in a["steps"]] == a["pixels"]  # row 0 is the start pixel


# --- the notes' computational examples, by their stated algorithms -------------------------


def test_notes_bresenham_line_2_2_10_6():
    sol = api.line(2, 2, 10, 6, convention="notes")
    rows = [(s.k, s.p, s.decision and s.decision.value, s.pixel) for s in sol.steps()]
    assert rows[0] == (0, 0, "NE", (2, 2)) and rows[-1] == (8, 0, None, (10, 6))
    assert [r[1] for r in rows] == [0, -8, 0, -8, 0, -8, 0, -8, 0]
    assert any("E1" in n for n in sol.notes)


def test_notes_dda_2_2_10_6_is_the_notes_table():
    sol = api.line(2, 2, 10, 6, algo="dda", convention="notes")
    ys = [s.extra[1] for s in sol.steps()]
    assert ys == [2, Fraction(5, 2), 3, Fraction(7, 2), 4, Fraction(9, 2), 5, Fraction(11, 2), 6]
    assert [s.pixel for s in sol.steps()] == [
        (2, 2), (3, 3), (4, 3), (5, 4), (6, 4), (7, 5), (8, 5), (9, 6), (10, 6),
    ]  # fmt: skip


def test_notes_dda_2_2_5_10_and_basic_2_2_8_5():
    dda = api.line(2, 2, 5, 10, algo="dda", convention="notes")
    assert list(dda.pixels())[-1] == (5, 10) and any("E2" in n for n in dda.notes)
    basic = api.line(2, 2, 8, 5, algo="basic", convention="notes")
    assert list(basic.pixels()) == [(2, 2), (3, 3), (4, 3), (5, 4), (6, 4), (7, 5), (8, 5)]


def test_notes_general_method_r5():
    sol = api.circle(5, method="general", convention="notes")
    steps = list(sol.steps())
    assert [s.p for s in steps] == [0, -5, 0, 1]
    assert [s.pixel for s in steps] == [(0, 5), (1, 4), (2, 4), (3, 3)]
    assert any("E8" in n for n in sol.notes)


def test_notes_topic9_circle_r5():
    sol = api.circle(5, method="midpoint", convention="notes")
    steps = list(sol.steps())
    assert [s.p for s in steps] == [-4, -1, 4, 3, 6]
    assert [s.pixel for s in steps] == [(0, 5), (1, 5), (2, 5), (3, 4), (4, 3)]
    assert any("E10" in n for n in sol.notes)
    b = api.circle(5, method="bresenham")
    assert any("'midpoint'" in n for n in b.notes)  # says how to get the notes' p0 = 1 - r


# --- bad combinations -----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (("line", "0", "0", "5", "2", "--algo", "dda", "--tie", "keep"), ("--tie", "dda")),
        (("line", "0", "0", "5", "2", "--rounding", "half-even"), ("--rounding", "bresenham")),
        (("circle", "5", "-m", "bresenham", "--p0", "5/4-r"), ("--p0",)),
        (("circle", "5", "-m", "trig", "--tie", "keep"), ("--tie", "trig")),
        (("circle", "5", "-m", "general", "--update", "old"), ("--update",)),
        (("circle", "5", "-m", "midpoint", "--rounding", "trunc"), ("--rounding",)),
        (("circle", "5", "--convention", "wikipedia"), ("--convention",)),
        (("ellipse", "8", "6", "--convention", "wikipedia"), ("--convention",)),
        (("circle", "5", "--layout", "sideways"), ("--layout",)),
    ],
)
def test_bad_combinations_are_one_line_errors(args, words):
    assert_refused(run(*args), *words)


def test_library_refuses_a_knob_that_does_not_apply():
    with pytest.raises(InputError) as err:
        api.line(0, 0, 3, 1, algo="basic", tie="keep")
    assert err.value.param == "tie"


def test_ellipse_inclusive_loop_example():
    # rx = ry = 3: region 1 ends on 2ry²x = 2rx²y exactly, where <= takes one more step
    strict = list(ellipses.midpoint_ellipse(3, 3, "strict"))
    inclusive = list(ellipses.midpoint_ellipse(3, 3, "inclusive"))
    assert strict != inclusive
    assert sum(s.extra[0] == 1 for s in inclusive) == sum(s.extra[0] == 1 for s in strict) + 1


# --- which end point is plotted first (start), the ellipse's tie and p0 ------------------------


def _mirror(points, steep):
    return [(x, -y) if steep else (-x, y) for x, y in points]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(coord, coord, coord, coord, st.sampled_from(["step", "keep"]))
def test_start_given_walks_from_p1_as_the_mirrored_swap_walk(x1, y1, x2, y2, tie):
    """Walking from P1 with the major coordinate decreasing is the swap walk of the mirrored
    line, mirrored back: the same decisions, a tie seen from P1's side."""
    steep = abs(y2 - y1) > abs(x2 - x1)
    given_walk = list(api.line(x1, y1, x2, y2, tie=tie, start="given").pixels())
    assert given_walk[0] == (x1, y1) and given_walk[-1] == (x2, y2)
    if (y2 - y1 if steep else x2 - x1) >= 0:  # nothing to swap: the two starts agree
        assert given_walk == list(api.line(x1, y1, x2, y2, tie=tie).pixels())
        return
    (a1, b1), (a2, b2) = _mirror([(x1, y1), (x2, y2)], steep)
    mirrored = list(api.line(a1, b1, a2, b2, tie=tie, start="swap").pixels())
    assert given_walk == _mirror(mirrored, steep)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(coord, coord, coord, coord)
def test_start_changes_bresenham_pixels_only_where_a_tie_is_met(x1, y1, x2, y2):
    swap = api.line(x1, y1, x2, y2, start="swap")
    given_walk = api.line(x1, y1, x2, y2, start="given")
    if all(s.p != 0 for s in swap.steps() if s.decision is not None):
        assert set(swap.pixels()) == set(given_walk.pixels())


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@given(halves, halves, halves, halves)
def test_dda_start_changes_pixels_only_at_halves(x1, y1, x2, y2):
    given_walk = api.line(x1, y1, x2, y2, algo="dda", start="given")
    swap = api.line(x1, y1, x2, y2, algo="dda", start="swap")
    values = [v for s in given_walk.steps() for v in s.extra[:2]]
    if all(Fraction(v).denominator != 2 for v in values):
        assert set(given_walk.pixels()) == set(swap.pixels())
    assert len(list(given_walk.pixels())) == len(list(swap.pixels()))


def test_start_examples_by_hand():
    # (4, 2) to (0, 0): p = 0, -4, 0, -4. Swapped, the ties step y on the way up from (0, 0);
    # walked from (4, 2), they step y on the way down.
    assert list(api.line(4, 2, 0, 0).pixels()) == [(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)]
    assert list(api.line(4, 2, 0, 0, start="given").pixels()) == [
        (4, 2),
        (3, 1),
        (2, 1),
        (1, 0),
        (0, 0),
    ]
    # the DDA from (5, 1) to (0, 0): y = 1, 0.8, ..., 0 from P1; 0, 0.2, ... from P2
    dda_given = [s.pixel for s in api.line(5, 1, 0, 0, algo="dda").steps()]
    dda_swap = [s.pixel for s in api.line(5, 1, 0, 0, algo="dda", start="swap").steps()]
    assert dda_given == [(5, 1), (4, 1), (3, 1), (2, 0), (1, 0), (0, 0)]
    assert dda_swap == [(0, 0), (1, 0), (2, 0), (3, 1), (4, 1), (5, 1)]
    import scanconv

    text = scanconv.line(5, 1, 0, 0, algo="dda", start="swap").to("plain")
    assert "swap the end points so that x increases" in text
    assert "start = swap" in text


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
def test_ellipse_exact_quarters_meet_no_tie_on_small_ellipses():
    """Why the ellipse's tie knob matters only with p0 = rounded: with exact quarters no
    decision parameter of these ellipses is 0, so the two tie rules agree."""
    # The quadrant's steps from the generator itself (the plotted pixels are their mirror
    # images): the worked answers around them cost ten times as much.
    for rx in range(1, 25):
        for ry in range(1, 25):
            step = list(ellipses.midpoint_ellipse(rx, ry))
            assert all(s.p != 0 for s in step)
            keep = ellipses.midpoint_ellipse(rx, ry, tie="keep")
            assert [s.pixel for s in step] == [s.pixel for s in keep]


def test_ellipse_rounded_p0_and_tie_by_hand():
    # rx = 6, ry = 5, rounded as Hearn & Baker's code: p1_0 = 25 - 180 + 9 = -146, and
    # int(-146 + 0.5) = int(-145.5) = -145 (C truncates toward zero). Region 1 ends at (5, 3);
    # p2_0 = 25 * 5.5^2 + 36 * 2^2 - 900 = 0.25, int(0.75) = 0: a tie. step: SE to (6, 2);
    # keep: S to (5, 2).
    step = list(api.ellipse(6, 5, p0="rounded").steps())
    keep = list(api.ellipse(6, 5, p0="rounded", tie="keep").steps())
    assert step[0].p == -145
    r2_step = [(s.p, s.decision.value, s.pixel) for s in step if s.extra[0] == 2]
    r2_keep = [(s.p, s.decision.value, s.pixel) for s in keep if s.extra[0] == 2]
    assert r2_step[0] == (0, "SE", (6, 2))
    assert r2_keep[0] == (0, "S", (5, 2))
    import scanconv

    text = scanconv.ellipse(6, 5, p0="rounded").to("plain")
    assert "= 0.25 -> 0 (rounded)" in text
    assert "= -146 -> -145 (rounded)" in text


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@given(st.integers(1, 30), st.integers(1, 30))
def test_ellipse_tie_changes_the_walk_only_from_its_first_tie(rx, ry):
    step = list(api.ellipse(rx, ry, p0="rounded").steps())
    keep = list(api.ellipse(rx, ry, p0="rounded", tie="keep").steps())
    first = next((i for i, s in enumerate(step) if s.p == 0), None)
    if first is None:
        assert [s.pixel for s in step] == [s.pixel for s in keep]
    else:
        assert [s.pixel for s in step[:first]] == [s.pixel for s in keep[:first]]


def test_hearn_baker_ellipse_example_is_exact_not_their_codes_rounding():
    """Hearn & Baker's printed example (rx = 8, ry = 6) has p1 = -332, -224, -44, 208, -108,
    288, 244 and p2 = -23, 361, 297: the exact values, which the preset prints. Their C code's
    round(a) = int(a + 0.5) would start from int(-331.5) = -331 (``--p0 rounded``)."""
    hb = [s.p for s in api.ellipse(8, 6, convention="hearn-baker").steps()]
    assert hb == [-332, -224, -44, 208, -108, 288, 244, -23, 361, 297]
    code = [s.p for s in api.ellipse(8, 6, p0="rounded").steps()]
    assert code == [-331, -223, -43, 209, -107, 289, 245, -22, 362, 298]


def test_ellipse_p0_values_are_checked_per_method():
    with pytest.raises(ValueError, match="choose from exact, rounded"):
        api.ellipse(3, 2, p0="1-r")
    with pytest.raises(ValueError, match="choose from 1-r, 5/4-r"):
        api.circle(5, method="midpoint", p0="rounded")
