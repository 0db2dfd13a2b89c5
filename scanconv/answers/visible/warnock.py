"""The worked answer of Warnock's area subdivision: the windows depth first (the quadtree),
each polygon's class against each window, the test that decides it, and the final frame."""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import Any

from ...algorithms import visible_warnock as wa
from ...algorithms.polygon import fill_pixels
from ...algorithms.visible import Face
from ...algorithms.visible_zbuffer import check_plane, grid_of
from ...core.checks import InputError
from ...core.numeric import fmt_short
from ...core.records import Column, Solution, Table, Walk, heading, rule, worked
from ._shared import buffer_tables, convention_note, knobs_for, letter, plane_tex, vec
from .zbuffer import polygons_from


def _size(size: str | None, polys: Sequence[tuple[str, Face]]) -> int:
    if size is None:
        side = max(grid_of(polys))
        n = 1
        while n < side:
            n *= 2
        return n
    if not size.strip().isdigit():
        raise InputError(f"size is one number of pixels, 2^n (as 8), got {size!r}", "size")
    return int(size)


def _decision_text(w: wa.Window, names: Sequence[str], knobs: Mapping[str, str]) -> str:
    if w.decision == "background":
        return "all disjoint: background"
    if w.decision == "one":
        assert w.shown is not None
        return f"only {names[w.shown]}: {names[w.shown]} where it covers"
    if w.decision == "obscures":
        assert w.shown is not None
        far, *others = w.depths
        near = ", ".join(f"{names[j]} {fmt_short(z)}" for j, z in others)
        return f"{names[w.shown]} surrounds, farthest z {fmt_short(far[1])} vs nearest {near}: {names[w.shown]}"
    if w.decision == "pixel":
        zs = ", ".join(f"z_{names[j]} = {fmt_short(z)}" for j, z in w.depths)
        shown = "background" if w.shown is None else names[w.shown]
        return f"pixel: {zs or 'none covers it'}: {shown}"
    return "subdivide"


def _windows_table(
    windows: Sequence[wa.Window], names: Sequence[str], knobs: Mapping[str, str]
) -> Table:
    def rows() -> Iterator[tuple[Any, ...]]:
        for w in windows:
            xs = f"{w.x0}..{w.x0 + w.size - 1}"
            ys = f"{w.y0}..{w.y0 + w.size - 1}"
            yield (
                w.k,
                w.label,
                len(w.label) - 1,
                xs,
                ys,
                *w.classes,
                _decision_text(w, names, knobs),
            )

    return Table(
        "Windows, depth first (the quadtree: W, its quadrants W1 top left, W2 top right, W3 "
        "bottom left, W4 bottom right, theirs W11 ...)",
        (
            heading("k", "k", role="label"),
            heading("window", r"\text{window}", role="label"),
            heading("level", r"\text{level}", role="label"),
            heading("x", "x", role="given"),
            heading("y", "y", role="given"),
            *(Column(f"class_{n}", n, f"\\text{{{n}}}") for n in names),
            heading("decision", r"\text{decision}"),
        ),
        rows,
    )


def warnock_solution(
    polygons: Sequence[Any],
    *,
    size: str | None = None,
    conventions: Mapping[str, str | None] | None = None,
    convention: str | None = None,
) -> Solution:
    """Warnock's subdivision of the polygons (numbers ``x y z ...``, ``:`` between polygons)
    on a square grid of 2^n pixels.

    >>> sol = warnock_solution([0, 0, 1, 4, 0, 1, 0, 4, 1, ":", 0, 0, 2, 2, 0, 2, 0, 2, 2])
    >>> [r[1] for r in sol.tables[0].rows()][:3]
    ['W', 'W1', 'W2']
    """
    knobs = knobs_for("warnock", conventions or {}, convention)
    polys = polygons_from(polygons)
    side = _size(size, polys)
    names = [n for n, _ in polys]
    windows = list(wa.warnock(polys, side, knobs))
    pixels = [frozenset(fill_pixels([(v[0], v[1]) for v in f])) for _, f in polys]
    frame = wa.frame_of(windows, pixels)
    planes = [check_plane(n, f) for n, f in polys]
    given = (
        *(worked(n, f, f"{n}: " + ", ".join(vec(v) for v in f)) for n, f in polys),
        worked(
            "grid",
            side,
            f"\\text{{grid: }} {side} \\times {side} \\text{{ pixels, centres at integer }} (x, y)",
        ),
    )
    derived = [
        rule(
            "classes",
            r"\text{classes: surrounding, intersecting, contained, disjoint (the pixels' squares)}",
        ),
        *(rule(f"test_{key}", f"\\text{{{key}: {text}}}") for key, text in wa.DECISIONS.items()),
        *(worked(f"plane_{n}", p, plane_tex(n, p)) for n, p in zip(names, planes, strict=True)),
    ]
    counts = {d: sum(w.decision == d for w in windows) for d in wa.DECISIONS}
    notes = (
        f"{len(windows)} windows: " + ", ".join(f"{v} {k}" for k, v in counts.items() if v) + ".",
        "Orthographic view along z; a pixel is covered by a polygon as in the scan-line fill "
        "(centres at integer points, half-open spans and edges).",
        convention_note(knobs, convention),
    )
    frame_table, _ = buffer_tables(frame, {}, side, side, "-")
    return Solution(
        primitive="3d",
        algorithm="warnock",
        title=f"Warnock's area subdivision: {len(polys)} polygon(s) on a {side} x {side} grid",
        given=given,
        derived=tuple(derived),
        notes=notes,
        walk=Walk(tables=(_windows_table(windows, names, knobs), frame_table)),
        data={
            "windows": [
                {"label": w.label, "x": w.x0, "y": w.y0, "size": w.size, "classes": list(w.classes),
                 "decision": w.decision, "shown": None if w.shown is None else names[w.shown]}
                for w in windows
            ],
            "frame": {f"{x},{y}": letter(i) for (x, y), i in sorted(frame.items())},
            "conventions": dict(knobs),
        },
    )  # fmt: skip
