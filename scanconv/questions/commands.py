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
from .._api.color_theory import color as color_api
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

TRANSFORM_WORDS = {"--translate", "--scale", "--rotate", "--reflect", "--shear", "--about"}
TRANSFORM_WORDS |= {"--points"}
"""The words of ``transform`` that start a transformation (or more points)."""


def _text(value: Any) -> Any:
    """A choice as its text (an enum member's value); ``None`` stays."""
    return getattr(value, "value", value)


def quantize(bits: Any, value_range: Any, kind: Any, recon: Any) -> Solution:
    return api.quantize(bits, value_range, integer=_text(kind) == "integer", recon=_text(recon))


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


def color(model: Any, values: list[str], to: Any, unit: bool, bits: Any) -> Solution:
    targets = list(to or [])
    numbers: list[str] = []
    for token in values:
        if not token.isalpha():
            numbers.append(token)
        elif to is not None:
            targets.append(token)
        else:
            raise ValueError(
                f"a colour component must be a number, got {token!r} (name the target models "
                "after --to)"
            )
    return color_api(model, *numbers, to=targets, unit=unit, bits=8 if bits is None else bits)


def dither_ordered(
    image: str,
    top: Any,
    matrix: Any,
    compare: Any,
    scale: Any,
    base: Any,
    transpose: bool,
) -> Solution:
    return api.dither_ordered(
        image,
        "2" if matrix is None else matrix,
        255 if top is None else top,
        compare=_text(compare),
        scale=_text(scale),
        base=_text(base),
        transpose=transpose,
    )


def dither_lookup(
    pixels: list[Any],
    matrix: Any,
    top: Any,
    value: Any,
    count: Any,
    compare: Any,
    scale: Any,
    base: Any,
    transpose: bool,
) -> Solution:
    return api.dither_lookup(
        pixels,
        "4" if matrix is None else matrix,
        255 if top is None else top,
        value=value,
        count=_text(count),
        compare=_text(compare),
        scale=_text(scale),
        base=_text(base),
        transpose=transpose,
    )


def halftone(n: Any, level: Any, bits: Any, order: Any = None, matrix: Any = None) -> Solution:
    return api.halftone(
        n,
        level=level,
        bits=1 if bits is None else bits,
        order=_text(order) or "bayer",
        matrix=matrix,
    )


def printer(dpi: Any, lpi: Any, cell: Any, levels: Any, count: Any, dots: Any) -> Solution:
    return api.printer(
        dpi,
        lpi,
        cell=cell,
        levels=levels,
        count=_text(count) or "n2+1",
        dots=_text(dots) or "whole",
    )


def inside(words: list[str], rule: Any, boundary: Any) -> Solution:
    vertices, points = numbers_around(words, "--points", "points")
    return api.inside(vertices, points, rule=_text(rule), boundary=_text(boundary))


def char_storage(
    count: Any,
    width: Any,
    height: Any,
    packing: Any,
    char: Any = None,
    first: Any = None,
    base: Any = None,
) -> Solution:
    return api.char_storage(
        count,
        width,
        height,
        packing=_text(packing),
        char=char,
        first=0 if first is None else first,
        base=0 if base is None else _address(base),
    )


def _address(text: Any) -> int:
    """A memory address as a user writes it: decimal (``4096``) or hexadecimal (``0x1000``).

    >>> _address("0x1000"), _address("4096")
    (4096, 4096)
    """
    s = str(text).strip().lower()
    try:
        return int(s[2:], 16) if s.startswith("0x") else int(s)
    except ValueError:
        raise InputError(
            f"an address is a whole number or 0x hexadecimal, got {text!r}", "base"
        ) from None


BODIES: dict[str, Body] = {
    fn.__name__: fn
    for fn in (
        quantize, transform, color, clip_convex, clip_polygon, dither_ordered, dither_lookup,
        halftone, printer, inside, char_storage,
    )
}  # fmt: skip
"""Each command's answer, by the command's function name (``parametric_circle``), for the
commands not yet declared by their library function (:mod:`.declared`)."""
