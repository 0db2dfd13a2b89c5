"""What the visible-surface answers share: faces read from numbers, vectors and planes as
text, the conventions resolved and stated, the frame and depth buffers as tables."""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import Any

from ...algorithms.conventions import KNOBS
from ...algorithms.space_conventions import VISIBLE_SOURCES, visible_preset
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


def knobs_for(
    method: str, given: Mapping[str, str | None], convention: str | None = None
) -> dict[str, str]:
    """The conventions of ``3d`` method ``method``: each given value checked, else the
    preset's (``convention``, default Hearn & Baker's:
    :data:`~scanconv.algorithms.space_conventions.VISIBLE_PRESETS`).

    A preset's depth buffer from 0 (``clear = zero``) is the back of a range where a larger z
    is nearer; with ``depth = smaller-nearer`` it starts at the farthest value instead, and
    ``clear = zero`` given with it is refused.

    >>> knobs_for("zbuffer", {"ties": None}, "foley")
    {'depth': 'larger-nearer', 'ties': 'replace', 'clear': 'zero'}
    >>> knobs_for("zbuffer", {"depth": "smaller-nearer"})["clear"]
    'farthest'
    """
    _, preset = visible_preset(convention)
    out: dict[str, str] = {}
    for name, knob in KNOBS.items():
        if not knob.applies_to("3d", method):
            continue
        value = given.get(name) or preset.get(name, knob.default)
        if value not in knob.values:
            raise InputError(
                f"unknown {name} {value!r} (choose from {', '.join(knob.values)})", name
            )
        out[name] = value
    if out.get("clear") == "zero" and out.get("depth") == "smaller-nearer":
        if given.get("clear") == "zero":
            raise InputError(
                "clear zero is the back of a depth range where a larger z is nearer: with "
                "depth smaller-nearer, give far for the buffer's first value",
                "clear",
            )
        out["clear"] = "farthest"
    return out


def convention_note(used: Mapping[str, str], convention: str | None = None) -> str:
    """The note naming the preset and every convention an answer used (a value that is not
    the preset's says so).

    >>> print(convention_note({"ties": "replace"}, "hearn-baker"))  # doctest: +ELLIPSIS
    Conventions (preset hearn-baker: Hearn & Baker, ...): ties = replace, not the preset's keep (...).
    """
    name, preset = visible_preset(convention)

    def part(k: str, v: str) -> str:
        theirs = preset.get(k, KNOBS[k].default)
        other = "" if theirs == v else f", not the preset's {theirs}"
        return f"{k} = {v}{other} ({KNOBS[k].values[v]})"

    parts = "; ".join(part(k, v) for k, v in used.items())
    return f"Conventions (preset {name}: {VISIBLE_SOURCES[name]}): {parts}."


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
        Table(f"Depth buffer ({far} where never written)", columns, depth_rows),
    )
