"""The worked answer of a 3D projection: the projection matrix with its numbers, the projected
vertex table (``M·P = (X, Y, Z, W)``, then the point ``(X/W, Y/W)``), the vanishing points of a
perspective, the foreshortening of an axonometric projection, and a drawn figure of the
projected solid from its edges.

Transformations given before the projection (``--translate 0 0 2``, as ``3d transform`` takes
them) are applied first. The conventions (:mod:`scanconv.algorithms.space_conventions`)
decide how the matrices are written, what the oblique angle means and where the centre of
projection is.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any, NamedTuple, cast

from ...algorithms import projection as pj
from ...algorithms import space
from ...algorithms.radical import Radical, Scalar, approx, round_half_up_exact, simplify
from ...algorithms.space import Matrix4
from ...algorithms.transform import cos_sin, outline
from ...core.checks import InputError
from ...core.ideal import Polyline
from ...core.numeric import Number, fmt_short
from ...core.records import Plot, Quantity, Solution, Table, Walk, heading, worked
from ..asked import ProjectionQuestion
from ..methods import method
from ..process._shared import json_scalar, matrix_json, text
from ..process.transform import _tex_deg, parse_angle
from .transform import (
    MATRIX_COLUMNS,
    Factor,
    Stage,
    approx_point,
    composite,
    conventions,
    irrational,
    notes_of,
    parse,
    point_text,
    solid_of,
    stage_matrices,
    vertices_given,
)

if TYPE_CHECKING:
    from ..asked import CentreOfProjection, ObliqueAngle

FIGURE_CELLS = 24
"""The drawn figure's longer side, in grid cells: the projected solid is scaled to it."""


def _trig(deg: Fraction, what: str) -> tuple[Scalar, Scalar]:
    c, s, exact = cos_sin(deg)
    if not exact:
        raise InputError(
            f"{what} must be a multiple of 15 degrees to stay exact, got {fmt_short(deg)}", what
        )
    return c, s


def _degrees(word: str | None, default: int, what: str) -> Fraction:
    if word is None:
        return Fraction(default)
    deg = parse_angle(word)[0]
    if deg is None:
        raise InputError(f"{what} must be in degrees or a multiple of pi, got {word!r}", what)
    return deg


_GREEK_TEX = {"θ": "\\theta", "φ": "\\phi"}
"""The angles' names as TeX (the Unicode name is the plain text's)."""


def _rot(axis: str, c: Scalar, s: Scalar, name: str, sense: int) -> Factor:
    tex = _GREEK_TEX.get(name) or _tex_deg(name)
    return Factor(f"R{axis}({name})", f"R_{axis}({tex})", space.rotation(axis, c, sense * s))


class Built(NamedTuple):
    """A projection as one kind builds it: its factors (applied in order), its working, its
    description, the coordinates drawn, the options it reads, and what else it shows."""

    factors: list[Factor]
    work: list[Quantity]
    label: str
    uv: tuple[int, int] = (0, 1)
    reads: tuple[str, ...] = ()
    vanishing: bool = False
    foreshortening: bool = False
    knobs: tuple[str, ...] = ()


Builder = Callable[[ProjectionQuestion], Built]


def orthographic(q: ProjectionQuestion) -> Built:
    view = q.view or "xy"
    zero = "xyz"[3 - sum(pj.VIEWS[view])]
    p = pj.orthographic(view)
    label = f"orthographic projection onto the {view} plane ({zero} = 0)"
    return Built([Factor(f"P_{view}", f"P_{{{view}}}", p)], [], label, pj.VIEWS[view], ("view",))


def _axonometric(
    kind: str,
    cs: Any,
    work: list[Quantity],
    names: tuple[str, str],
    sense: int,
    reads: tuple[str, ...],
) -> Built:
    (cp, sp), (ct, st) = cs
    factors = [
        _rot("y", cp, sp, names[0], sense),
        _rot("x", ct, st, names[1], sense),
        Factor("P_z", "P_z", pj.onto_z0()),
    ]
    label = f"{kind} projection: about y by {names[0]}, about x by {names[1]}, onto z = 0"
    return Built(factors, work, label, reads=reads, foreshortening=True)


def isometric(q: ProjectionQuestion) -> Built:
    work = [
        worked(
            "angles",
            None,
            "\\phi = 45^\\circ \\text{ about y};\\ \\theta \\text{ about x}: \\sin\\theta = "
            "1/\\sqrt{3} = \\frac{\\sqrt{3}}{3},\\ \\cos\\theta = \\frac{\\sqrt{6}}{3}\\ "
            "(\\theta \\approx 35.26^\\circ)",
        )
    ]
    return _axonometric("isometric", pj.ISOMETRIC, work, ("45°", "θ"), q.sense, ())


def dimetric(q: ProjectionQuestion) -> Built:
    f = q.ratio or Fraction(1, 2)
    if not 0 < f <= 1:
        raise InputError(
            f"dimetric: the z axis's foreshortening ratio must be in (0, 1], got {fmt_short(f)}",
            "ratio",
        )
    (cp, sp), (ct, st) = cs = pj.dimetric(Fraction(f))
    work = [
        worked(
            "angles",
            None,
            f"f_z = {fmt_short(f)}:\\ \\sin\\theta = f_z/\\sqrt{{2}} = {text(st, True)},\\ "
            f"\\cos\\theta = {text(ct, True)};\\ \\sin\\phi = f_z/\\sqrt{{2 - f_z^2}} = "
            f"{text(sp, True)},\\ \\cos\\phi = {text(cp, True)}",
        )
    ]
    return _axonometric("dimetric", cs, work, ("φ", "θ"), q.sense, ("ratio",))


def trimetric(q: ProjectionQuestion) -> Built:
    phi, theta = (
        _degrees(w, d, "angles") for w, d in zip(q.angles or (None, None), (30, 45), strict=True)
    )
    cs = (_trig(phi, "angles"), _trig(theta, "angles"))
    return _axonometric(
        "trimetric", cs, [], (f"{fmt_short(phi)}°", f"{fmt_short(theta)}°"), q.sense, ("angles",)
    )


def _oblique(kind: str, ratio: Scalar | None, how: str, q: ProjectionQuestion) -> Built:
    reads: tuple[str, ...] = ("angle",)
    if q.oblique_angle == "projector" and ratio is None:
        alpha = _degrees(q.angle, 45, "angle")
        ca, sa = _trig(alpha, "angle")
        if sa == 0:
            raise InputError("the projectors cannot be parallel to the view plane (α = 0)", "angle")
        ratio = simplify(Radical.of(ca) / sa)
        phi = _degrees(q.receding, 45, "receding")
        how = f"L_1 = \\cos\\alpha/\\sin\\alpha,\\ \\alpha = {fmt_short(alpha)}^\\circ: L_1 = {text(ratio, True)}"
        reads += ("receding",)
    else:
        phi = _degrees(q.angle, 45, "angle")
        if ratio is None:
            ratio = q.ratio or Fraction(1, 2)
            how = f"L_1 = {text(ratio, True)}"
            reads += ("ratio",)
    c, s = _trig(phi, "angle")
    work = [
        worked(
            "oblique",
            (json_scalar(ratio), json_scalar(c), json_scalar(s)),
            f"{how};\\ \\phi = {fmt_short(phi)}^\\circ: \\cos\\phi = {text(c, True)},\\ "
            f"\\sin\\phi = {text(s, True)};\\ x' = x + L_1 z \\cos\\phi,\\ "
            f"y' = y + L_1 z \\sin\\phi",
        )
    ]
    label = f"{kind} projection onto z = 0 (L1 = {text(ratio)}, φ = {fmt_short(phi)}°)"
    return Built(
        [Factor("P_obl", "P_{obl}", pj.oblique(ratio, c, s))],
        work,
        label,
        reads=reads,
        knobs=("oblique-angle",),
    )


def oblique(q: ProjectionQuestion) -> Built:
    return _oblique("oblique", None, "", q)


def cavalier(q: ProjectionQuestion) -> Built:
    return _oblique("cavalier", 1, "L_1 = 1\\ \\text{(cavalier: } \\alpha = 45^\\circ)", q)


def cabinet(q: ProjectionQuestion) -> Built:
    return _oblique(
        "cabinet",
        Fraction(1, 2),
        "L_1 = 1/2\\ \\text{(cabinet: } \\tan\\alpha = 2,\\ \\alpha \\approx 63.43^\\circ)",
        q,
    )


def _turn(axis: str, word: str | None, default: int, what: str, sense: int) -> Factor:
    deg = _degrees(word, default, what)
    c, s = _trig(deg, what)
    if c == 0 or s == 0:
        raise InputError(
            f"the turn about {axis} must not be a multiple of 90° (its axes must meet the view plane)",
            what,
        )
    return _rot(axis, c, s, f"{fmt_short(deg)}°", sense)


def _perspective(
    kind: str, turns: list[Factor], q: ProjectionQuestion, reads: tuple[str, ...]
) -> Built:
    d = Fraction(q.d or 1)
    if d <= 0:
        raise InputError(f"the distance d must be positive, got {fmt_short(d)}", "d")
    cop = q.cop
    centre = {
        "minus-d": f"(0, 0, -{fmt_short(d)}), view plane z = 0",
        "plus-d": f"(0, 0, {fmt_short(d)}), view plane z = 0",
        "origin": f"the origin, view plane z = {fmt_short(d)}",
    }[cop]
    formula = {
        "minus-d": "x' = x·d/(z + d), y' = y·d/(z + d)",
        "plus-d": "x' = x·d/(d - z), y' = y·d/(d - z)",
        "origin": "x' = x·d/z, y' = y·d/z",
    }[cop]
    work = [
        worked(
            "centre",
            json_scalar(d),
            f"d = {fmt_short(d)}:\\ \\text{{centre of projection {centre}}};\\ "
            + formula.replace("·", " \\cdot "),
        )
    ]
    factors = [*turns, Factor("P_per", "P_{per}", pj.perspective(cop, d))]
    label = f"{kind} perspective projection, centre {centre}"
    return Built(factors, work, label, reads=("d", *reads), vanishing=True, knobs=("cop",))


def one_point(q: ProjectionQuestion) -> Built:
    return _perspective("one-point", [], q, ())


def two_point(q: ProjectionQuestion) -> Built:
    return _perspective("two-point", [_turn("y", q.angle, 30, "angle", q.sense)], q, ("angle",))


def three_point(q: ProjectionQuestion) -> Built:
    phi, theta = q.angles or (None, None)
    turns = [_turn("y", phi, 30, "angles", q.sense), _turn("x", theta, 30, "angles", q.sense)]
    return _perspective("three-point", turns, q, ("angles",))


def _figure(s: space.Solid, uv: Sequence[tuple[Scalar, Scalar]], title: str) -> Plot:
    """The projected solid's edges, scaled to :data:`FIGURE_CELLS` cells."""
    us = [approx(u) for u, _ in uv]
    vs = [approx(v) for _, v in uv]
    extent = max(max(us) - min(us), max(vs) - min(vs))
    # an integer scale up, or 1/n down, so that the figure is about FIGURE_CELLS wide
    if extent >= FIGURE_CELLS:
        scale: Fraction | int = Fraction(1, math.ceil(extent / FIGURE_CELLS))
    else:
        scale = max(1, int(FIGURE_CELLS / extent)) if extent else 1
    pts = [(simplify(u * scale), simplify(v * scale)) for u, v in uv]
    cells = [(round_half_up_exact(u), round_half_up_exact(v)) for u, v in pts]
    pixels = tuple(
        dict.fromkeys(p for i, j in s.edges for p in outline([cells[i], cells[j]], closed=False))
    )
    xs, ys = [p[0] for p in pixels] or [0], [p[1] for p in pixels] or [0]
    ideal = tuple(
        Polyline([(float(pts[i][0]), float(pts[i][1])) for i in path], "edges")
        for path in edge_walks(len(pts), s.edges)
    )
    return Plot(
        pixels=lambda: iter(pixels),
        bbox=(min(xs), min(ys), max(xs), max(ys)),
        marks=tuple(dict.fromkeys(cells)),
        marks_label=f"vertices ({title}, scaled by {fmt_short(scale)})",
        ideal=ideal,
    )


def edge_walks(n: int, edges: Sequence[tuple[int, int]]) -> list[list[int]]:
    """Paths along the edges that draw each edge (going back along an edge where a path must
    turn back), one per connected part: a figure's polyline traces only edges.

    >>> edge_walks(3, [(0, 1), (1, 2)])
    [[0, 1, 2, 1, 0]]
    """
    nbrs: dict[int, list[int]] = {i: [] for i in range(n)}
    for i, j in edges:
        nbrs[i].append(j)
        nbrs[j].append(i)
    used: set[tuple[int, int]] = set()
    walks = []
    for start in range(n):
        if not any((min(start, w), max(start, w)) not in used for w in nbrs[start]):
            continue
        path = [start]
        stack = [(start, iter(nbrs[start]))]
        while stack:
            v, it = stack[-1]
            w = next((w for w in it if (min(v, w), max(v, w)) not in used), None)
            if w is None:
                stack.pop()
                if stack:
                    path.append(stack[-1][0])
                continue
            used.add((min(v, w), max(v, w)))
            path.append(w)
            stack.append((w, iter(nbrs[w])))
        walks.append(path)
    return walks


def _vp_table(m: Matrix4) -> tuple[Table, list[Any]]:
    vps = pj.vanishing_points(m)
    rows = [
        (
            f"{axis} axis",
            "(" + ", ".join(text(v) for v in h) + ")",
            "none: parallel to the view plane" if vp is None else point_text(vp[:2]),
        )
        for axis, h, vp in vps
    ]
    cols = (
        heading("axis", r"\text{direction}", role="label"),
        heading("image", r"M \cdot [d, 0]^T", role="working"),
        heading("vp", r"\text{vanishing point}"),
    )
    data = [None if vp is None else [json_scalar(v) for v in vp[:2]] for _, _, vp in vps]
    return Table("Vanishing points of the principal axes", cols, lambda: rows), data


def _projected(m: Matrix4, s: space.Solid) -> list[pj.Projected]:
    """Each vertex through ``m``, refused at or behind the centre of projection."""
    projected = []
    for lab, p in zip(s.labels, s.vertices, strict=True):
        try:
            projected.append(pj.project(m, p))
        except ZeroDivisionError:
            raise InputError(
                f"vertex {lab} {point_text(p)} is in the plane of the centre of projection (W = 0)",
                "d",
            ) from None
        if approx(projected[-1].homogeneous[3]) < 0:
            raise InputError(
                f"vertex {lab} {point_text(p)} is behind the centre of projection (W < 0)", "d"
            )
    return projected


def _vertex_table(
    s: space.Solid,
    projected: Sequence[pj.Projected],
    uv: Sequence[tuple[Scalar, Scalar]],
    uv_index: tuple[int, int],
) -> Table:
    """Each vertex, M·P and the projected point (and its approximation where irrational)."""
    u_name, v_name = "xyz"[uv_index[0]], "xyz"[uv_index[1]]
    rough = irrational(uv)
    cols = [
        heading("vertex", r"\text{vertex}", role="label"),
        heading("before", "P = (x, y, z)", role="given"),
        heading("h", r"M \cdot P = (X, Y, Z, W)", role="working"),
        heading("after", f"P' = ({u_name}', {v_name}')"),
    ]
    if rough:
        cols.append(heading("approx", r"P' \text{ (approx.)}"))

    def rows() -> list[tuple[str, ...]]:
        return [
            (
                lab,
                point_text(p),
                "(" + ", ".join(text(v) for v in q.homogeneous) + ")",
                point_text(w),
                *((approx_point(w),) if rough else ()),
            )
            for lab, p, q, w in zip(s.labels, s.vertices, projected, uv, strict=True)
        ]

    return Table("Projected vertices", tuple(cols), rows)


def projection_question(kind: str, used: Mapping[str, str], sense: int) -> ProjectionQuestion:
    """The question of the projection ``kind`` with no option given, under the conventions
    ``used`` (:func:`~scanconv.algorithms.space_conventions.resolve`'s, each checked against
    its choices) and ``sense`` (1 or -1).

    >>> from scanconv.algorithms.space_conventions import resolve
    >>> projection_question("one-point", resolve(None, {}), 1).cop  # Hearn & Baker's
    'plus-d'
    """
    oblique = cast("ObliqueAngle", used["oblique-angle"])  # each one of SPACE_KNOBS' choices
    cop = cast("CentreOfProjection", used["cop"])
    return ProjectionQuestion(kind, oblique, cop, 1 if sense == 1 else -1)


def project_solution(
    words: Sequence[str],
    solid: str | None = None,
    parallel: str | None = None,
    perspective: str | None = None,
    view: str | None = None,
    angle: str | None = None,
    receding: str | None = None,
    angles: Sequence[str] | None = None,
    ratio: Number | None = None,
    d: Number | None = None,
    convention: str | None = None,
    **given: str | None,
) -> Solution:
    """The worked answer of the projection of the vertices (or ``solid``), after any
    transformations in ``words``.

    >>> sol = project_solution([], "unit-cube", parallel="cavalier")
    >>> sol.data["projected"][4]
    ['sqrt(2)/2', 'sqrt(2)/2']
    """
    used, sense, written = conventions(convention, given)
    points, stages = parse(words, sense)
    s = solid_of(points, solid)
    if (parallel is None) == (perspective is None):
        raise InputError("choose one projection, a parallel or a perspective one", "parallel")
    kind = str(parallel or perspective)
    pair = None if angles is None else tuple(angles)
    q = projection_question(kind, used, sense)._replace(
        view=view, angle=angle, receding=receding, angles=pair, ratio=ratio, d=d
    )
    built: Built = method("3d", kind).load("generator")(q)
    for name in q.given():
        if name not in built.reads:
            raise InputError(f"--{name} does not apply to the {kind} projection", name)
    label = built.label
    all_stages = [*stages, Stage(label, tuple(built.factors), tuple(built.work), True)]
    derived, mat_rows, mats = stage_matrices(all_stages, written)
    m, order, shown = composite(mats, written, derived, mat_rows, always=False)
    projected = _projected(m, s)
    uv = pj.drawn([q.point for q in projected], built.uv)
    rough = irrational(uv)
    tables = [
        Table(f"Matrices ({written.law})", MATRIX_COLUMNS, lambda: mat_rows),
        _vertex_table(s, projected, uv, built.uv),
    ]
    data: dict[str, Any] = {
        "conventions": used,
        "matrix": matrix_json(shown),
        "projected": [[json_scalar(v) for v in p] for p in uv],
        "edges": [list(e) for e in s.edges],
    }
    if built.vanishing:
        vp_table, data["vanishing_points"] = _vp_table(m)
        tables.append(vp_table)
    if built.foreshortening:
        f2 = pj.foreshortening(m)
        derived.append(
            worked(
                "foreshortening",
                [json_scalar(v) for v in f2],
                "\\text{foreshortening of the unit x, y, z vectors: } f_x^2, f_y^2, f_z^2 = "
                + ", ".join(text(v, True) for v in f2),
            )
        )
    knobs = ("vectors", "axes", "sense", *built.knobs)
    notes = notes_of(convention, used, knobs, all(st.exact for st in stages))
    notes.append(
        f"{written.law} with P = [x, y, z, 1]; the projected point is (X/W, Y/W); M = {order}."
    )
    if rough:
        notes.append("Values with square roots are exact; the figure rounds them half up.")
    sol = Solution(
        primitive="3d-project",
        algorithm=kind,
        title=f"3D projection of {s.title}: {label}",
        given=vertices_given(s),
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(tables=tuple(tables)),
        plot=_figure(s, uv, label),
        data=data,
    )
    sol.question = q
    return sol
