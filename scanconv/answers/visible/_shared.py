"""What the visible-surface answers share: faces read from numbers, vectors and planes as
text, the conventions resolved and stated, the frame and depth buffers as tables."""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import Any

from ...algorithms.conventions import KNOBS
from ...algorithms.visible import MAX_FACES, Face, Plane, check_face
from ...core.checks import InputError
from ...core.numeric import Number, fmt_paren, fmt_short
from ...core.records import Column, Table, heading

SEPARATOR = ":"
"""The word between two faces (or polygons) on the command line."""


def vec(v: Sequence[Number]) -> str:
    """``(1, 0, -1/2)``."""
    return "(" + ", ".join(fmt_short(c) for c in v) + ")"


def letter(i: int) -> str:
    """The name of polygon i: ``A``, ``B``, ... (``P27`` beyond Z)."""
    return chr(ord("A") + i) if i < 26 else f"P{i + 1}"


def faces_from(values: Sequence[Any], param: str) -> list[Face]:
    """Faces from the numbers ``x y z x y z ... : x y z ...`` (a ``:`` between faces), or from
    a sequence of faces each a sequence of ``(x, y, z)``."""
    groups: list[list[Any]] = [[]]
    for v in values:
        if isinstance(v, tuple | list):
            if v and isinstance(v[0], tuple | list):  # a face of points
                groups.append([c for p in v for c in _point(p, param)])
                groups.append([])
            else:
                groups[-1].extend(_point(v, param))
        elif isinstance(v, str) and v.strip() == SEPARATOR:
            groups.append([])
        else:
            groups[-1].append(v)
    groups = [g for g in groups if g]
    if len(groups) > MAX_FACES:
        raise InputError(f"{len(groups)} faces; at most {MAX_FACES}", param)
    faces = []
    for i, g in enumerate(groups):
        if len(g) % 3:
            raise InputError(
                f"face {i + 1} has {len(g)} numbers: each vertex is x y z "
                f"(a '{SEPARATOR}' between faces)",
                param,
            )
        pts = tuple(tuple(g[j : j + 3]) for j in range(0, len(g), 3))
        faces.append(pts)
    return faces


def _point(p: Sequence[Any], param: str) -> Sequence[Any]:
    if len(p) != 3:
        raise InputError(f"a vertex is (x, y, z), got {p!r}", param)
    return p


def checked_faces(faces: Sequence[Face], names: Sequence[str]) -> dict[str, Face]:
    """The faces by name, each checked (planar, not degenerate)."""
    return {name: check_face(f, name) for name, f in zip(names, faces, strict=True)}


def knobs_for(method: str, given: Mapping[str, str | None]) -> dict[str, str]:
    """The conventions of ``3d`` method ``method``: each given value checked, else the knob's
    default (Hearn & Baker's)."""
    out: dict[str, str] = {}
    for name, knob in KNOBS.items():
        if not knob.applies_to("3d", method):
            continue
        value = given.get(name) or knob.default
        if value not in knob.values:
            raise InputError(
                f"unknown {name} {value!r} (choose from {', '.join(knob.values)})", name
            )
        out[name] = value
    return out


def convention_note(used: Mapping[str, str]) -> str:
    """The note naming every convention an answer used."""
    parts = "; ".join(f"{k} = {v} ({KNOBS[k].values[v]})" for k, v in used.items())
    changed = any(KNOBS[k].default != v for k, v in used.items())
    where = "as given" if changed else "Hearn & Baker's, the default"
    return f"Conventions ({where}): {parts}."


def plane_tex(name: str, p: Plane) -> str:
    """``A x + B y + C z + D = 0`` with the numbers."""
    return (
        f"\\text{{{name}: }} {fmt_short(p.a)} x + {fmt_paren(p.b)} y + {fmt_paren(p.c)} z "
        f"+ {fmt_paren(p.d)} = 0"
    )


def buffer_tables(
    frame: Mapping[tuple[int, int], int],
    depth: Mapping[tuple[int, int], Number],
    width: int,
    height: int,
    far: str,
) -> tuple[Table, Table]:
    """The final frame buffer (the polygon at each pixel, ``.`` the background) and depth
    buffer, top row first, as tables with a column per x."""
    columns = (
        heading("y", "y", role="label"),
        *(Column(f"x{x}", f"x={x}", f"x={x}") for x in range(width)),
    )

    def frame_rows() -> Iterator[tuple[Any, ...]]:
        for y in range(height - 1, -1, -1):
            cells = (letter(frame[(x, y)]) if (x, y) in frame else "." for x in range(width))
            yield (y, *cells)

    def depth_rows() -> Iterator[tuple[Any, ...]]:
        for y in range(height - 1, -1, -1):
            cells = (fmt_short(depth[(x, y)]) if (x, y) in depth else far for x in range(width))
            yield (y, *cells)

    return (
        Table(
            "Frame buffer (the polygon seen at each pixel; . the background)", columns, frame_rows
        ),
        Table(f"Depth buffer ({far}: never written)", columns, depth_rows),
    )
