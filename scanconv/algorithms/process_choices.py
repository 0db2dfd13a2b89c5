"""The named choices of clipping, filling and anti-aliasing, apart from the line and circle
choices of :mod:`.choices` so that those commands load none of these at start-up."""

from __future__ import annotations

from enum import Enum

from .choices import WuEnds

__all__ = [
    "AAMethod",
    "Across",
    "FillRule",
    "LineClipMethod",
    "Order",
    "PolygonClipMethod",
    "Subgrid",
    "WuEnds",
]  # WuEnds lives with the line's choices (line --algo wu takes it)


class LineClipMethod(str, Enum):
    """The line clipping methods, by the names the API and the CLI (``--method``) take."""

    cohen_sutherland = "cohen-sutherland"
    liang_barsky = "liang-barsky"
    cyrus_beck = "cyrus-beck"
    midpoint_subdivision = "midpoint-subdivision"
    nicholl_lee_nicholl = "nicholl-lee-nicholl"


class PolygonClipMethod(str, Enum):
    """The polygon clipping methods."""

    sutherland_hodgman = "sutherland-hodgman"
    weiler_atherton = "weiler-atherton"


class AAMethod(str, Enum):
    """Anti-aliasing methods, by the names the API and the CLI (``--method``) take; ``wu`` is
    for lines only (:mod:`scanconv.algorithms.wu`)."""

    area = "area"
    supersample = "supersample"
    wu = "wu"
    subpixel = "subpixel"


class Across(str, Enum):
    """How a line's width is measured (the ``across`` convention,
    :data:`scanconv.algorithms.coverage.ACROSS`)."""

    minor = "minor"
    perpendicular = "perpendicular"


class Subgrid(str, Enum):
    """Where Hearn & Baker's sub-pixel line runs (the ``subgrid`` convention,
    :data:`scanconv.algorithms.subpixel.SUBGRIDS`)."""

    span = "span"
    centre = "centre"


class Divide(str, Enum):
    """How a sub-pixel count becomes an intensity (the ``divide`` convention of
    :func:`scanconv.answers.process.antialias.subpixel.subpixel_solution`)."""

    n = "n"
    n2 = "n2"


class FillRule(str, Enum):
    """The fill rules, by the names the API and the CLI (``--rule``) take."""

    even_odd = "even-odd"
    nonzero = "nonzero"


class Order(str, Enum):
    """How the pending pixels are taken: last in first out (the recursion's order) or first
    in first out (breadth first)."""

    stack = "stack"
    queue = "queue"
