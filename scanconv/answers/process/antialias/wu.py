"""The worked answer of Xiaolin Wu's anti-aliased line: a step table of the two pixels of each
column and their intensities, with the end-point convention (``ends``) named."""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator
from fractions import Fraction
from typing import NamedTuple

from ....algorithms import coverage as cov
from ....algorithms.image_limits import check_levels
from ....algorithms.wu import ENDS, end_gaps, wu_line
from ....core.checks import InputError
from ....core.ideal import IdealLine
from ....core.numeric import Number, fmt_exact, fmt_short, normalize, round_half_up
from ....core.records import (
    MAX_GRID_CELLS,
    Column,
    Pixel,
    Plot,
    Quantity,
    Solution,
    Step,
    Walk,
    heading,
    rule,
    worked,
)
from ._shared import SHADING
from ._shared import level_rule as _level_rule
from ._shared import paren_short as _p
from ._shared import picture as _picture


class _WuWalk(NamedTuple):
    """Wu's walk along the major coordinate ``a`` (the minor one ``b``), from (a1, b1) to
    (a2, b2) with a increasing; ``ends`` is the end-point convention (:data:`ENDS`)."""

    steep: bool
    maj: str
    mnr: str
    lower: str
    upper: str
    a1: Number
    b1: Number
    a2: Number
    b2: Number
    swapped: bool
    ends: str

    @property
    def integer(self) -> bool:
        return all(isinstance(v, int) for v in (self.a1, self.b1, self.a2, self.b2))


def _wu_walk(x1: Number, y1: Number, x2: Number, y2: Number, ends: str) -> _WuWalk:
    steep = abs(Fraction(y2 - y1)) > abs(Fraction(x2 - x1))
    maj, mnr = ("y", "x") if steep else ("x", "y")
    lower, upper = ("left", "right") if steep else ("lower", "upper")
    (a1, b1), (a2, b2) = ((y1, x1), (y2, x2)) if steep else ((x1, y1), (x2, y2))
    swapped = a2 < a1
    if swapped:
        a1, b1, a2, b2 = a2, b2, a1, b1
    return _WuWalk(steep, maj, mnr, lower, upper, a1, b1, a2, b2, swapped, ends)


def _wu_ends(w: _WuWalk) -> tuple[Quantity, ...]:
    """The end columns round(a) and (with ``ends = coverage``) their weights."""
    maj = w.maj
    if w.integer and w.ends == "full":
        return ()
    g1, g2 = end_gaps(w.a1, w.a2, w.ends)
    c1, c2 = round_half_up(w.a1), round_half_up(w.a2)
    out = [
        rule(
            "columns",
            f"{maj}_{{\\text{{end}}}} = \\lfloor {maj} + 1/2 \\rfloor:\\ "
            f"\\lfloor {fmt_short(w.a1)} + 1/2 \\rfloor = {c1},\\ "
            f"\\lfloor {fmt_short(w.a2)} + 1/2 \\rfloor = {c2}",
        )
    ]
    if w.ends == "coverage":
        out += [
            worked(
                "gap1",
                g1,
                f"\\text{{gap}}_1 = 1 - \\operatorname{{frac}}({fmt_short(w.a1)} + 1/2) = {fmt_exact(g1)}",
            ),
            worked(
                "gap2",
                g2,
                f"\\text{{gap}}_2 = \\operatorname{{frac}}({fmt_short(w.a2)} + 1/2) = {fmt_exact(g2)}",
            ),
        ]
    return tuple(out)


def _wu_derived(w: _WuWalk, levels: int) -> tuple[Quantity, ...]:
    """Δ along both coordinates, the gradient, the minor coordinate and the split."""
    maj, mnr, a1, b1 = w.maj, w.mnr, w.a1, w.b1
    da, db = normalize(w.a2 - a1), normalize(w.b2 - b1)
    grad = normalize(Fraction(db) / da) if da else 0
    a2s, b2s = fmt_short(w.a2), fmt_short(w.b2)
    gap = "" if w.ends == "full" else " \\cdot \\text{gap}"
    return (
        worked(f"d{maj}", da, f"\\Delta {maj} = {a2s} - {_p(a1)} = {fmt_exact(da)}"),
        worked(f"d{mnr}", db, f"\\Delta {mnr} = {b2s} - {_p(b1)} = {fmt_exact(db)}"),
        worked(
            "gradient",
            grad,
            f"g = \\frac{{\\Delta {mnr}}}{{\\Delta {maj}}} = \\frac{{{fmt_exact(db)}}}"
            f"{{{fmt_exact(da)}}} = {fmt_exact(grad)}"
            if da
            else r"g = 0 \text{ (a single point)}",
        ),
        *_wu_ends(w),
        rule(
            "minor",
            f"{mnr}_k = {mnr}_1 + g ({maj}_k - {maj}_1) = {fmt_short(b1)} + {fmt_exact(grad)} "
            f"({maj}_k - {_p(a1)})",
        ),
        rule(
            "split",
            f"f = {mnr}_k - \\lfloor {mnr}_k \\rfloor,\\ I(\\text{{{w.lower}}}) = (1 - f){gap},\\ "
            f"I(\\text{{{w.upper}}}) = f{gap}"
            if gap
            else f"f = {mnr}_k - \\lfloor {mnr}_k \\rfloor,\\ I(\\text{{{w.lower}}}) = 1 - f,\\ "
            f"I(\\text{{{w.upper}}}) = f",
        ),
        _level_rule(levels),
    )


def _wu_notes(w: _WuWalk) -> tuple[str, ...]:
    if w.ends == "full":
        ends = (
            "End points (ends = full, the default; ends = coverage weights them): as in Wu "
            "(1991), drawn at full intensity"
            + (
                " (f = 0 there, so the second pixel of the first and last step has intensity 0)."
                if w.integer
                else "; the end columns are round(x) = floor(x + 1/2), the minor coordinate "
                "there read off the line."
            )
        )
        share = (
            f"Each step's two intensities sum to 1: the line's ink is shared between the two "
            f"pixels nearest to it along {w.mnr}, in proportion to its distance from each."
        )
    else:
        ends = (
            "End points (ends = coverage, as Wikipedia's widely copied pseudocode; the default "
            "is ends = full): each end column is weighted by the part of it the line covers "
            f"along {w.maj}, gap = 1 - frac({w.maj}1 + 1/2) and frac({w.maj}2 + 1/2) (1/2 for an "
            "integer end point); the columns between have gap = 1."
        )
        share = (
            f"Each step's two intensities sum to its gap: the line's ink is shared between the "
            f"two pixels nearest to it along {w.mnr}, in proportion to its distance from each."
        )
    return (
        *((f"End points swapped so that {w.maj} increases along the walk.",) if w.swapped else ()),
        ends,
        share,
        "Wu keeps f as an integer error term of n bits and draws from both ends at once; the "
        "table walks one way with f exact, and the levels are the intensities quantized.",
        SHADING,
    )


def _wu_columns(w: _WuWalk) -> tuple[Column, ...]:
    lower, upper = w.lower, w.upper
    gap = (heading("gap", r"\text{gap}", 3),) if w.ends == "coverage" else ()
    return (
        heading("k", "k", role="label"),
        heading(w.maj, f"{w.maj}_k"),
        heading(w.mnr, f"{w.mnr}_k \\text{{ (exact)}}", 3),
        *gap,
        heading("pixel_a", f"\\text{{{lower} pixel}}"),
        heading("pixel_b", f"\\text{{{upper} pixel}}"),
        heading("i_a", f"I(\\text{{{lower}}})", 3),
        heading("i_b", f"I(\\text{{{upper}}})", 3),
        heading("levels", f"\\text{{levels ({lower}, {upper})}}"),
    )


def _wu_shades(steps: Iterable[Step]) -> dict[Pixel, int]:
    """Each pixel's level (a pixel both steps share keeps the larger)."""
    values: dict[Pixel, int] = {}
    for s in steps:
        a, b = s.extra[-1]
        values[s.extra[2]] = a
        values[s.extra[3]] = max(values.get(s.extra[3], 0), b)
    return values


def _wu_point(v: Number) -> str:
    return fmt_short(v)


def wu_solution(
    x1: Number, y1: Number, x2: Number, y2: Number, levels: int = 8, ends: str = "full"
) -> Solution:
    """Xiaolin Wu's anti-aliased line as a worked answer; ``ends`` is ``"full"`` (the
    default) or ``"coverage"`` (:data:`~scanconv.algorithms.wu.ENDS`); the end points may be
    fractions.

    >>> sol = wu_solution(0, 0, 8, 3)
    >>> [str(q.value) for q in sol.derived[:3]]
    ['8', '3', '3/8']
    >>> [s.extra[4:] for s in sol.steps()][1]
    (Fraction(5, 8), Fraction(3, 8), (4, 3))
    >>> [str(s.extra[4]) for s in wu_solution(0, 1, 10, 2, ends="coverage").steps()][:2]
    ['1/2', '9/10']
    """
    if ends not in ENDS:
        raise InputError(f"unknown ends {ends!r} (choose from {', '.join(ENDS)})", "ends")
    fx1, fy1, fx2, fy2 = (normalize(v) for v in (x1, y1, x2, y2))
    L = check_levels(levels)
    w = _wu_walk(fx1, fy1, fx2, fy2, ends)
    coverage = ends == "coverage"

    def steps() -> Iterator[Step]:
        for s in wu_line(fx1, fy1, fx2, fy2, ends):
            ia, ib = s.extra[4], s.extra[5]
            levels_ab = (cov.quantize(ia, L), cov.quantize(ib, L))
            extra = (*s.extra[:6], *((s.extra[6],) if coverage else ()), levels_ab)
            yield Step(s.k, None, None, s.pixel, extra)

    def pixels() -> Iterator[Pixel]:
        for s in wu_line(fx1, fy1, fx2, fy2, ends):
            if s.extra[4]:
                yield s.extra[2]
            if s.extra[5]:
                yield s.extra[3]

    c1, c2 = round_half_up(w.a1), round_half_up(w.a2)
    plotted = list(pixels()) if c2 - c1 < 4 * MAX_GRID_CELLS else []
    values = _wu_shades(steps()) if plotted else {}
    picture = _picture({p: v for p, v in values.items() if v}, L) if plotted else None
    box = _wu_box(w)
    p1, p2 = f"({_wu_point(fx1)}, {_wu_point(fy1)})", f"({_wu_point(fx2)}, {_wu_point(fy2)})"
    sol = Solution(
        primitive="line",
        algorithm="wu",
        title=f"Xiaolin Wu's anti-aliased line: {p1} to {p2}, L = {L}"
        + (", ends weighted by coverage" if coverage else ""),
        given=(
            worked("P1", (fx1, fy1), f"P_1 = {p1}"),
            worked("P2", (fx2, fy2), f"P_2 = {p2}"),
            worked("L", L, f"L = {L} \\text{{ levels}}"),
        ),
        derived=_wu_derived(w, L),
        notes=_wu_notes(w),
        walk=Walk(
            columns=_wu_columns(w),
            extra_keys=(w.maj, w.mnr, "pixel_a", "pixel_b", "i_a", "i_b",
                        *(("gap",) if coverage else ()), "levels"),
            steps=steps,
        ),
        plot=Plot(
            pixels=pixels,
            bbox=box,
            figures=(picture,) if picture else (),
            ideal=(IdealLine(fx1, fy1, fx2, fy2),),
            shades=values or None,
            levels=L if values else 2,
            numbering="none" if values else None,
        ),
    )  # fmt: skip
    sol.data = {**sol.data, "conventions": {"ends": ends}}
    return sol


def _wu_box(w: _WuWalk) -> tuple[int, int, int, int]:
    """The pixel box of the walk: both end columns' two pixels (the minor coordinate is
    monotonic, so the ends bound it)."""
    da = w.a2 - w.a1
    grad = Fraction(w.b2 - w.b1) / da if da else Fraction(0)
    c1, c2 = round_half_up(w.a1), round_half_up(w.a2)
    lows = [math.floor(w.b1 + grad * (c - Fraction(w.a1))) for c in (c1, c2)]
    lo, hi = min(lows), max(lows) + 1
    return (lo, c1, hi, c2) if w.steep else (c1, lo, c2, hi)
