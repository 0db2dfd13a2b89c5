"""The Python API: the scan-conversion process (``scanconv transform``, ``viewport``, ``clip``, ``pipeline``). See :mod:`scanconv._api`."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..algorithms.choices import LineAlgorithm
from ..core import lazy
from ..core.checks import InputError
from ..core.choices import (
    ClipEndsName,
    FillRuleName,
    LineAlgorithmName,
    LineClipMethodName,
    MidpointName,
    NormalsName,
    PolygonClipMethodName,
)
from ..display import answers
from .values import NumberLike, PointsLike, _choice, _flat, _numbers, _rect

if TYPE_CHECKING:
    from ..algorithms.process_choices import FillRule, LineClipMethod, PolygonClipMethod
    from ..answers import clip as answers_clip
    from ..answers import clip_polygon as answers_clip_polygon
    from ..answers import cyrus_beck as answers_cyrus_beck
    from ..answers import midpoint_clip as answers_midpoint_clip
    from ..answers import nll as answers_nll
    from ..answers import pipeline as answers_pipeline
    from ..answers import transform as answers_transform
    from ..answers import viewport as answers_viewport
    from ..answers import weiler_atherton as answers_weiler_atherton
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_clip = lazy.module("scanconv.answers.clip")
    answers_clip_polygon = lazy.module("scanconv.answers.clip_polygon")
    answers_cyrus_beck = lazy.module("scanconv.answers.cyrus_beck")
    answers_midpoint_clip = lazy.module("scanconv.answers.midpoint_clip")
    answers_nll = lazy.module("scanconv.answers.nll")
    answers_pipeline = lazy.module("scanconv.answers.pipeline")
    answers_transform = lazy.module("scanconv.answers.transform")
    answers_viewport = lazy.module("scanconv.answers.viewport")
    answers_weiler_atherton = lazy.module("scanconv.answers.weiler_atherton")


@answers
def transform(
    points: PointsLike, transforms: str | Sequence[str], inverse: bool = False
) -> Solution:
    """The composite of ``transforms`` applied to ``points`` (``scanconv transform``).

    ``transforms`` is a string or a list of words, applied in order: ``"rotate 90 about 2 1,
    translate 3 0"`` (see :mod:`scanconv.answers.transform`); ``inverse`` also shows M^-1.

    >>> transform([(0, 0), (4, 0)], "rotate 90 about 2 1, translate 3 0").data["after"]
    [[6, -1], [6, 3]]
    """
    return answers_transform.transform_solution(
        _flat(points, "points"), transforms, inverse_too=bool(inverse)
    )


@answers
def viewport(
    window: Sequence[NumberLike], viewport: Sequence[NumberLike], points: PointsLike = ()
) -> Solution:
    """The window-to-viewport mapping of ``points`` (default: the window's corners)
    (``scanconv viewport``).

    >>> viewport((0, 0, 10, 10), (100, 100, 150, 200), [(5, 5)]).data["mapped"]
    [[125, 150]]
    """
    return answers_viewport.viewport_solution(
        _flat(points, "points"), _rect(window, "window"), _rect(viewport, "viewport")
    )


@answers
def clip_line(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    window: Sequence[NumberLike],
    method: LineClipMethod | LineClipMethodName = "cohen-sutherland",
    *,
    normals: NormalsName | None = None,
    ends: ClipEndsName | None = None,
    midpoint: MidpointName | None = None,
) -> Solution:
    """The segment clipped against ``window`` (``scanconv clip line``).

    ``method`` is ``cohen-sutherland``, ``liang-barsky``, ``cyrus-beck`` (the rectangle as a
    convex window; ``normals`` outward or inward, ``ends`` exact or truncated) or
    ``midpoint-subdivision`` (``midpoint`` rounded, floor or exact) or
    ``nicholl-lee-nicholl`` (P1's region, the slope tests, P2's region).

    >>> clip_line(7, 9, 11, 4, (4, 4, 10, 8)).data["clipped"]
    [[Fraction(39, 5), 8], [10, Fraction(21, 4)]]
    >>> clip_line(7, 9, 11, 4, (4, 4, 10, 8), "cyrus-beck").data["clipped"]
    [[Fraction(39, 5), 8], [10, Fraction(21, 4)]]
    """
    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    rect = _rect(window, "window")
    name = _choice(method, "method")
    _only(name, {"normals": normals, "ends": ends}, "cyrus-beck")
    _only(name, {"midpoint": midpoint}, "midpoint-subdivision")
    if name == "cyrus-beck":
        x0, y0, x1_, y1_ = rect
        corners = [x0, y0, x1_, y0, x1_, y1_, x0, y1_]
        return answers_cyrus_beck.cyrus_beck_solution(
            a, b, c, d, corners, normals=normals or "outward", ends=ends or "exact"
        )
    if name == "midpoint-subdivision":
        return answers_midpoint_clip.midpoint_clip_solution(
            a, b, c, d, list(rect), midpoint=midpoint or "rounded"
        )
    if name == "nicholl-lee-nicholl":
        return answers_nll.nll_solution(a, b, c, d, rect)
    return answers_clip.clip_line_solution(a, b, c, d, rect, name)


def _only(method: str, given: dict[str, str | None], owner: str) -> None:
    """Refuse a convention given to a method it does not apply to."""
    for param, value in given.items():
        if value is not None and method != owner:
            raise InputError(f"{param} applies to {owner} only, not to {method}", param)


@answers
def clip_convex(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    window: PointsLike,
    *,
    normals: NormalsName = "outward",
    ends: ClipEndsName = "exact",
) -> Solution:
    """Cyrus-Beck clipping against any convex window given by its vertices
    (``scanconv clip convex``).

    >>> clip_convex(-1, 2, 9, 2, [(0, 0), (8, 0), (0, 8)]).data["clipped"]
    [[0, 2], [6, 2]]
    """
    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return answers_cyrus_beck.cyrus_beck_solution(
        a, b, c, d, _flat(window, "window"), normals=normals, ends=ends
    )


@answers
def clip_polygon(
    vertices: PointsLike,
    window: Sequence[NumberLike],
    method: PolygonClipMethod | PolygonClipMethodName = "sutherland-hodgman",
) -> Solution:
    """The polygon clipped against ``window`` by Sutherland-Hodgman or Weiler-Atherton
    (``scanconv clip polygon``).

    >>> clip_polygon([(0, 0), (4, 0), (0, 4)], (1, 1, 3, 3)).data["clipped"]
    [[1, 3], [1, 1], [3, 1]]
    >>> clip_polygon([(0, 0), (8, 0), (8, 8)], (2, 1, 9, 3), "weiler-atherton").data["polygons"]
    [[[8, 1], [8, 3], [3, 3], [2, 2], [2, 1]]]
    """
    name = _choice(method, "method")
    flat, rect = _flat(vertices, "vertices"), _rect(window, "window")
    if name == "weiler-atherton":
        x0, y0, x1, y1 = rect
        return answers_weiler_atherton.weiler_atherton_solution(
            flat, [x0, y0, x1, y0, x1, y1, x0, y1]
        )
    if name != "sutherland-hodgman":
        raise InputError(
            f"unknown polygon clipping method {name!r} (sutherland-hodgman, weiler-atherton)",
            "method",
        )
    return answers_clip_polygon.clip_polygon_solution(flat, rect)


@answers
def pipeline_line(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    window: Sequence[NumberLike],
    viewport: Sequence[NumberLike],
    algo: LineAlgorithm | LineAlgorithmName = LineAlgorithm.bresenham,
    clip: LineClipMethod | LineClipMethodName = "cohen-sutherland",
) -> Solution:
    """A world-coordinate line clipped, mapped, rounded and scan converted
    (``scanconv pipeline line``).

    >>> pipeline_line(-5, 0, 15, 10, (0, 0, 10, 10), (0, 0, 20, 10)).data["rounded"]
    [[0, 3], [20, 8]]
    """
    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return answers_pipeline.pipeline_line_solution(
        a,
        b,
        c,
        d,
        _rect(window, "window"),
        _rect(viewport, "viewport"),
        algo=_choice(algo, "algo"),
        clip=_choice(clip, "clip"),
    )


@answers
def pipeline_polygon(
    vertices: PointsLike,
    window: Sequence[NumberLike],
    viewport: Sequence[NumberLike],
    fill: bool = False,
    rule: FillRule | FillRuleName = "even-odd",
) -> Solution:
    """A world-coordinate polygon clipped (Sutherland-Hodgman), mapped to the viewport, then
    outlined or, with ``fill``, scan-line filled (``scanconv pipeline polygon``).

    >>> pipeline_polygon([(-2, 0), (6, 0), (2, 6)], (0, 0, 4, 4), (0, 0, 8, 8)).data["device"][2]
    [0, 6]
    """
    return answers_pipeline.pipeline_polygon_solution(
        _flat(vertices, "vertices"),
        _rect(window, "window"),
        _rect(viewport, "viewport"),
        fill=bool(fill),
        rule=_choice(rule, "rule"),
    )
