"""The free word lists some commands take first, read by the library function that declares
them (:func:`scanconv.core.declare.words`): ``transform``'s points and then its
transformations, the numbers around a flag (``inside``'s ``--points``, ``clip convex``'s and
``clip polygon``'s ``--window-vertices``). Each reader takes the words and the command's other
arguments and gives the library function's arguments; bad words are one line, as the command
line words them (``No such option: --bogus``, ``Invalid value: 'x' is not a number``)."""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..core import lazy
from ..core.checks import InputError, looks_like_option
from ..core.numeric import parse_number

if TYPE_CHECKING:
    from ..answers.process import transform as answers_transform
else:
    answers_transform = lazy.module("scanconv.answers.process.transform")

TRANSFORM_WORDS = {"--translate", "--scale", "--rotate", "--reflect", "--shear", "--about"}
TRANSFORM_WORDS |= {"--points"}
"""The words of ``transform`` that start a transformation (or more points)."""


def _number(word: str) -> Fraction:
    """A word that must be a number: a flag where one was expected is "No such option", any
    other bad word an "Invalid value"."""
    try:
        return parse_number(word)
    except ValueError as err:
        if looks_like_option(word):
            raise InputError(f"No such option: {word.strip()}") from None
        raise InputError(f"Invalid value: {err}") from None


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
        _number(word)
    if not word.startswith("-") or word.split("=", 1)[0] in TRANSFORM_WORDS or _is_number(word):
        return
    try:
        answers_transform.parse_angle(word)
    except ValueError:
        raise InputError(f"No such option: {word.split('=', 1)[0]}") from None


def split_words(words: Sequence[str]) -> tuple[list[Fraction], list[str]]:
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
            points.append(parse_number(word))
        else:
            taking = False
            ops.append(word)
    return points, ops


def numbers_around(
    words: Sequence[str], flag: str, required: bool = True
) -> tuple[list[Fraction], list[Fraction]]:
    """``X1 Y1 ... FLAG X Y ...`` (the words of ``inside`` and ``clip convex``): the numbers
    before ``flag`` and the numbers after it.

    >>> numbers_around(["0", "0", "--points", "1", "-2"], "--points")
    ([Fraction(0, 1), Fraction(0, 1)], [Fraction(1, 1), Fraction(-2, 1)])
    """
    before: list[Fraction] = []
    after: list[Fraction] = []
    taking = before
    for word in words:
        name, eq, value = word.partition("=")
        if name == flag:
            taking = after
            if not eq:
                continue
            word = value
        taking.append(_number(word))
    if not after and required:
        raise InputError(f"Missing option '{flag}' (give {flag} X Y ...)")
    return before, after


def transform_words(words: Sequence[str], given: dict[str, Any]) -> dict[str, Any]:
    """``transform``: the points, then the transformations."""
    points, ops = split_words(words)
    return {"points": points, "transforms": ops, **given}


def inside_words(words: Sequence[str], given: dict[str, Any]) -> dict[str, Any]:
    """``inside``: the polygon's vertices, then ``--points`` and the points tested."""
    vertices, points = numbers_around(words, "--points")
    return {"vertices": vertices, "points": points, **given}


def clip_convex_words(words: Sequence[str], given: dict[str, Any]) -> dict[str, Any]:
    """``clip convex``: the segment's end points, then ``--window-vertices`` and the
    window's."""
    ends, window = numbers_around(words, "--window-vertices")
    if len(ends) != 4:
        raise InputError(
            f"give the segment's end points X1 Y1 X2 Y2 before --window-vertices, got "
            f"{len(ends)} number(s)"
        )
    x1, y1, x2, y2 = ends
    return {"x1": x1, "y1": y1, "x2": x2, "y2": y2, "window": window, **given}


def clip_polygon_words(words: Sequence[str], given: dict[str, Any]) -> dict[str, Any]:
    """``clip polygon``: the polygon's vertices, and the window as ``--window`` (a rectangle)
    or ``--window-vertices X Y ...`` after them (a polygon), one or the other."""
    vertices, corners = numbers_around(words, "--window-vertices", required=False)
    window = given.get("window")
    if corners and window is not None:
        raise InputError("give the window as --window or --window-vertices, not both")
    if not corners and window is None:
        raise InputError(
            "Missing option '--window' (give --window XMIN YMIN XMAX YMAX, or "
            "--window-vertices X Y ... after the polygon)"
        )
    return {**given, "vertices": vertices, "window": corners or window}
