"""The named choices of the algorithms, in one small module.

The command line builds its options from these enums at start-up, so they live apart from the
algorithms that use them: asking for ``scanconv line`` loads no circle, clipping or fill code.
Each algorithm module imports its own back, so ``scanconv.algorithms.lines.LineAlgorithm`` is
the same class as ``scanconv.algorithms.choices.LineAlgorithm``.
"""

from __future__ import annotations

from enum import Enum
from typing import Literal

LineAlgorithmName = Literal["bresenham", "dda", "basic", "wu", "midpoint", "symmetric-dda"]
"""``algo`` of :func:`scanconv.line`, the API's ``Literal`` (what mypy checks a name against):
one line method's name here and in :class:`LineAlgorithm` just below, the two side by side
(``tests/test_api_typing.py`` checks they agree, ``tests/test_methods.py`` that each has its
record). It lives beside the enum, not in :mod:`scanconv.core.choices`, so that a new line
method is named in one file."""


class LineAlgorithm(str, Enum):
    """The line algorithms, by the names the API and the CLI (``--algo``) take
    (:data:`LineAlgorithmName`, in the same order)."""

    bresenham = "bresenham"
    dda = "dda"
    basic = "basic"
    wu = "wu"
    """Xiaolin Wu's anti-aliased line (the table of :mod:`scanconv.answers.process.antialias.sampling`)."""
    midpoint = "midpoint"
    """The midpoint line algorithm: d = F(M), Bresenham's p with its own derivation."""
    symmetric_dda = "symmetric-dda"
    """The symmetric DDA: both coordinates stepped by ε Δ, ε = 2^-n (Rogers)."""


class Rounding(str, Enum):
    """How a computed coordinate becomes a pixel coordinate."""

    half_up = "half-up"
    trunc = "trunc"
    half_even = "half-even"
    c_cast = "c-cast"
    half_away = "half-away"


class Tie(str, Enum):
    """What a decision parameter of exactly 0 chooses."""

    step = "step"
    keep = "keep"


class Start(str, Enum):
    """Which end point a line's walk starts from."""

    swap = "swap"
    given = "given"


class LineScale(str, Enum):
    """The midpoint line's decision variable: d = 2F(M) in integers or d = F(M) in halves."""

    integer = "integer"
    half = "half"


class WuEnds(str, Enum):
    """Wu's end points (the ``ends`` convention, :data:`scanconv.algorithms.wu.ENDS`)."""

    full = "full"
    coverage = "coverage"


class Layout(str, Enum):
    """The step table's row shape: the notes' or the textbook's."""

    notes = "notes"
    textbook = "textbook"


class Convention(str, Enum):
    """The named presets (:data:`PRESETS`)."""

    notes = "notes"
    hearn_baker = "hearn-baker"
    foley = "foley"
    wikipedia = "wikipedia"
