"""What an answer's pixels are numbered and marked with: the plotted images of a step's point
under 4- or 8-way symmetry, the step number of every plotted pixel, what the numbers and the
grid's ``o`` mean. Facts about the answer's structure, read once by :mod:`scanconv.document`
(and by the figures of :mod:`scanconv.render.figures.figure`), never guessed again by a format.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from ..core.ideal import ControlPolygon, IdealCircle, IdealEllipse, Polyline
from ..core.records import Numbering, Pixel, Solution


def mirror_images(pixel: Pixel, symmetry: int, center: tuple[Any, Any]) -> Iterator[Pixel]:
    """The plotted pixels of a step's point.

    Without symmetry the point is the pixel. With 4- or 8-way symmetry it is the point
    relative to the centre, as the circle and ellipse tables print it (an octant point
    ``(x, y)`` of the circle about the origin), and its images are ``(xc ± x, yc ± y)`` and,
    for 8-way symmetry, ``(xc ± y, yc ± x)``, in the notes' order.

    >>> list(mirror_images((3, 4), 1, (0, 0)))
    [(3, 4)]
    >>> list(mirror_images((2, 1), 4, (10, 5)))
    [(12, 6), (8, 6), (12, 4), (8, 4)]
    >>> sorted(set(mirror_images((3, 4), 8, (0, 0))))[:4]
    [(-4, -3), (-4, 3), (-3, -4), (-3, 4)]
    """
    if symmetry not in (4, 8):
        yield pixel
        return
    xc, yc = int(center[0]), int(center[1])
    x, y = pixel
    offsets = [(x, y), (-x, y), (x, -y), (-x, -y)]
    if symmetry == 8:
        offsets += [(y, x), (-y, x), (y, -x), (-y, -x)]
    for ox, oy in offsets:
        yield (xc + ox, yc + oy)


def label_offset(solution: Solution) -> int:
    """1 when the step table's pixel column is ``(x_{k+1}, y_{k+1})``, else 0: as the answer
    declares it (:attr:`~scanconv.core.records.Walk.next_pixel`), not as a heading reads.

    >>> from scanconv.answers.primitives.line import line_solution
    >>> label_offset(line_solution("bresenham", 2, 2, 10, 6)), label_offset(
    ...     line_solution("dda", 2, 2, 10, 6))
    (1, 0)
    """
    return 1 if solution.walk.next_pixel else 0


def numbering(solution: Solution) -> Numbering:
    """How :func:`step_labels` numbers the pixels: ``"row"`` (the table's k, or k + 1 when
    its pixel column is ``(x_{k+1}, y_{k+1})``), ``"continued"`` (the table's k, but later
    tables, the ellipse's region 2, carry on from the last number instead of starting again
    at 0) or ``"order"`` (a curve: the plotting order, since several samples may land on one
    pixel and the joining pixels have no sample).
    """
    declared = solution.plot.numbering
    if declared is not None:
        return declared
    curve = any(isinstance(s, Polyline) and s.points for s in solution.plot.ideal)
    if curve and solution.walk.symmetry == 1:
        return "order"
    previous = -1
    for step in solution.steps():
        if step.k <= previous:
            return "continued"
        previous = step.k
    return "row"


def numbering_legend(solution: Solution) -> str:
    """What the numbers in the pixels mean (the legend of the figure and of the HTML grid).

    >>> from scanconv.answers.primitives.line import line_solution
    >>> numbering_legend(line_solution("bresenham", 2, 2, 10, 6))
    'number: k + 1 for row k; 0: start'
    """
    how = numbering(solution)
    if how == "order":
        return f"number: {solution.plot.order_name}"
    if label_offset(solution):
        return "number: k + 1 for row k; 0: start"
    if how == "continued":
        return "number: row k (region 2 counts on)"
    return "number: row k of the step table"


def step_labels(solution: Solution) -> dict[Pixel, int]:
    """The step number of every plotted pixel that has one (see the module's notes and
    :func:`numbering`).

    >>> from scanconv.answers.primitives.line import line_solution
    >>> labels = step_labels(line_solution("bresenham", 2, 2, 10, 6))
    >>> labels[(2, 2)], labels[(3, 3)], labels[(10, 6)]
    (0, 1, 8)
    >>> step_labels(line_solution("dda", 2, 2, 10, 6))[(10, 6)]
    8
    """
    plotted = set(solution.pixels()) if solution.pixels is not None else set()
    labels: dict[Pixel, int] = {}
    how = numbering(solution)
    if how == "none":
        return labels
    if how == "order" and solution.pixels is not None:
        for i, p in enumerate(solution.pixels()):
            labels.setdefault(p, i)
        return labels
    offset = label_offset(solution)
    symmetry, center = solution.walk.symmetry, solution.walk.center
    shift, previous, last = 0, -1, -1
    for step in solution.steps():
        if how == "continued" and step.k <= previous:
            shift = last + 1 - step.k - offset
        previous = step.k
        number = step.k + offset + shift
        last = max(last, number)
        for p in mirror_images(step.pixel, symmetry, center):
            if p in plotted:
                labels.setdefault(p, number)
    if offset:
        for p in plotted:
            labels.setdefault(p, 0)
    return labels


def marks_label(solution: Solution) -> str:
    """What the grid's ``o`` stands for: :attr:`Plot.marks_label`, or worked out from the
    answer's ideal primitive (a curve's control points, a circle's or ellipse's centre).

    >>> from scanconv.answers.primitives.circle import circle_solution
    >>> marks_label(circle_solution("midpoint", 3))
    'centre'
    """
    if solution.marks_label:
        return solution.marks_label
    ideal = solution.plot.ideal
    if any(isinstance(s, ControlPolygon) and s.points for s in ideal):
        return "control point"
    if any(isinstance(s, IdealCircle | IdealEllipse) for s in ideal):
        return "centre"
    return "marked point"
