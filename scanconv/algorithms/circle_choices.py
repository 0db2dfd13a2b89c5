"""The named choices of the circle methods, apart from the line's in :mod:`.choices` so that
``scanconv line`` creates none of them at start-up."""

from __future__ import annotations

from enum import Enum


class CircleMethod(str, Enum):
    """The circle methods, by the names the API and the CLI (``--method``) take: ``general`` is
    the notes' decision method at the point (p0 = 0), ``polynomial`` the √ method."""

    midpoint = "midpoint"
    bresenham = "bresenham"
    polynomial = "polynomial"
    general = "general"
    trig = "trig"
    symmetric_dda = "symmetric-dda"


class P0(str, Enum):
    """The midpoint circle's initial decision parameter as printed."""

    integer = "1-r"
    exact = "5/4-r"


class EllipseP0(str, Enum):
    """How the midpoint ellipse takes each region's first decision parameter."""

    exact = "exact"
    rounded = "rounded"


class Loop(str, Enum):
    """Whether the octant (region-1) loop is strict (``x < y``) or inclusive (``x <= y``)."""

    strict = "strict"
    inclusive = "inclusive"


class XStep(str, Enum):
    """Bresenham's circle: d updated before x += 1 (``last``) or after it (``first``)."""

    last = "last"
    first = "first"


class Update(str, Enum):
    """Whether the midpoint circle's increments are written with the new or the old x."""

    new = "new"
    old = "old"
