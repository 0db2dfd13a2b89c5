"""The worked answer of Weiler-Atherton polygon clipping: the two vertex lists with the
crossings inserted and labelled in/out, each walk, and the output polygons
(:mod:`scanconv.algorithms.weiler_atherton`)."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING, Any

from ....algorithms.weiler_atherton import Entry, weiler_atherton
from ....core.checks import InputError
from ....core.ideal import Polyline
from ....core.numeric import Number, normalize
from ....core.records import Plot, Solution, Table, Walk, heading, rule, worked
from .._shared import pt
from ._shared import corners

if TYPE_CHECKING:
    from ...asked import ClipPolygonQuestion


def _points(coords: Sequence[Number], name: str) -> list[tuple[Number, Number]]:
    if len(coords) % 2 or len(coords) < 6:
        raise InputError(f"the {name} polygon is at least 3 vertices x y", name)
    return [(normalize(coords[i]), normalize(coords[i + 1])) for i in range(0, len(coords), 2)]


_KIND = {"in": "in (entering)", "out": "out (leaving)", "touch": "touch (no switch)"}


def _list_table(title: str, prefix: str, entries: Sequence[Entry]) -> Table:
    def rows() -> Iterator[tuple[Any, ...]]:
        for e in entries:
            if e.crossing is None:
                yield (f"{prefix}{e.vertex}", pt(e.point), "vertex")
            else:
                name = f"I{e.crossing + 1}"
                if e.vertex is not None:
                    name += f" = {prefix}{e.vertex}"
                yield (name, pt(e.point), _KIND[e.label])

    return Table(
        title,
        (
            heading("name", r"\text{name}"),
            heading("point", r"\text{point}"),
            heading("kind", r"\text{kind}"),
        ),
        rows,
    )


def weiler_atherton_solution(subject: Sequence[Number], clip: Sequence[Number]) -> Solution:
    """Weiler-Atherton clipping of the polygon ``subject`` (``x y ...``) by ``clip``.

    >>> sol = weiler_atherton_solution([0, 0, 8, 0, 8, 8, 6, 8, 6, 2, 2, 2, 2, 8, 0, 8],
    ...                                [-1, 4, 9, 4, 9, 9, -1, 9])
    >>> [q.text for q in sol.derived[-2:]]
    ['walk 1: I1 → S3 → S4 → I2 → I1', 'walk 2: I3 → S7 → S8 → I4 → I3']
    """
    s, c = _points(subject, "subject"), _points(clip, "clip")
    r = weiler_atherton(s, c)
    derived = [
        rule("in", r"\text{in: the subject enters the clip region; out: it leaves}"),
        rule("walk", r"\text{walk: from an unvisited in, follow the subject to an out,}"),
        rule("switch", r"\text{then the clip polygon to an in, until back at the start}"),
    ]
    for i, walk in enumerate(r.walks, 1):
        arrow = " \\to ".join((*walk, walk[0]))
        derived.append(worked(f"walk{i}", list(walk), f"\\text{{walk {i}: }} {arrow}"))
    notes = ["Both polygons are walked counter-clockwise."]
    if any(e.label == "touch" for e in r.subject):
        notes.append(
            "Where the polygons only touch (a vertex on the other's edge, an edge along "
            "another), the point is inserted as a touch: the walk does not switch lists there. "
            "Each point's label is read from the subject's pieces on either side of it: a piece "
            "is inside when its midpoint is inside the clip polygon (or on its edge, running "
            "the same way)."
        )
    if r.reversed:
        notes.append(f"Given clockwise and reversed: the {' and '.join(r.reversed)} polygon.")
    if not r.walks:
        if not r.polygons:
            what = "empty (they do not meet)."
        elif set(r.polygons[0]) == set(s):
            what = "the subject (inside the clip polygon)."
        else:
            what = "the clip polygon (inside the subject)."
        notes.append(f"No edges cross: the answer is {what}")
    result = Table(
        "Output polygons",
        (heading("polygon", r"\text{polygon}"), heading("vertices", r"\text{vertices}")),
        lambda: ((i, ", ".join(pt(p) for p in poly)) for i, poly in enumerate(r.polygons, 1)),
    )
    return Solution(
        primitive="clip",
        algorithm="weiler-atherton",
        title=f"Weiler-Atherton clipping: a subject of {len(s)} vertices, a clip polygon of {len(c)}",
        given=(
            worked("subject", s, "\\text{subject: } " + ", ".join(pt(p) for p in s)),
            worked("clip", c, "\\text{clip: } " + ", ".join(pt(p) for p in c)),
        ),
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(
            tables=(
                _list_table("Subject list (crossings inserted)", "S", r.subject),
                _list_table("Clip list (crossings inserted)", "C", r.clip),
                result,
            )
        ),
        plot=Plot(ideal=(Polyline([(float(x), float(y)) for x, y in (*s, s[0])], "subject"),)),
        data={"polygons": [[list(p) for p in poly] for poly in r.polygons]},
    )


def polygon_answer(q: ClipPolygonQuestion) -> Solution:
    """The question's polygon clipped against its window: a polygon's ``x y x y ...``, or the
    rectangle ``(xmin, ymin, xmax, ymax)`` (the record's ``answer``)."""
    shape = q.window if q.polygon else [c for p in corners(q.window) for c in p]
    return weiler_atherton_solution(q.vertices, shape)
