"""The worked answer of Hearn & Baker's supersampling of a line: the sub-pixel line, the
Bresenham decision table on the n x n sub-pixel grid, and each pixel's count and intensity."""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction
from typing import Any

from ....algorithms import coverage as cov
from ....algorithms.image_limits import check_levels
from ....algorithms.subpixel import SUBGRIDS, counts, pixel_of, sub_line, walk
from ....core.checks import InputError, check_integer
from ....core.ideal import IdealLine
from ....core.numeric import Number, fmt_exact, normalize
from ....core.records import (
    Pixel,
    Plot,
    Quantity,
    Solution,
    Step,
    Table,
    Walk,
    heading,
    rule,
    worked,
)
from ._shared import SHADING, level_rule, picture, pixel_box

DIVIDES = {
    "n": "I = c / n, full intensity at n sub-pixels: n levels above zero (Hearn & Baker's "
    "three settings for a 3 x 3 grid)",
    "n2": "I = c / n², the fraction of the pixel's n² sub-pixels on the path",
}
"""How a pixel's count becomes its intensity (the ``divide`` convention), the default first."""


def _signed(v: Number) -> str:
    """``+ 8`` or ``- 8``: a term added in the working.

    >>> _signed(-8), _signed(Fraction(1, 2))
    ('- 8', '+ 1/2')
    """
    v = normalize(v)
    return f"- {fmt_exact(-v)}" if v < 0 else f"+ {fmt_exact(v)}"


def _derived(line: Any, n: int, subgrid: str, levels: int, per: int) -> list[Quantity]:
    maj, mnr = ("y", "x") if line.steep else ("x", "y")
    u1, v1 = line.u0 + line.du, normalize(line.v0 + line.dv)
    dv = abs(Fraction(line.dv))
    p0 = normalize(2 * dv - line.du)
    start = (
        f"U_0 = {n} \\cdot {maj}_1 = {line.u0},\\ V_0 = {n} \\cdot {mnr}_1 = {line.v0}"
        if subgrid == "span"
        else f"U_0 = {n} {maj}_1 + {(n - 1) // 2} = {line.u0},\\ V_0 = {n} {mnr}_1 + "
        f"{(n - 1) // 2} = {line.v0}"
    )
    span = (
        f"\\Delta U = {n} \\Delta {maj} + {n - 1} = {line.du},\\ \\Delta V = m \\Delta U = "
        f"{fmt_exact(line.dv)}"
        if subgrid == "span"
        else f"\\Delta U = {n} \\Delta {maj} = {line.du},\\ \\Delta V = {n} \\Delta {mnr} = "
        f"{fmt_exact(line.dv)}"
    )
    return [
        worked("n", n, f"{n} \\times {n} = {n * n} \\text{{ sub-pixels per pixel}}"),
        worked("start", (line.u0, line.v0), start),
        worked("span", (line.du, line.dv), span),
        worked("end", (u1, v1), f"(U, V) \\text{{ from }} ({line.u0}, {line.v0}) \\text{{ to }} "
               f"({u1}, {fmt_exact(v1)})"),
        worked("p0", p0, f"p_0 = 2 |\\Delta V| - \\Delta U = 2 \\cdot {fmt_exact(dv)} - "
               f"{line.du} = {fmt_exact(p0)}"),
        rule("decide", f"p_k < 0: V \\text{{ kept}},\\ p_{{k+1}} = p_k + {fmt_exact(2 * dv)};\\ "
             f"p_k \\ge 0: V \\text{{ stepped}},\\ p_{{k+1}} = p_k {_signed(2 * dv - 2 * line.du)}"),
        rule("pixel", f"\\text{{pixel}} = (\\lfloor U / {n} \\rfloor, \\lfloor V / {n} \\rfloor)"
             + (" \\text{ (U along y: swapped back)}" if line.steep else "")),
        rule("intensity", f"I = c / {per} \\quad (c \\text{{ sub-pixels of the path in the pixel; "
             f"at most {n}}})"),
        level_rule(levels),
    ]  # fmt: skip


def _notes(subgrid: str, divide: str, maj: str, n: int) -> tuple[str, ...]:
    """The two conventions named, what a row is, and the shading."""
    return (
        f"Sub-grid (subgrid = {subgrid}"
        + (", the default" if subgrid == "span" else "; the default is subgrid = span")
        + f"): {SUBGRIDS[subgrid]}.",
        f"Each row is one sub-pixel of the path; its pixel collects it. An {maj}-major path "
        f"puts at most {n} sub-pixels in a pixel. Intensity (divide = {divide}"
        + (", the default" if divide == "n" else "; the default is divide = n")
        + f"): {DIVIDES[divide]}. A tie (p = 0) steps V, as the notes' Bresenham does.",
        SHADING,
    )


def _count_table(rows: Any, per: int) -> Table:
    """Each pixel's count c, its intensity c / per and its level."""
    return Table(
        "Sub-pixels per pixel and intensities",
        (
            heading("pixel", r"\text{pixel } (x, y)"),
            heading("count", "c"),
            heading("intensity", f"I = c / {per}", 3),
            heading("level", r"\text{level}"),
        ),
        rows,
    )


def subpixel_solution(
    x1: Number, y1: Number, x2: Number, y2: Number, n: int = 3, levels: int = 8,
    subgrid: str = "span", divide: str = "n",
) -> Solution:  # fmt: skip
    """Hearn & Baker's supersampling of the line between the pixels P1 and P2: Bresenham on the
    ``n x n`` sub-pixel grid (:mod:`scanconv.algorithms.subpixel`), the counts, ``I = c / n``
    (``divide="n"``, Hearn & Baker's levels) or ``I = c / n²`` (``"n2"``, the fraction of the
    pixel's sub-pixels).

    >>> sol = subpixel_solution(0, 0, 2, 1)
    >>> [(s.p, s.extra[:2]) for s in sol.steps()][:3]
    [(0, (0, 0)), (-8, (1, 1)), (0, (2, 1))]
    >>> [(r[0], r[1], str(r[2])) for r in sol.tables[0].rows()]
    [((0, 0), 3, '1'), ((1, 0), 2, '2/3'), ((1, 1), 1, '1/3'), ((2, 1), 3, '1')]
    """
    ix1, iy1, ix2, iy2 = (
        check_integer(v, name) for v, name in ((x1, "x1"), (y1, "y1"), (x2, "x2"), (y2, "y2"))
    )
    n = cov.check_samples(n)
    L = check_levels(levels)
    if divide not in DIVIDES:
        raise InputError(f"unknown divide {divide!r} (choose from {', '.join(DIVIDES)})", "divide")
    per = n if divide == "n" else n * n
    line = sub_line(ix1, iy1, ix2, iy2, n, subgrid)
    columns = max(abs(ix2 - ix1), abs(iy2 - iy1)) + 1
    if columns > cov.MAX_AA_CELLS:
        raise InputError(
            f"the line crosses {columns:,} pixel columns; at most {cov.MAX_AA_CELLS:,} are "
            "supersampled",
            "line",
        )
    found = counts(line, n)
    levels_of = {p: cov.quantize(Fraction(c, per), L) for p, c in found.items()}

    def steps() -> Iterator[Step]:
        for k, p, u, v in walk(line):
            yield Step(k, p, None, pixel_of(line, u, v, n), (u, v))

    def rows() -> Iterator[tuple[Any, ...]]:
        for px, c in found.items():
            yield (px, c, normalize(Fraction(c, per)), levels_of[px])

    order: list[Pixel] = list(found)
    art = picture({p: lv for p, lv in levels_of.items() if lv}, L)
    maj, mnr = ("y", "x") if line.steep else ("x", "y")
    sol = Solution(
        primitive="line",
        algorithm="subpixel",
        title=f"Supersampling on a {n} x {n} sub-pixel grid (Hearn & Baker): ({ix1}, {iy1}) to "
        f"({ix2}, {iy2}), L = {L}",
        given=(
            worked("P1", (ix1, iy1), f"P_1 = ({ix1}, {iy1})"),
            worked("P2", (ix2, iy2), f"P_2 = ({ix2}, {iy2})"),
            worked("L", L, f"L = {L} \\text{{ levels}}"),
        ),
        derived=tuple(_derived(line, n, subgrid, L, per)),
        notes=_notes(subgrid, divide, maj, n),
        walk=Walk(
            columns=(
                heading("k", "k", role="label"),
                heading("p", "p_k"),
                heading("u", f"U_k \\text{{ (sub-{maj})}}"),
                heading("v", f"V_k \\text{{ (sub-{mnr})}}"),
                heading("pixel", r"\text{pixel}"),
            ),
            extra_keys=("u", "v"),
            steps=steps,
            tables=(_count_table(rows, per),),
        ),
        plot=Plot(
            pixels=lambda: iter(order),
            bbox=pixel_box(order),
            figures=(art,) if art else (),
            ideal=(IdealLine(ix1, iy1, ix2, iy2),),
            shades=levels_of,
            levels=L,
            numbering="none",
        ),
    )
    sol.data = {**sol.data, "conventions": {"subgrid": subgrid, "divide": divide}}
    return sol
