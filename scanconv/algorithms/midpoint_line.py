"""The midpoint line algorithm: the decision variable is the line's implicit function at the
midpoint between the two candidate pixels, ``d = F(M)`` (Pitteway 1967; Foley, van Dam, Feiner &
Hughes, *Computer Graphics*, 2nd ed., §3.2.2, ``MidpointLine``).

With ``F(x, y) = Δy·x - Δx·y + c`` (zero on the line) and ``M = (x_k + 1, y_k + 1/2)``,
``2F(M)`` starts at ``2Δy - Δx`` and grows by ``2Δy`` (E) or ``2Δy - 2Δx`` (NE): exactly
Bresenham's ``p_k``. So the steps are derived from :func:`scanconv.algorithms.lines.bresenham`'s
(the arithmetic exists once); ``scale="half"`` prints ``d = F(M)`` itself (``Δy - Δx/2``, in
halves). The tie (``d = 0``: the line through M) is a named convention: ``step`` (NE, the notes'
Bresenham rule) or ``keep`` (E, Foley's ``if (d <= 0)``).
"""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction

from ..core.numeric import normalize
from ..core.records import Step
from .lines import bresenham


def midpoint_line(
    x1: int, y1: int, x2: int, y2: int, tie: str = "step", scale: str = "integer"
) -> Iterator[Step]:
    """The midpoint line's steps: ``p`` is ``d_k``, ``extra`` is ``(d_{k+1},)``.

    >>> [(str(s.p), s.decision.value) for s in midpoint_line(0, 0, 5, 2, scale="half")]
    [('-1/2', 'E'), ('3/2', 'NE'), ('-3/2', 'E'), ('1/2', 'NE'), ('-5/2', 'E')]
    """
    for s in bresenham(x1, y1, x2, y2, tie):
        if scale == "half":
            yield s._replace(p=halve(s.p), extra=(halve(s.extra[0]),))
        else:
            yield s


def halve(v: int | Fraction | None) -> int | Fraction | None:
    """``v / 2`` exactly (``None`` stays ``None``).

    >>> halve(-3), halve(4), halve(None)
    (Fraction(-3, 2), 2, None)
    """
    return None if v is None else normalize(Fraction(v) / 2)
