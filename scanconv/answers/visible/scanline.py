"""The worked answer of the scan-line method: the edge and polygon tables, the active edge
list of each scan line with the in/out flags, the depth comparison where polygons overlap,
and the final frame."""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from fractions import Fraction
from typing import Any

from ...algorithms import visible_scanline as sl
from ...algorithms.visible_zbuffer import check_plane
from ...core.numeric import fmt_short, normalize
from ...core.records import Solution, Table, Walk, heading, rule, worked
from ._shared import buffer_tables, convention_note, knobs_for, letter, plane_tex, vec
from .zbuffer import polygons_from, size_of


def _edge_table(polys: Sequence[tuple[str, Any]]) -> Table:
    edges = sl.edges_of(polys)

    def rows() -> Iterator[tuple[Any, ...]]:
        for i, e in edges:
            yield (
                f"{letter(i)}.e{e.idx}",
                fmt_short(e.y_min),
                fmt_short(e.y_max),
                fmt_short(e.x_bottom),
                fmt_short(e.inv_m),
                letter(i),
            )

    return Table(
        "Edge table (each polygon's edges, an edge on scan line y when y_min <= y < y_max)",
        (
            heading("edge", r"\text{edge}", role="label"),
            heading("y_min", r"y_{\min}", role="given"),
            heading("y_max", r"y_{\max}", role="given"),
            heading("x_bottom", r"x \text{ at } y_{\min}", role="given"),
            heading("inv_m", "1/m", role="working"),
            heading("polygon", r"\text{polygon}", role="given"),
        ),
        rows,
    )


def _polygon_table(names: Sequence[str], planes: Sequence[Any]) -> Table:
    def rows() -> Iterator[tuple[Any, ...]]:
        for n, p in zip(names, planes, strict=True):
            yield (
                n,
                fmt_short(p.a),
                fmt_short(p.b),
                fmt_short(p.c),
                fmt_short(p.d),
                fmt_short(normalize(Fraction(-p.a) / p.c)),
                "off",
            )

    return Table(
        "Polygon table (plane coefficients; every flag starts off)",
        (
            heading("polygon", r"\text{polygon}", role="label"),
            heading("A", "A"),
            heading("B", "B"),
            heading("C", "C"),
            heading("D", "D"),
            heading("dz", "-A/C"),
            heading("flag", r"\text{flag}", role="given"),
        ),
        rows,
    )


def _pixel_text(p: sl.Shown) -> str:
    if not p.depths:
        return f"{p.x}: {letter(p.shown)}"
    zs = ", ".join(f"z_{letter(i)} = {fmt_short(z)}" for i, z in p.depths)
    return f"{p.x}: {zs}: {letter(p.shown)}"


def _scan_table(rows_: Sequence[sl.ScanRow]) -> Table:
    def rows() -> Iterator[tuple[Any, ...]]:
        for r in rows_:
            ael = ", ".join(f"{letter(c.polygon)}.e{c.edge} {fmt_short(c.x)}" for c in r.crossings)
            if not r.intervals:
                yield (r.y, ael, "-", "-", "-")
            for n, iv in enumerate(r.intervals):
                span = f"[{fmt_short(iv.x_start)}, {fmt_short(iv.x_end)})"
                flags = ", ".join(letter(i) for i in iv.on)
                pixels = "; ".join(_pixel_text(p) for p in iv.pixels) or "no pixel centre"
                yield (r.y, ael if n == 0 else "", span, flags, pixels)

    return Table(
        "Scan lines from the top: the active edge list (edge x), and between crossings the flags on and each pixel",
        (
            heading("y", "y", role="label"),
            heading("ael", r"\text{active edges (x)}", role="working"),
            heading("span", r"[x_a, x_b)", role="working"),
            heading("flags", r"\text{flags on}"),
            heading("pixels", r"x\text{: depths compared: shown}"),
        ),
        rows,
    )


def scanline_solution(
    polygons: Sequence[Any],
    *,
    size: str | None = None,
    conventions: Mapping[str, str | None] | None = None,
    convention: str | None = None,
) -> Solution:
    """The scan-line method for the polygons (numbers ``x y z ...``, ``:`` between them) on
    a ``W x H`` grid.

    >>> sol = scanline_solution([0, 0, 1, 4, 0, 1, 0, 4, 1, ":", 1, 0, 2, 4, 0, 2, 4, 3, 2], size="5")
    >>> sol.data["frame"]["2,1"], sol.data["frame"]["1,1"]
    ('B', 'A')
    """
    knobs = knobs_for("scanline", conventions or {}, convention)
    polys = polygons_from(polygons)
    width, height = size_of(size, polys)
    names = [n for n, _ in polys]
    planes = [check_plane(n, f) for n, f in polys]
    rows = list(sl.scanline(polys, width, height, knobs))
    frame = sl.frame_of(rows)
    given = (
        *(worked(n, f, f"{n}: " + ", ".join(vec(v) for v in f)) for n, f in polys),
        worked(
            "grid",
            (width, height),
            f"\\text{{grid: }} {width} \\times {height} \\text{{ pixels, centres at integer }} (x, y)",
        ),
    )
    derived = (
        rule("flags", r"\text{crossing an edge of a polygon turns its flag over (in/out)}"),
        rule(
            "depth",
            r"\text{where two or more flags are on: } z = (-A x - B y - D)/C \text{ compared at each pixel}",
        ),
        *(worked(f"plane_{n}", p, plane_tex(n, p)) for n, p in zip(names, planes, strict=True)),
    )
    overlaps = sum(1 for r in rows for i in r.intervals if len(i.on) > 1)
    notes = (
        f"{len(rows)} scan lines meet the polygons; {overlaps} interval(s) with more than one flag on.",
        "Orthographic view along z; a pixel lies in the interval [x_a, x_b) its centre is in "
        "(the scan-line fill's half-open rule, each polygon's top end left out).",
        convention_note(knobs, convention),
    )
    frame_table, _ = buffer_tables(frame, {}, width, height, "-")
    return Solution(
        primitive="3d",
        algorithm="scanline",
        title=f"Scan-line method: {len(polys)} polygon(s) on a {width} x {height} grid",
        given=given,
        derived=derived,
        notes=notes,
        walk=Walk(
            tables=(
                _edge_table(polys),
                _polygon_table(names, planes),
                _scan_table(rows),
                frame_table,
            )
        ),
        data={
            "frame": {f"{x},{y}": letter(i) for (x, y), i in sorted(frame.items())},
            "conventions": dict(knobs),
        },
    )
