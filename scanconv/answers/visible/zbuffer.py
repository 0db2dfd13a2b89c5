"""The worked answer of the z-buffer: each polygon's plane and depth increments, its scan
lines with the depth down the left edge, the step table of depth comparisons and buffer
updates, and the final frame and depth buffers."""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from fractions import Fraction
from typing import Any

from ...algorithms import visible_zbuffer as zb
from ...algorithms.visible import Face, Plane, normal, sub
from ...core.checks import InputError
from ...core.numeric import Number, fmt_paren, fmt_short, normalize
from ...core.records import Column, Solution, Table, Walk, heading, rule, worked
from ._shared import (
    buffer_tables,
    checked_faces,
    convention_note,
    faces_from,
    knobs_for,
    letter,
    plane_tex,
    vec,
)

MAX_XY = 2 * zb.MAX_SIDE
"""The largest |x| or |y| of a vertex (the polygon's scan lines are walked)."""


def polygons_from(values: Sequence[Any], param: str = "polygons") -> list[tuple[str, Face]]:
    """The named polygons ``A``, ``B``, ... of the numbers (``:`` between polygons), each
    checked: planar, within :data:`MAX_XY`, at most :data:`~zb.MAX_POLYGONS`."""
    faces = faces_from(values, param)
    if not faces:
        raise InputError("give the polygons: x y z x y z x y z ... : ...", param)
    if len(faces) > zb.MAX_POLYGONS:
        raise InputError(f"{len(faces)} polygons; at most {zb.MAX_POLYGONS}", param)
    named = checked_faces(faces, [letter(i) for i in range(len(faces))])
    for name, face in named.items():
        if any(max(abs(Fraction(v[0])), abs(Fraction(v[1]))) > MAX_XY for v in face):
            raise InputError(f"polygon {name}: |x| and |y| are at most {MAX_XY}", param)
    return list(named.items())


def size_of(size: str | None, polygons: Sequence[tuple[str, Face]]) -> tuple[int, int]:
    """``WxH`` (or ``N`` for a square) or the smallest grid holding the vertices."""
    if size is None:
        w, h = zb.grid_of(polygons)
    else:
        text = size.lower().replace(" ", "")
        parts = text.split("x") if "x" in text else [text, text]
        if len(parts) != 2 or not all(p.isdigit() for p in parts):
            raise InputError(f"size is W x H (as 8x6, or 8), got {size!r}", "size")
        w, h = int(parts[0]), int(parts[1])
    zb.check_grid(w, h)
    return w, h


def _plane_quantities(name: str, face: Face, p: Plane) -> list[Any]:
    n = normal(face)
    return [
        worked(
            f"N_{name}", n,
            f"N_{{{name}}} = (V_2 - V_1) \\times (V_3 - V_1) = {vec(sub(face[1], face[0]))} \\times "
            f"{vec(sub(face[2], face[0]))} = {vec(n)} = (A, B, C)",
        ),
        worked(
            f"D_{name}", p.d,
            f"D_{{{name}}} = -(A x_1 + B y_1 + C z_1) = -({fmt_short(p.a)} \\cdot {fmt_paren(face[0][0])} + "
            f"{fmt_paren(p.b)} \\cdot {fmt_paren(face[0][1])} + {fmt_paren(p.c)} \\cdot {fmt_paren(face[0][2])}) = {fmt_short(p.d)}",
        ),
        worked(f"plane_{name}", p, plane_tex(name, p)),
        worked(
            f"dx_{name}", normalize(Fraction(-p.a) / p.c),
            f"\\Delta z_x = -A/C = -({fmt_short(p.a)})/{fmt_paren(p.c)} = {fmt_short(normalize(Fraction(-p.a) / p.c))}",
        ),
    ]  # fmt: skip


def _scan_table(name: str, rows: Sequence[zb.ScanRow], p: Plane) -> Table:
    def cells() -> Iterator[tuple[Any, ...]]:
        for r in rows:
            if r.incremental:
                how = (
                    f"z_L(y+1) + (A·(1/m) + B)/C = z_L(y+1) + {fmt_paren(zb.edge_step(p, r.inv_m))}"
                )
            else:
                how = f"(-A·x_L - B·y - D)/C at ({fmt_short(r.x_edge)}, {r.y})"
            spans = ", ".join(f"{a}..{b}" for a, b in r.runs)
            yield (
                r.y,
                f"e{r.edge}",
                fmt_short(r.inv_m),
                fmt_short(r.x_edge),
                how,
                fmt_short(r.z_edge),
                spans,
            )

    return Table(
        f"Polygon {name}: scan lines from the top, the depth down the left edge",
        (
            heading("y", "y", role="label"),
            heading("edge", r"\text{left edge}", role="given"),
            heading("inv_m", "1/m", role="given"),
            heading("x_L", "x_L"),
            heading("how", r"\text{how}", role="working"),
            heading("z_L", "z_L"),
            heading("pixels", r"\text{pixels } x"),
        ),
        cells,
    )


def _far_text(depth: str, far: Number | None) -> str:
    if far is not None:
        return fmt_short(far)
    return "-inf" if depth == "larger-nearer" else "+inf"


def _steps_table(
    steps: Sequence[zb.ZStep],
    polys: Sequence[tuple[str, Face]],
    planes: Sequence[Plane],
    far: str,
    knobs: Mapping[str, str],
) -> Table:
    op = ">" if knobs["depth"] == "larger-nearer" else "<"
    op = op + "=" if knobs["ties"] == "replace" else op

    def cells() -> Iterator[tuple[Any, ...]]:
        for s in steps:
            p = planes[s.polygon]
            dz = f"({fmt_short(normalize(Fraction(-p.a) / p.c))})"
            if s.first:
                x_l, z_l = s.edge
                how = f"z_L + (-A/C)(x - x_L) = {fmt_short(z_l)} + {dz}({s.pixel[0]} - {fmt_paren(x_l)})"
            else:
                how = f"z(x - 1) + (-A/C) = z(x - 1) + {dz}"
            before = far if s.before is None else fmt_short(s.before)
            test = f"{fmt_short(s.z)} {op} {before}: {'yes' if s.written else 'no'}"
            held = "." if s.holder is None else letter(s.holder)
            after = letter(s.polygon) if s.written else held
            yield (s.k, polys[s.polygon][0], s.pixel, how, fmt_short(s.z), before, test, after)

    return Table(
        "Depth comparisons and buffer updates",
        (
            heading("k", "k", role="label"),
            heading("polygon", r"\text{polygon}", role="given"),
            heading("pixel", "(x, y)", role="given"),
            heading("how", r"\text{how}", role="working"),
            heading("z", "z"),
            heading("before", r"\text{depth}(x, y)", role="working"),
            heading("test", r"\text{nearer?}"),
            Column("frame", "frame(x, y)", r"\text{frame}(x, y)"),
        ),
        cells,
    )


def zbuffer_solution(
    polygons: Sequence[Any],
    *,
    size: str | None = None,
    far: Number | None = None,
    conventions: Mapping[str, str | None] | None = None,
    convention: str | None = None,
) -> Solution:
    """The z-buffer of the polygons (numbers ``x y z ...``, ``:`` between polygons) on a
    ``W x H`` grid.

    >>> sol = zbuffer_solution([0, 0, 1, 3, 0, 1, 0, 3, 1, ":", 0, 0, 2, 2, 0, 2, 0, 2, 2])
    >>> [r for r in sol.tables[-2].rows()]
    [(3, '.', '.', '.', '.'), (2, 'A', '.', '.', '.'), (1, 'B', 'A', '.', '.'), (0, 'B', 'B', 'A', '.')]
    """
    knobs = knobs_for("zbuffer", conventions or {}, convention)
    if far is not None:  # the buffer's first value given: no clear convention applies
        if (conventions or {}).get("clear"):
            raise InputError(
                "far gives the depth buffer's first value: clear cannot go with it", "far"
            )
        del knobs["clear"]
    start = far if far is not None or knobs["clear"] == "farthest" else 0
    polys = polygons_from(polygons)
    width, height = size_of(size, polys)
    planes = [zb.check_plane(n, f) for n, f in polys]
    steps = list(zb.zbuffer(polys, width, height, knobs, start))
    frame, depth = zb.buffers(steps)
    far_text = _far_text(knobs["depth"], start)
    behind = sum(1 for s in steps if s.before is not None and s.holder is None and not s.written)
    given = (
        *(worked(n, f, f"{n}: " + ", ".join(vec(v) for v in f)) for n, f in polys),
        worked(
            "grid",
            (width, height),
            f"\\text{{grid: }} {width} \\times {height} \\text{{ pixels, centres at integer }} (x, y)",
        ),
        worked(
            "far",
            far_text,
            f"\\text{{depth buffer initialised to }} {far_text}\\text{{, frame buffer to the background}}",
        ),
    )
    derived: list[Any] = [
        rule("plane", r"A x + B y + C z + D = 0,\ (A, B, C) = N,\ z = (-A x - B y - D)/C"),
        rule("along", r"\text{along a scan line: } z(x + 1) = z(x) - A/C"),
        rule("down", r"\text{down an edge: } y \to y - 1,\ x \to x - 1/m,\ z' = z + (A/m + B)/C"),
    ]
    for (n, f), p in zip(polys, planes, strict=True):
        derived += _plane_quantities(n, f, p)
    tables = [
        _scan_table(n, zb.scan_rows(f, p, width, height), p)
        for (n, f), p in zip(polys, planes, strict=True)
    ]
    tables.append(_steps_table(steps, polys, planes, far_text, knobs))
    tables += buffer_tables(frame, depth, width, height, far_text)
    notes = (
        "Orthographic view along z: a polygon's pixels are the scan-line fill's (pixel centres "
        "at integer points, a span from ceil(x_left) to ceil(x_right) - 1, an edge's top end "
        "left out), walked from the top scan line down; polygons in the order given.",
        *(
            (
                f"{behind} pixel(s) lie at or behind the depth buffer's first value "
                f"{far_text} (the back clipping plane) and are never written.",
            )
            if behind
            else ()
        ),
        convention_note(knobs, convention),
    )
    return Solution(
        primitive="3d",
        algorithm="zbuffer",
        title=f"Z-buffer: {len(polys)} polygon(s) on a {width} x {height} grid",
        given=given,
        derived=tuple(derived),
        notes=notes,
        walk=Walk(tables=tuple(tables)),
        data={
            "frame": {f"{x},{y}": letter(i) for (x, y), i in sorted(frame.items())},
            "depth": {f"{x},{y}": z for (x, y), z in sorted(depth.items())},
            "conventions": dict(knobs),
        },
    )
