"""The named choices of the algorithms, in one small module.

The command line builds its options from these enums at start-up, so they live apart from the
algorithms that use them: asking for ``scanconv line`` loads no circle, clipping or fill code.
Each algorithm module imports its own back, so ``scanconv.algorithms.lines.LineAlgorithm`` is
the same class as ``scanconv.algorithms.choices.LineAlgorithm``.
"""

from __future__ import annotations

from enum import Enum


class LineAlgorithm(str, Enum):
    """The line algorithms, by the names the API and the CLI (``--algo``) take."""

    bresenham = "bresenham"
    dda = "dda"
    basic = "basic"
    wu = "wu"
    """Xiaolin Wu's anti-aliased line (the table of :mod:`scanconv.answers.antialias`)."""


class CircleMethod(str, Enum):
    """The circle methods, by the names the API and the CLI (``--method``) take: ``general`` is
    the notes' decision method at the point (p0 = 0), ``polynomial`` the √ method."""

    midpoint = "midpoint"
    bresenham = "bresenham"
    polynomial = "polynomial"
    general = "general"
    trig = "trig"
    symmetric_dda = "symmetric-dda"


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


class P0(str, Enum):
    """The midpoint circle's initial decision parameter as printed."""

    integer = "1-r"
    exact = "5/4-r"


class Loop(str, Enum):
    """Whether the octant (region-1) loop is strict (``x < y``) or inclusive (``x <= y``)."""

    strict = "strict"
    inclusive = "inclusive"


class Update(str, Enum):
    """Whether the midpoint circle's increments are written with the new or the old x."""

    new = "new"
    old = "old"


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


class LineClipMethod(str, Enum):
    """The line clipping methods, by the names the API and the CLI (``--method``) take."""

    cohen_sutherland = "cohen-sutherland"
    liang_barsky = "liang-barsky"


class PolygonClipMethod(str, Enum):
    """The polygon clipping methods (one, named for symmetry with the line methods)."""

    sutherland_hodgman = "sutherland-hodgman"


class AAMethod(str, Enum):
    """Anti-aliasing methods, by the names the API and the CLI (``--method``) take; ``wu`` is
    for lines only (:mod:`scanconv.algorithms.wu`)."""

    area = "area"
    supersample = "supersample"
    wu = "wu"


class FillRule(str, Enum):
    """The fill rules, by the names the API and the CLI (``--rule``) take."""

    even_odd = "even-odd"
    nonzero = "nonzero"


class Order(str, Enum):
    """How the pending pixels are taken: last in first out (the recursion's order) or first
    in first out (breadth first)."""

    stack = "stack"
    queue = "queue"
