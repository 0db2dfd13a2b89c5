"""The worked answer of the midpoint line algorithm: the implicit function, the midpoint, the
decision variable d = F(M) and its two increments derived with the numbers, and its relation to
Bresenham's p shown. The table's shape, the pixels and the grid are Bresenham's (the same
steps, :mod:`scanconv.algorithms.midpoint_line`)."""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction
from typing import TYPE_CHECKING

from ...algorithms.lines import bresenham_terms, orient
from ...algorithms.midpoint_line import halve
from ...core import lazy
from ...core.numeric import Number, fmt_short
from ...core.records import Column, Quantity, Solution, Step, rule, worked

if TYPE_CHECKING:
    from . import line
else:
    line = lazy.module("scanconv.answers.primitives.line")


def _renamed(c: Column) -> Column:
    """A Bresenham column headed for the midpoint line: p becomes d."""
    if c.key not in ("p", "p_next"):
        return c
    return c._replace(text=c.text.replace("p", "d"), tex=c.tex.replace("p_", "d_"))


def derivation(steep: bool, dmaj: int, dmin: int, scale: str, tie: str) -> list[Quantity]:
    """The midpoint line's derivation with the numbers: F, M, d_0 and the two increments
    (written for the major axis; ``dmaj``, ``dmin`` the absolute differences)."""
    maj, mnr = ("y", "x") if steep else ("x", "y")
    D, d = f"\\Delta {maj}", f"\\Delta {mnr}"
    half = scale == "half"
    div = 2 if half else 1
    d0, keep, step = (Fraction(v, div) for v in bresenham_terms(dmaj, dmin)[:3])
    factor = "" if half else "2"
    lt, ge = ("<", "\\ge") if tie == "step" else ("\\le", ">")
    lhs = "F(M)" if half else "2F(M)"
    # F(x, y) for the x-major line with y increasing; the other octants by symmetry (named)
    return [
        rule(
            "F",
            f"F({maj}, {mnr}) = {d} \\cdot {maj} - {D} \\cdot {mnr} + c "
            f"\\quad (F = 0 \\text{{ on the line}})",
        ),
        rule(
            "M",
            f"M = ({maj}_k + 1, {mnr}_k + 1/2) \\quad (\\text{{midway between the candidates}})",
        ),
        rule("d", f"d_k = {lhs}"),
        worked(
            "d0",
            d0,
            f"d_0 = {factor}F({maj}_1 + 1, {mnr}_1 + 1/2) = "
            + (
                f"{d} - {D}/2 = {dmin} - {dmaj}/2"
                if half
                else f"2{d} - {D} = 2 \\cdot {dmin} - {dmaj}"
            )
            + f" = {fmt_short(d0)}",
        ),
        worked(
            "inc_keep",
            keep,
            f"d_{{k+1}} = d_k + {factor}{d} = d_k {_plus(keep)} "
            f"\\quad (d_k {lt} 0\\text{{: the line passes between M and the kept pixel}})",
        ),
        worked(
            "inc_step",
            step,
            f"d_{{k+1}} = d_k + {factor}({d} - {D}) = d_k {_plus(step)} "
            f"\\quad (d_k {ge} 0\\text{{: the line passes between M and the stepped pixel}})",
        ),
        rule(
            "tie",
            f"d_k = 0: \\text{{M on the line, the {'minor coordinate stepped' if tie == 'step' else 'minor coordinate kept'}}}",
        ),
    ]


def _plus(v: Fraction) -> str:
    """``+ 8`` or ``- 8``."""
    return f"+ {fmt_short(v)}" if v >= 0 else f"- {fmt_short(-v)}"


def midpoint_answer(
    x1: Number, y1: Number, x2: Number, y2: Number, knobs: dict[str, str], layout: str
) -> Solution:
    """The midpoint line (record ``line/midpoint``) with its conventions ``knobs``.

    >>> sol = midpoint_answer(2, 2, 10, 6, {"tie": "step", "scale": "integer"}, "textbook")
    >>> [s.p for s in sol.steps()]
    [0, -8, 0, -8, 0, -8, 0, -8]
    >>> print(sol.derived[7].text)
    d₀ = 2F(x₁ + 1, y₁ + 1/2) = 2Δy - Δx = 2·4 - 8 = 0
    """
    tie, scale = knobs["tie"], knobs["scale"]
    base = line.line_solution("bresenham", x1, y1, x2, y2, tie=tie, layout=layout)
    ix1, iy1, ix2, iy2 = int(x1), int(y1), int(x2), int(y2)
    o = orient(ix1, iy1, ix2, iy2)

    def steps() -> Iterator[Step]:
        for s in base.steps():
            if scale == "half":
                yield s._replace(p=halve(s.p), extra=tuple(halve(v) for v in s.extra))
            else:
                yield s

    derived = (
        *base.derived[:4],
        *derivation(o.steep, o.dmaj, o.dmin, scale, tie),
    )
    notes = (
        base.notes[0],
        "d_k is Bresenham's p_k"
        + (" halved" if scale == "half" else "")
        + ": the same start and the same increments, so the same pixels; the midpoint form "
        "derives them from the line's equation at the midpoint.",
        f"Conventions: tie = {tie} (d = 0 {'steps' if tie == 'step' else 'keeps'} the minor "
        f"coordinate), scale = {scale} "
        + ("(d = F(M), in halves)." if scale == "half" else "(d = 2F(M), integers only)."),
    )
    return Solution(
        primitive=base.primitive,
        algorithm="midpoint",
        title=f"Midpoint line algorithm: ({ix1}, {iy1}) to ({ix2}, {iy2})",
        given=base.given,
        derived=derived,
        notes=notes,
        walk=base.walk._replace(columns=tuple(_renamed(c) for c in base.columns), steps=steps),
        plot=base.plot,
        theory=base.theory,
        data={**base.data, "conventions": dict(knobs), "layout": layout},
    )
