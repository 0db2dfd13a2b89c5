"""The worked answer of the depth-sort (painter's) method: the polygons by farthest depth, the
tests of each pair in order (z, x and y extents, the plane side tests, the projections), the
splits that resolve a cyclic overlap (each vertex's side of the plane, the split line, the
pieces), the painting order and the frame painted."""

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
    name = [p.name for p in result.polygons]

    def rows() -> Iterator[tuple[Any, ...]]:
        for t in result.tests:
            said = "; ".join(f"{n}: {_WORDS[n][ok]}" for n, ok in t.results)
            if t.split is not None:
                cut = result.splits[t.split]
                first, second = (name[i] for i in cut.pieces)
                outcome = (
                    f"all fail and {name[t.second]} moved before: cyclic overlap; "
                    f"{name[cut.polygon]} split by the plane of {name[cut.by]} "
                    f"into {first} and {second}"
                )
            elif t.cycle:
                outcome = (
                    f"all fail and {name[t.second]} moved before: cyclic overlap, and no "
                    "plane cuts a polygon of the list"
                )
            elif t.passed is None:
                outcome = f"all fail: {name[t.second]} moves before {name[t.first]}"
            else:
                outcome = f"passes ({t.passed})"
            yield (t.k, name[t.first], name[t.second], said, outcome)

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


def _splits_table(result: ds.DepthSort) -> Table:
    """Each split: the polygon, the plane, each vertex's side of it, the split line, the
    pieces (the viewer's side first)."""
    name = [p.name for p in result.polygons]

    def rows() -> Iterator[tuple[Any, ...]]:
        for n, cut in enumerate(result.splits):
            face = result.polygons[cut.polygon].face
            sides = ", ".join(
                f"{vec(v)}: {fmt_short(d)}" for v, d in zip(face, cut.sides, strict=True)
            )
            pieces = "; ".join(
                f"{name[i]}: " + ", ".join(vec(v) for v in result.polygons[i].face)
                for i in cut.pieces
            )
            line = f"{vec(cut.line[0])} to {vec(cut.line[1])}"
            yield (n + 1, cut.k, name[cut.polygon], name[cut.by], sides, line, pieces)

    return Table(
        "Splits (a cyclic overlap: the polygon cut along the other's plane, "
        "A x + B y + C z + D with the viewer's side positive)",
        (
            heading("split", r"\text{split}", role="label"),
            heading("k", "k", role="given"),
            heading("polygon", r"\text{polygon}", role="given"),
            heading("plane", r"\text{plane of}", role="given"),
            heading("sides", r"\text{each vertex's side}", role="working"),
            heading("line", r"\text{split line}"),
            heading("pieces", r"\text{pieces (the viewer's side first)}"),
        ),
        rows,
    )


def _painted(result: ds.DepthSort, width: int, height: int) -> dict[tuple[int, int], int]:
    """The frame painted in the sort's order: each pixel the given polygon (by index) of the
    last polygon or piece that covers it."""
    frame: dict[tuple[int, int], int] = {}
    for i in result.painted:
        piece = result.polygons[i]
        for x, y in fill_pixels([(v[0], v[1]) for v in piece.face]):
            if 0 <= x < width and 0 <= y < height:
                frame[(x, y)] = piece.origin
    return frame


def _split_working(result: ds.DepthSort) -> tuple[Any, ...]:
    """The split rule and each split's line and pieces, as working."""
    if not result.splits:
        return ()
    name = [p.name for p in result.polygons]
    out: list[Any] = [
        rule(
            "split",
            r"\text{cyclic overlap: cut } S' \text{ by the plane of } S \text{; on the edge } "
            r"V_i V_j \text{ with } d_i d_j < 0 \text{: } V_i + (V_j - V_i)\, d_i / (d_i - d_j)",
        )
    ]
    for n, cut in enumerate(result.splits, start=1):
        first, second = (name[i] for i in cut.pieces)
        out.append(
            worked(
                f"split_{n}",
                [list(p) for p in cut.line],
                f"\\text{{split {n}: {name[cut.polygon]} by the plane of {name[cut.by]}, "
                f"along {vec(cut.line[0])} to {vec(cut.line[1])}, into {first} and {second}}}",
            )
        )
    return tuple(out)


def _cycle_note(result: ds.DepthSort) -> str:
    if result.splits:
        return (
            f"A cyclic overlap: S' had moved before S once and fails again, so it is split along "
            f"the plane of S (Hearn & Baker, section 13-5), and the two pieces take its place in "
            f"the list by their farthest depth ({len(result.splits)} split(s), at most "
            f"{ds.MAX_SPLITS}); the marks are cleared and the tests start again."
        )
    if result.cycle:
        return (
            "A cyclic overlap that no polygon's plane cuts: the rest is painted in the list's "
            "order."
        )
    return "Painted in order, the farthest first: a later polygon overwrites an earlier one."


def _data(
    result: ds.DepthSort, frame: Mapping[tuple[int, int], int], knobs: Mapping[str, str]
) -> dict[str, Any]:
    """The JSON data: the orders, the tests, the splits (exact numbers), the frame."""
    names = [p.name for p in result.polygons]
    return {
        "initial": [names[i] for i in result.initial],
        "painted": [names[i] for i in result.painted],
        "cycle": result.cycle,
        "tests": [
            {"S": names[t.first], "S2": names[t.second], "passed": t.passed} for t in result.tests
        ],
        "splits": [
            {
                "polygon": names[cut.polygon],
                "by": names[cut.by],
                "sides": list(cut.sides),
                "line": [list(p) for p in cut.line],
                "pieces": {
                    names[i]: [list(v) for v in result.polygons[i].face] for i in cut.pieces
                },
            }
            for cut in result.splits
        ],
        "frame": {f"{x},{y}": letter(i) for (x, y), i in sorted(frame.items())},
        "conventions": dict(knobs),
    }


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
    frame = _painted(result, width, height)
    names = [p.name for p in result.polygons]
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
        *_split_working(result),
        worked(
            "painted",
            [names[i] for i in result.painted],
            r"\text{painting order: } " + ", ".join(names[i] for i in result.painted),
        ),
    )
    notes = (
        _cycle_note(result),
        "Orthographic view along z; each polygon's pixels are the scan-line fill's"
        + (" (a piece's pixels are shown as its polygon's)." if result.splits else "."),
        convention_note(knobs, convention),
    )
    frame_table, _ = buffer_tables(frame, {}, width, height, "-")
    tables = (
        _tests_table(result),
        *((_splits_table(result),) if result.splits else ()),
        frame_table,
    )
    return Solution(
        primitive="3d",
        algorithm="depth-sort",
        title=f"Depth sort (painter's method): {len(polys)} polygon(s)",
        given=given,
        derived=derived,
        notes=notes,
        walk=Walk(tables=tables),
        data=_data(result, frame, knobs),
    )
