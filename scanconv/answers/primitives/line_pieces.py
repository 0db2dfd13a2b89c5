"""The line records' pieces other than the answer and the row estimate: the ``--derive`` and
``--algorithm`` pieces and the practice wording, each taking the
:class:`~scanconv.answers.asked.LineQuestion` (the answers are in :mod:`.line`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...algorithms.lines import abs_value, dda_steps, orient
from ...core import lazy
from ...core.numeric import Number, fmt_short, normalize
from ...core.records import Code, Quantity
from ..asked import LineQuestion
from ..methods import method

if TYPE_CHECKING:
    from ..theory import derivations as theory
else:  # only --derive and --algorithm need it
    theory = lazy.module("scanconv.answers.theory.derivations")


def _orientation(q: LineQuestion) -> tuple[Number, Number, bool, int]:
    """Δx, Δy, whether y is the major axis, and the sign of the slope."""
    dx, dy = normalize(q.x2 - q.x1), normalize(q.y2 - q.y1)
    sign = -1 if (dx > 0 > dy or dy > 0 > dx) else 1
    return dx, dy, abs_value(dy) > abs_value(dx), sign


def bresenham_derivation(q: LineQuestion) -> tuple[Quantity, ...]:
    """``--derive`` for Bresenham's line: p and its increments from the line's equation."""
    sx, sy, _, _, steep, dmaj, dmin, sign, _, _ = orient(*(int(v) for v in q.ends))
    u0, v0 = (sy, sign * sx) if steep else (sx, sign * sy)
    return (
        theory.DERIVATION,
        *theory.bresenham_line_derivation(u0, v0, dmaj, dmin, steep, sign),
    )


def bresenham_pseudocode(q: LineQuestion) -> Code:
    """``--algorithm`` for Bresenham's line, in the question's octant and conventions."""
    ix1, iy1, ix2, iy2 = (int(v) for v in q.ends)
    sx, sy, _, _, steep, _, _, sign, _, _ = orient(ix1, iy1, ix2, iy2)
    swapped = (sx, sy) != (ix1, iy1)
    backward = swapped and q.knobs.start == "given"
    return theory.bresenham_line_code(steep, sign, swapped, str(q.knobs.tie), backward)


def dda_derivation(q: LineQuestion) -> tuple[Quantity, ...]:
    """``--derive`` for the DDA: the increments from the slope."""
    dx, dy, _, _ = _orientation(q)
    return (theory.DERIVATION, *theory.dda_derivation(dx, dy, dda_steps(*q.points)))


def dda_pseudocode(q: LineQuestion) -> Code:
    """``--algorithm`` for the DDA."""
    dx, dy, steep, sign = _orientation(q)
    swapped = q.knobs.start == "swap" and (dy if steep else dx) < 0
    return theory.dda_code(steep, sign, str(q.knobs.rounding), swapped)


def basic_derivation(q: LineQuestion) -> tuple[Quantity, ...]:
    """``--derive`` for the basic method: the slope (the DDA's first line)."""
    dx, dy, _, _ = _orientation(q)
    return (theory.DERIVATION, *theory.dda_derivation(dx, dy, dda_steps(*q.points))[:1])


def basic_pseudocode(q: LineQuestion) -> Code:
    """``--algorithm`` for the basic method."""
    _, _, steep, _ = _orientation(q)
    return theory.basic_code(steep, str(q.knobs.rounding))


def _practice(name: str, q: LineQuestion) -> str:
    return (
        f"Scan-convert the line from ({fmt_short(q.x1)}, {fmt_short(q.y1)}) to "
        f"({fmt_short(q.x2)}, {fmt_short(q.y2)}) with {name}: give the step table and the "
        "pixels plotted."
    )


def dda_practice(q: LineQuestion) -> str:
    """A practice question's wording for the DDA."""
    return _practice("the DDA algorithm", q)


def bresenham_practice(q: LineQuestion) -> str:
    """A practice question's wording for Bresenham's line."""
    return _practice("Bresenham's line algorithm", q)


def practice(q: LineQuestion) -> str:
    """A practice question's wording for any line method, named by its record's title (the
    ``line-methods`` practice topic draws every line record that has a wording)."""
    return _practice(f"the {method('line', q.algo).title}", q)
