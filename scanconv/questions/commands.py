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
from ..core import lazy
from ..core.checks import InputError
from ..core.numeric import parse_number
from .words import UsageError, no_such_option, number

if TYPE_CHECKING:
    from ..answers.process import transform as answers_transform
else:
    answers_transform = lazy.module("scanconv.answers.process.transform")

if TYPE_CHECKING:
    from ..core.records import Solution

Body = Callable[..., "Solution"]

ORIGIN = (Fraction(0), Fraction(0))
"""The default centre or vertex of a parametric curve."""

TRANSFORM_WORDS = {"--translate", "--scale", "--rotate", "--reflect", "--shear", "--about"}
TRANSFORM_WORDS |= {"--points"}
"""The words of ``transform`` that start a transformation (or more points)."""


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


def _is_number(word: str) -> bool:
    try:
        parse_number(word)
    except ValueError:
        return False
    return True


def _check_word(word: str) -> None:
    """A word of ``transform`` that is neither a number, a transformation nor an angle is an
    unknown option."""
    if not word.strip():  # an empty word, as the command line's number parser words it
        try:
            number(word)
        except ValueError as err:
            raise UsageError(f"Invalid value: {err}") from None
    if not word.startswith("-") or word.split("=", 1)[0] in TRANSFORM_WORDS or _is_number(word):
        return
    try:
        answers_transform.parse_angle(word)
    except ValueError:
        raise no_such_option(word.split("=", 1)[0]) from None


def split_words(words: list[str]) -> tuple[list[Fraction], list[str]]:
    """``transform``'s words: the leading points, and the transformations after them.

    >>> split_words(["0", "0", "4", "0", "--rotate", "90"])
    ([Fraction(0, 1), Fraction(0, 1), Fraction(4, 1), Fraction(0, 1)], ['--rotate', '90'])
    """
    points: list[Fraction] = []
    ops: list[str] = []
    taking = True
    for word in words:
        _check_word(word)
        if word == "--points":
            taking = True
        elif taking and _is_number(word):
            points.append(number(word))
        else:
            taking = False
            ops.append(word)
    return points, ops


def transform(words: list[str], inverse: bool) -> Solution:
    points, ops = split_words(words)
    return api.transform(points, ops, inverse=inverse)


def numbers_around(
    words: list[str], flag: str, param: str, required: bool = True
) -> tuple[list[Any], list[Any]]:
    """``X1 Y1 ... FLAG X Y ...`` (the words of ``inside`` and ``clip convex``): the numbers
    before ``flag`` and the numbers after it.

    >>> numbers_around(["0", "0", "--points", "1", "-2"], "--points", "points")
    ([Fraction(0, 1), Fraction(0, 1)], [Fraction(1, 1), Fraction(-2, 1)])
    """
    before: list[Any] = []
    after: list[Any] = []
    taking = before
    for word in words:
        name, eq, value = word.partition("=")
        if name == flag:
            taking = after
            if not eq:
                continue
            word = value
        try:
            taking.append(number(word))
        except ValueError as err:
            if isinstance(err, UsageError):
                raise
            raise UsageError(f"Invalid value: {err}") from None
    if not after and required:
        raise UsageError(f"Missing option '{flag}' (give {flag} X Y ...)")
    return before, after


def clip_convex(words: list[str], normals: Any, ends: Any) -> Solution:
    ends_, window = numbers_around(words, "--window-vertices", "window")
    if len(ends_) != 4:
        raise UsageError(
            f"give the segment's end points X1 Y1 X2 Y2 before --window-vertices, got "
            f"{len(ends_)} number(s)"
        )
    x1, y1, x2, y2 = ends_
    return api.clip_convex(
        x1, y1, x2, y2, window, normals=_text(normals) or "outward", ends=_text(ends) or "exact"
    )


def clip_polygon(words: list[str], window: Any, method: Any) -> Solution:
    """``clip polygon``: the polygon's vertices, and the window as ``--window`` (a rectangle)
    or ``--window-vertices X Y ...`` after them (a polygon), one or the other."""
    vertices, corners = numbers_around(words, "--window-vertices", "window", required=False)
    if corners and window is not None:
        raise UsageError("give the window as --window or --window-vertices, not both")
    if not corners and window is None:
        raise UsageError(
            "Missing option '--window' (give --window XMIN YMIN XMAX YMAX, or "
            "--window-vertices X Y ... after the polygon)"
        )
    return api.clip_polygon(vertices, corners or window, method=method)


def inside(words: list[str], rule: Any, boundary: Any) -> Solution:
    vertices, points = numbers_around(words, "--points", "points")
    return api.inside(vertices, points, rule=_text(rule), boundary=_text(boundary))


def theory(topic: str, list_: bool = False) -> Solution:
    return theory_api(topic)


BODIES: dict[str, Body] = {
    fn.__name__: fn
    for fn in (
        parametric_circle, bezier, bspline, continuity, local_control, transform, theory,
        clip_convex, clip_polygon, inside,
    )
}  # fmt: skip
"""Each command's answer, by the command's function name (``parametric_circle``), for the
commands not yet declared by their library function (:mod:`.declared`)."""
