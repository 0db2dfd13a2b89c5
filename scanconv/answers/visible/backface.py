"""The worked answer of back-face detection: each face's normal from its vertices (the cross
product with its numbers), the view vector, the sign test and the table of faces."""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import Any

from ...algorithms import visible as vs
from ...core.checks import InputError
from ...core.numeric import Number, fmt_paren, fmt_short
from ...core.records import Solution, Table, Walk, heading, rule, worked
from ._shared import checked_faces, convention_note, faces_from, knobs_for, vec


def _cross_tex(name: str, t: vs.FaceTest) -> str:
    (a1, a2, a3), (b1, b2, b3) = t.e1, t.e2
    p = fmt_paren
    parts = (
        f"{p(a2)} \\cdot {p(b3)} - {p(a3)} \\cdot {p(b2)}",
        f"{p(a3)} \\cdot {p(b1)} - {p(a1)} \\cdot {p(b3)}",
        f"{p(a1)} \\cdot {p(b2)} - {p(a2)} \\cdot {p(b1)}",
    )
    return (
        f"N_{{\\text{{{name}}}}} = (V_2 - V_1) \\times (V_3 - V_1) = {vec(t.e1)} \\times "
        f"{vec(t.e2)} = ({', '.join(parts)}) = {vec(t.normal)}"
    )


def _dot_tex(name: str, t: vs.FaceTest, verdict: str) -> str:
    terms = " + ".join(
        f"{fmt_paren(v)} \\cdot {fmt_paren(n)}" for v, n in zip(t.view, t.normal, strict=True)
    )
    sign = "" if t.dot == 0 else (" < 0" if t.dot < 0 else " > 0")
    return (
        f"V \\cdot N_{{\\text{{{name}}}}} = {terms} = {fmt_short(t.dot)}{sign}\\text{{: {verdict}}}"
    )


def _verdict(t: vs.FaceTest) -> str:
    word = "hidden (back face)" if t.back else "visible"
    return f"edge-on, {word}" if t.edge_on else word


def _table(tests: Sequence[vs.FaceTest]) -> Table:
    def rows() -> Iterator[tuple[Any, ...]]:
        for t in tests:
            yield (
                t.name,
                " ".join(vec(v) for v in t.vertices),
                vec(t.e1),
                vec(t.e2),
                vec(t.normal),
                vec(t.view),
                t.dot,
                _verdict(t),
            )

    return Table(
        "Faces",
        (
            heading("face", r"\text{face}", role="label"),
            heading("vertices", r"V_1, V_2, V_3, \ldots", role="given"),
            heading("e1", r"V_2 - V_1", role="working"),
            heading("e2", r"V_3 - V_1", role="working"),
            heading("normal", r"N = (A, B, C)"),
            heading("view", "V", role="given"),
            heading("dot", r"V \cdot N"),
            heading("verdict", r"\text{verdict}"),
        ),
        rows,
    )


def _test_rule(knobs: Mapping[str, str]) -> str:
    back = r"V \cdot N > 0" if knobs["direction"] == "into-scene" else r"V \cdot N < 0"
    edge = "hidden" if knobs["edge-on"] == "hidden" else "visible"
    return f"\\text{{back face (hidden) when }} {back}\\text{{; }} V \\cdot N = 0 \\text{{ (edge-on): {edge}}}"


def backface_solution(
    faces: Sequence[Any] = (),
    *,
    solid: str | None = None,
    view: Sequence[Number] | None = None,
    eye: Sequence[Number] | None = None,
    names: str | None = None,
    conventions: Mapping[str, str | None] | None = None,
    convention: str | None = None,
) -> Solution:
    """Back-face detection of the faces given (numbers ``x y z ...`` with ``:`` between faces)
    or of a named solid (:data:`~scanconv.algorithms.visible.SOLIDS`).

    >>> sol = backface_solution(solid="cube")
    >>> [r[-1] for r in sol.tables[0].rows()]
    ['visible', 'hidden (back face)', 'edge-on, hidden (back face)', 'edge-on, hidden (back face)', 'edge-on, hidden (back face)', 'edge-on, hidden (back face)']
    """
    knobs = knobs_for("backface", conventions or {}, convention)
    if solid is not None and faces:
        raise InputError("give the faces or a named solid, not both", "solid")
    if solid is not None and names is not None:
        raise InputError("a named solid's faces have their own names", "names")
    if solid is not None:
        if solid not in vs.SOLIDS:
            raise InputError(
                f"unknown solid {solid!r} (choose from {', '.join(vs.SOLIDS)})", "solid"
            )
        named = dict(vs.SOLIDS[solid])
    else:
        given = faces_from(faces, "faces")
        if not given:
            raise InputError(
                "give the faces (x y z x y z x y z ... : ...) or a named solid", "faces"
            )
        named = checked_faces(given, _names(names, len(given)))
    if view is not None and eye is not None:
        raise InputError("give the view vector or the eye, not both", "view")
    v = None if view is None else _vector(view, "view")
    e = None if eye is None else _vector(eye, "eye")
    if v == (0, 0, 0):
        raise InputError("the view vector is zero", "view")
    tests = list(vs.backface(named, v, e, knobs))
    return _solution(tests, solid, v, e, knobs, convention)


def _names(names: str | None, n: int) -> list[str]:
    """The faces' names: given, separated by commas, or F1, F2, ..."""
    if names is None:
        return [f"F{i}" for i in range(1, n + 1)]
    out = [w.strip() for w in names.split(",")]
    if len(out) != n or not all(out) or len(set(out)) != n:
        raise InputError(
            f"names: {len(out)} given for {n} faces (distinct, separated by commas)", "names"
        )
    if any(len(w) > 12 or not w.replace("-", "").replace("_", "").isalnum() for w in out):
        raise InputError("a face's name is up to 12 letters, digits, '-' or '_'", "names")
    return out


def _vector(values: Sequence[Number], param: str) -> vs.Vec:
    if len(values) != 3:
        raise InputError(f"{param} takes 3 numbers (x y z), got {len(values)}", param)
    return (values[0], values[1], values[2])


def _solution(
    tests: Sequence[vs.FaceTest],
    solid: str | None,
    view: vs.Vec | None,
    eye: vs.Vec | None,
    knobs: Mapping[str, str],
    convention: str | None,
) -> Solution:
    if eye is not None:
        how = r"V = V_1 - E" if knobs["direction"] == "into-scene" else r"V = E - V_1"
        seen: tuple[Any, ...] = (
            worked("eye", eye, f"E = {vec(eye)}"),
            rule("view", f"{how} \\text{{ for each face}}"),
        )
    else:
        used = view or vs.default_view(knobs["direction"], knobs["handed"])
        where = (
            "given"
            if view is not None
            else f"the default: {knobs['direction']}, {knobs['handed']}-handed"
        )
        seen = (worked("view", used, f"V = {vec(used)} \\text{{ ({where})}}"),)
    given = (
        *(
            worked(
                t.name, t.vertices, f"\\text{{{t.name}: }} " + ", ".join(vec(p) for p in t.vertices)
            )
            for t in tests
        ),
        *seen,
    )
    derived = [
        rule("normal", r"N = (V_2 - V_1) \times (V_3 - V_1) = (A, B, C)"),
        rule("test", _test_rule(knobs)),
    ]
    for t in tests:
        derived.append(worked(f"N_{t.name}", t.normal, _cross_tex(t.name, t)))
        derived.append(worked(f"dot_{t.name}", t.dot, _dot_tex(t.name, t, _verdict(t))))
    hidden = [t.name for t in tests if t.back]
    what = solid or f"{len(tests)} face(s)"
    notes = (
        f"Visible: {', '.join(t.name for t in tests if not t.back) or 'none'}; hidden (back faces): "
        f"{', '.join(hidden) or 'none'}.",
        "The normal points outward when the vertices run counter-clockwise seen from outside "
        "(right-handed axes; clockwise with left-handed ones).",
        convention_note(knobs, convention),
    )
    return Solution(
        primitive="3d",
        algorithm="backface",
        title=f"Back-face detection: {what}",
        given=given,
        derived=tuple(derived),
        notes=notes,
        walk=Walk(tables=(_table(tests),)),
        data={
            "faces": [
                {
                    "name": t.name,
                    "normal": list(t.normal),
                    "view": list(t.view),
                    "dot": t.dot,
                    "back": t.back,
                }
                for t in tests
            ],
            "conventions": dict(knobs),
        },
    )
