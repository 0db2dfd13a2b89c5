"""The ideal primitive an answer's pixels stand for, as typed values: what a figure draws over
the pixel grid (a red line, circle, ellipse or sampled curve, a green control polygon).

An answer lists its shapes in :attr:`~scanconv.core.records.Plot.ideal`, in drawing order; a
figure matches each by its type (:mod:`scanconv.render.figures.figure`, :mod:`scanconv.render.html.stepgrid`).
Coordinates are the answer's own numbers (ints, fractions or floats), y up.
"""

from collections.abc import Iterable, Sequence
from typing import NamedTuple

from .numeric import Number

Coordinate = Number | float
"""A coordinate of an ideal shape: exact when the question is, a float for a sampled curve."""


class IdealLine(NamedTuple):
    """The ideal line segment from ``(x1, y1)`` to ``(x2, y2)``."""

    x1: Coordinate
    y1: Coordinate
    x2: Coordinate
    y2: Coordinate


class IdealCircle(NamedTuple):
    """The ideal circle of radius ``r`` about ``(xc, yc)``."""

    xc: Coordinate
    yc: Coordinate
    r: Coordinate


class IdealEllipse(NamedTuple):
    """The ideal axis-aligned ellipse with semi-axes ``rx``, ``ry`` about ``(xc, yc)``."""

    xc: Coordinate
    yc: Coordinate
    rx: Coordinate
    ry: Coordinate


class Polyline(NamedTuple):
    """A sampled ideal curve or a closed outline (a polygon, a window), its points in order."""

    points: Sequence[tuple[float, float]]
    """The points, joined in order (a closed one repeats its first point last)."""
    name: str = "curve"
    """What it is called in a figure's legend (``"curve"``, ``"polygon"``, ``"window"``)."""


class ControlPolygon(NamedTuple):
    """A curve's control points, drawn as a polygon with its points (Bezier, B-spline)."""

    points: Sequence[tuple[float, float]]


Ideal = IdealLine | IdealCircle | IdealEllipse | Polyline | ControlPolygon
"""Any shape of the ideal primitive."""


def ideal_kinds(ideal: Iterable[Ideal]) -> list[str]:
    """What a legend's "ideal ..." names: each line, circle, ellipse and (non-empty) sampled
    curve by its name, in order; a control polygon has an entry of its own.

    >>> ideal_kinds((IdealLine(0, 0, 1, 1), Polyline([(0.0, 0.0)], "window"), ControlPolygon([])))
    ['line', 'window']
    """
    kinds: list[str] = []
    for shape in ideal:
        match shape:
            case IdealLine():
                kinds.append("line")
            case IdealCircle():
                kinds.append("circle")
            case IdealEllipse():
                kinds.append("ellipse")
            case Polyline(points, name) if points:
                kinds.append(name)
    return kinds


def control_points(ideal: Iterable[Ideal]) -> list[tuple[float, float]]:
    """The control points among ``ideal``'s shapes, in order (drawn as rings over the grid).

    >>> control_points((IdealLine(0, 0, 1, 1), ControlPolygon([(0.0, 0.0), (2.0, 1.0)])))
    [(0.0, 0.0), (2.0, 1.0)]
    """
    return [p for s in ideal if isinstance(s, ControlPolygon) for p in s.points]
