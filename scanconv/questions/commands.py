"""What each command answers: one function per command of the question language, taking its
parameters by the command's names (``x1``, ``center``, ``kind``) and returning the
:class:`~scanconv.core.records.Solution` that :mod:`scanconv._api` builds. The command line
and the questions of sheets, practice, the exam book and ``check`` all answer through these.

A choice may be given as its text or as an enum member; a list of points flat.
"""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from .. import _api as api
from .._api.color_theory import theory as theory_api
from ..core.checks import InputError

if TYPE_CHECKING:
    from ..core.records import Solution

Body = Callable[..., "Solution"]

ORIGIN = (Fraction(0), Fraction(0))
"""The default centre or vertex of a parametric curve."""


def _text(value: Any) -> Any:
    """A choice as its text (an enum member's value); ``None`` stays."""
    return getattr(value, "value", value)


def parametric_circle(r: Any, center: Any, radius: Any, t_range: Any, samples: Any) -> Solution:
    if r is not None and radius is not None and r != radius:
        raise InputError(
            f"unexpected extra argument {r}: the radius is already given by --radius {radius}"
        )
    chosen = r if r is not None else radius if radius is not None else Fraction(1)
    return api.parametric_circle(center, chosen, t_range=t_range, samples=samples)


def bezier(points: Any, samples: Any, t: Any) -> Solution:
    if t is not None:
        return api.bezier_at(points, t)
    return api.bezier(points, samples)


def bspline(points: Any, degree: Any, knots: Any, basis: bool, t: Any, samples: Any) -> Solution:
    if basis:
        if t is not None:
            return api.bspline_at(points or [], t, degree, knots)
        return api.bspline_basis(points, degree, knots, samples)
    if not points:
        raise InputError(
            "missing control points X0 Y0 X1 Y1 ... (only --basis takes a degree and a knot "
            "list alone)",
            "points",
        )
    if t is not None:
        return api.bspline_at(points, t, degree, knots)
    return api.bspline(points, degree, knots, samples)


def segments(values: list[Any]) -> tuple[list[Fraction], list[Fraction]]:
    """``X0 Y0 ... : X0 Y0 ...`` (numbers and one ``:``) as the two segments' values."""
    if values.count(":") != 1:
        raise ValueError(
            "give two Bezier segments separated by ':', e.g. 0 0 1 1 2 0 : 2 0 3 -1 4 0"
        )
    i = values.index(":")
    return values[:i], values[i + 1 :]


def continuity(values: list[Any], samples: Any) -> Solution:
    first, second = segments(values)
    return api.continuity(first, second, samples)


def local_control(points: Any, move: Any, degree: Any, knots: Any, samples: Any) -> Solution:
    index, x, y = move
    return api.local_control(points, index, (x, y), degree, knots, samples)




def theory(topic: str, list_: bool = False) -> Solution:
    return theory_api(topic)


BODIES: dict[str, Body] = {
    fn.__name__: fn
    for fn in (
        parametric_circle, bezier, bspline, continuity, local_control, theory,
    )
}  # fmt: skip
"""Each command's answer, by the command's function name (``parametric_circle``), for the
commands not yet declared by their library function (:mod:`.declared`)."""
