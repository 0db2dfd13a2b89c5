"""The API of the colour and theory commands: :func:`color` (``scanconv color``) and
:func:`theory` (``scanconv theory``). Library modules are imported inside the functions
(start-up time)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..core import lazy
from ..core.checks import check_whole
from ..core.choices import (
    ColorModelName,
)
from ..display import answers
from .values import NumberLike, _number

if TYPE_CHECKING:
    from ..answers import color as answers_color
    from ..answers import topics as answers_topics
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_color = lazy.module("scanconv.answers.color")
    answers_topics = lazy.module("scanconv.answers.topics")


@answers
def color(
    model: ColorModelName,
    *values: NumberLike,
    to: str | Sequence[str] = (),
    unit: bool = False,
    bits: NumberLike = 8,
) -> Solution:
    """Convert a colour (``scanconv color``): ``model`` is ``rgb``, ``cmy``, ``hsv``,
    ``hsi`` or ``grey``; ``to`` the models to convert to (default: every other one). RGB and
    grey are integers ``0 .. 2**bits - 1`` unless ``unit`` (then ``0 .. 1``); CMY, S, V, I
    are in ``[0, 1]`` and hue in degrees.

    >>> color("rgb", 51, 102, 153, to="cmy").data["cmy"]
    [Fraction(4, 5), Fraction(3, 5), Fraction(2, 5)]
    """
    targets = [to] if isinstance(to, str) else list(to)
    b = _number(bits, "bits")
    return answers_color.color_solution(
        model,
        [_number(v, "values") for v in values],
        [t for spec in targets for t in spec.replace(",", " ").split()],
        unit=unit,
        bits=check_whole(b, "bits", param="bits"),
    )


@answers
def theory(topic: str) -> Solution:
    """The model answer to the theory question ``topic`` (``scanconv theory``); the names
    are those of ``scanconv theory --list``.

    >>> theory("symmetry").tables[-1].title
    'The eight images of (2, 5) about the centre (0, 0)'
    """
    return answers_topics.theory_solution(topic)
