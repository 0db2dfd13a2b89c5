"""The worked answer of the depth-sort (painter's) method: the polygons by farthest depth, the
tests of each pair in order (z, x and y extents, the plane side tests, the projections), the
painting order and the frame painted."""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import Any

from ...algorithms import visible_depthsort as ds
from ...algorithms.polygon import fill_pixels
from ...algorithms.visible_zbuffer import check_plane
from ...core.numeric import fmt_short
from ...core.records import Solution, Table, Walk, heading, rule, worked
from ._shared import buffer_tables, convention_note, knobs_for, letter, plane_tex, vec
from .zbuffer import polygons_from, size_of

_WORDS = {
    "z": ("depth extents overlap", "S wholly farther"),
    "x": ("x extents overlap", "x extents apart"),
    "y": ("y extents overlap", "y extents apart"),
    "behind": ("S not wholly behind the plane of S'", "S behind the plane of S'"),
    "front": ("S' not wholly in front of the plane of S", "S' in front of the plane of S"),
    "apart": ("projections overlap", "projections apart"),
}
"""Each test's outcome in words: (failed, passed)."""


def _extents(face: Any) -> str:
    return ", ".join(
        f"{axis} {fmt_short(min(v[i] for v in face))}..{fmt_short(max(v[i] for v in face))}"
        for i, axis in enumerate("xyz")
    )


def _tests_table(result: ds.DepthSort) -> Table:
    def rows() -> Iterator[tuple[Any, ...]]:
        for t in result.tests:
            said = "; ".join(f"{n}: {_WORDS[n][ok]}" for n, ok in t.results)
            if t.cycle:
                outcome = (
                    f"all fail and {letter(t.second)} moved before: cyclic overlap, split needed"
                )
            elif t.passed is None:
                outcome = f"all fail: {letter(t.second)} moves before {letter(t.first)}"
            else:
                outcome = f"passes ({t.passed})"
            yield (t.k, letter(t.first), letter(t.second), said, outcome)

    return Table(
        "Pairs tested (S, the next to paint, against each S'), each test in order until one passes",
        (
            heading("k", "k", role="label"),
            heading("S", "S", role="given"),
            heading("S2", "S'", role="given"),
            heading("tests", r"\text{tests}", role="working"),
            heading("outcome", r"\text{outcome}"),
        ),
        rows,
    )


def _painted(
    polys: Sequence[Any], order: Sequence[int], width: int, height: int
) -> dict[tuple[int, int], int]:
    """The frame painted in ``order``: each pixel the last polygon (by index) that covers it."""
    frame: dict[tuple[int, int], int] = {}
    for i in order:
        for x, y in fill_pixels([(v[0], v[1]) for v in polys[i][1]]):
            if 0 <= x < width and 0 <= y < height:
                frame[(x, y)] = i
    return frame


def depth_sort_solution(
    polygons: Sequence[Any],
    *,
    size: str | None = None,
    conventions: Mapping[str, str | None] | None = None,
    convention: str | None = None,
) -> Solution:
    """The depth sort of the polygons (numbers ``x y z ...``, ``:`` between them), painted on a
    ``W x H`` grid.

    >>> sol = depth_sort_solution([0, 0, 3, 4, 0, 3, 0, 4, 3, ":", 0, 0, 1, 4, 0, 1, 0, 4, 1])
    >>> sol.data["painted"], sol.data["frame"]["0,0"]
    (['B', 'A'], 'A')
    """
    knobs = knobs_for("depth-sort", conventions or {}, convention)
    polys = polygons_from(polygons)
    width, height = size_of(size, polys)
    result = ds.depth_sort(polys, knobs)
    frame = _painted(polys, result.painted, width, height)
    names = [n for n, _ in polys]
    given = (
        *(worked(n, f, f"{n}: " + ", ".join(vec(v) for v in f)) for n, f in polys),
        worked(
            "grid", (width, height), f"\\text{{grid: }} {width} \\times {height} \\text{{ pixels}}"
        ),
    )
    derived = (
        rule(
            "sort",
            r"\text{sort by the farthest depth, the farthest first; paint S when every S' passes a test}",
        ),
        *(rule(f"test_{n}", f"\\text{{{n}: {_WORDS[n][1]}}}") for n in ds.TESTS),
        *(worked(f"extent_{n}", None, f"\\text{{{n}: {_extents(f)}}}") for n, f in polys),
        *(worked(f"plane_{n}", None, plane_tex(n, check_plane(n, f))) for n, f in polys),
        worked(
            "initial",
            [names[i] for i in result.initial],
            r"\text{by farthest depth: } " + ", ".join(names[i] for i in result.initial),
        ),
        worked(
            "painted",
            [names[i] for i in result.painted],
            r"\text{painting order: } " + ", ".join(names[i] for i in result.painted),
        ),
    )
    notes = (
        (
            "A cyclic overlap: each polygon would have to be painted before the other, so one "
            "must be split along the other's plane (not done here); the rest is painted in the "
            "list's order."
            if result.cycle
            else "Painted in order, the farthest first: a later polygon overwrites an earlier one."
        ),
        "Orthographic view along z; each polygon's pixels are the scan-line fill's.",
        convention_note(knobs, convention),
    )
    frame_table, _ = buffer_tables(frame, {}, width, height, "-")
    return Solution(
        primitive="3d",
        algorithm="depth-sort",
        title=f"Depth sort (painter's method): {len(polys)} polygon(s)",
        given=given,
        derived=derived,
        notes=notes,
        walk=Walk(tables=(_tests_table(result), frame_table)),
        data={
            "initial": [names[i] for i in result.initial],
            "painted": [names[i] for i in result.painted],
            "cycle": result.cycle,
            "tests": [
                {"S": names[t.first], "S2": names[t.second], "passed": t.passed}
                for t in result.tests
            ],
            "frame": {f"{x},{y}": letter(i) for (x, y), i in sorted(frame.items())},
            "conventions": dict(knobs),
        },
    )
