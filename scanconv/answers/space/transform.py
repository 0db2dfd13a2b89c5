"""The worked answer of a composite 3D transformation in homogeneous coordinates (4 x 4).

Each transformation is shown as its matrix with the numbers substituted (a rotation about an
arbitrary axis as its seven steps, each with its numbers), then the composite, then every
vertex before and after. sin and cos are exact at multiples of 15 degrees, an axis's direction
cosines exact with their square roots (``sqrt(3)/3``); other angles are rounded to 6 decimals.

Transformations are given as words (the command line's options), in the order applied::

    --translate TX TY TZ | --scale S | --scale SX SY SZ | --rotate-x A | --rotate-y A |
    --rotate-z A | --shear x|y|z A B   (each of scale, rotate and shear may add --about X Y Z)
    --rotate-axis X1 Y1 Z1 X2 Y2 Z2 A | --reflect xy|yz|zx | --reflect plane A B C D

(``plane A B C D``: the plane ``Ax + By + Cz + D = 0``.) The conventions
(:mod:`scanconv.algorithms.space_conventions`) decide how the matrices are written.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction
from typing import NamedTuple

from ...algorithms import space
from ...algorithms.radical import Radical, Scalar, approx, root_primes, simplify
from ...algorithms.space import Matrix4, Point3, Solid
from ...algorithms.space_conventions import convention_notes, resolve
from ...algorithms.transform import cos_sin
from ...core.checks import InputError
from ...core.numeric import fmt, fmt_short, parse_number
from ...core.records import Plot, Quantity, Solution, Table, Walk, heading, worked
from ..process._shared import (
    MAX_POINTS,
    json_scalar,
    matrix_json,
    matrix_rows,
    matrix_tex,
    text,
)
from ..process.transform import MAX_TRANSFORMS, _rounded, _tex_deg, _Words, parse_angle

NAMES = (
    "translate",
    "scale",
    "rotate-x",
    "rotate-y",
    "rotate-z",
    "rotate-axis",
    "reflect",
    "shear",
)
"""The transformations, by name."""

MAX_ROOT_PRIMES = 6
"""Most different primes under the square roots of one answer's matrices (2, 3 and the axes'
own): each doubles the terms an exact product can have."""


class Factor(NamedTuple):
    """A basic matrix: its name in text and TeX, its entries (column vectors)."""

    text: str
    tex: str
    matrix: Matrix4


class Stage(NamedTuple):
    """One transformation as given: what it is, its factors (applied in order) and the
    working shown for it."""

    label: str
    factors: tuple[Factor, ...]
    working: tuple[Quantity, ...]
    exact: bool


def point_text(p: Sequence[Scalar], tex: bool = False) -> str:
    """``(x, y, z)`` exactly."""
    return "(" + ", ".join(text(v, tex) for v in p) + ")"


def _t(p: Sequence[Scalar], sign: int = 1) -> Factor:
    x, y, z = (sign * v for v in p)
    s = f"T({text(x)}, {text(y)}, {text(z)})"
    return Factor(s, s, space.translation(x, y, z))


def _about(words: _Words, name: str, core: Factor) -> tuple[tuple[Factor, ...], str]:
    """``core`` about a fixed point if ``--about X Y Z`` follows: ``T(p)·core·T(-p)``."""
    if words.peek() != "about":
        return (core,), ""
    words.take()
    p = words.numbers(3, f"{name} about")
    return (_t(p, -1), core, _t(p)), f" about {point_text(p)}"


def _angle(words: _Words, what: str) -> tuple[Scalar, Scalar, bool, str, Quantity]:
    """``(cos θ, sin θ, exact, name, working)`` of the next word."""
    if not words.more():
        raise InputError(f"{what} needs an angle", "transforms")
    deg, rad, label = parse_angle(words.take())
    if deg is not None:
        c, s, exact = cos_sin(deg)
        name = f"{fmt_short(deg)}°"
    else:
        c, s, exact = _rounded(math.cos(rad)), _rounded(math.sin(rad)), False
        name = label
    how = "" if exact else "\\ \\text{(rounded half up to 6 decimals)}"
    trig = worked(
        "trig",
        (json_scalar(c), json_scalar(s)),
        f"\\theta = {_tex_deg(label)}: \\cos\\theta = {text(c, True)}, "
        f"\\sin\\theta = {text(s, True)}{how}",
    )
    return c, s, exact, name, trig


def _rotate(words: _Words, axis: str, sense: int) -> Stage:
    c, s, exact, name, trig = _angle(words, f"rotate-{axis}")
    core = Factor(
        f"R{axis}({name})", f"R_{axis}({_tex_deg(name)})", space.rotation(axis, c, sense * s)
    )
    factors, about = _about(words, f"rotate-{axis}", core)
    through = about.replace(" about", " through", 1)
    return Stage(f"rotate by {name} about the {axis} axis{through}", factors, (trig,), exact)


def _root_tex(square: Scalar, root: Scalar) -> str:
    """``\\sqrt{n} = value`` in TeX, or ``\\sqrt{n}`` alone where that is its exact value."""
    first = f"\\sqrt{{{text(square, True)}}}"
    return first if text(root, True) == first else f"{first} = {text(root, True)}"


def _rotate_axis(words: _Words, sense: int) -> Stage:
    coords = words.numbers(6, "rotate-axis")
    p1, p2 = (coords[0], coords[1], coords[2]), (coords[3], coords[4], coords[5])
    c, s, exact, name, trig = _angle(words, "rotate-axis")
    try:
        r = space.axis_rotation(p1, p2, c, sense * s)
    except ValueError as err:
        raise InputError(f"rotate-axis: {err}", "transforms") from None
    (vx, vy, vz), (a, b, cz) = r.v, r.u
    steps = [
        worked(
            "axis",
            [json_scalar(v) for v in r.u],
            f"V = P_2 - P_1 = {point_text(r.v, True)},\\ |V| = "
            f"{_root_tex(vx * vx + vy * vy + vz * vz, r.length)};\\ u = V/|V| = (a, b, c) = "
            f"{point_text(r.u, True)};\\ d = \\sqrt{{b^2 + c^2}} = {text(r.d, True)}",
        ),
    ]
    if r.d != 0:
        ca, sa = simplify(cz / Radical.of(r.d)), simplify(b / Radical.of(r.d))
        steps.append(
            worked(
                "alpha",
                (json_scalar(ca), json_scalar(sa)),
                f"\\text{{about x: }} \\cos\\alpha = c/d = {text(ca, True)},\\ "
                f"\\sin\\alpha = b/d = {text(sa, True)}",
            )
        )
    steps.append(
        worked(
            "beta",
            (json_scalar(r.d), json_scalar(-a)),
            f"\\text{{about y: }} \\cos\\beta = d = {text(r.d, True)},\\ "
            f"\\sin\\beta = -a = {text(-a, True)}",
        )
    )
    names = {"Rz(θ)": (f"Rz({name})", f"R_z({_tex_deg(name)})")}
    factors = tuple(
        Factor(*names.get(n, (n, n.replace("α", "\\alpha").replace("β", "\\beta"))), m)
        for n, m in r.factors
    )
    label = f"rotate by {name} about the axis through {point_text(p1)} and {point_text(p2)}"
    return Stage(label, factors, (*steps, trig), exact)


def _reflect(words: _Words) -> Stage:
    plane = words.take().lower() if words.more() else ""
    if plane in space.REFLECTIONS:
        n = f"Ref({plane})"
        return Stage(
            f"reflect about the {plane} plane", (Factor(n, n, space.REFLECTIONS[plane]),), (), True
        )
    if plane != "plane":
        choices = ", ".join([*space.REFLECTIONS, "plane A B C D"])
        raise InputError(
            f"cannot reflect about {plane or 'nothing'!r} (choose from {choices})", "transforms"
        )
    a, b, c, d = words.numbers(4, "reflect plane")
    nn = a * a + b * b + c * c
    if nn == 0:
        raise InputError(
            "reflect plane A B C D needs a normal (A, B, C) that is not 0", "transforms"
        )
    p0 = (-d * a / nn, -d * b / nn, -d * c / nn)
    core = Factor("Ref(n)", "\\mathrm{Ref}(n)", space.reflection_plane((a, b, c)))
    work = worked(
        "plane",
        None,
        f"n = ({fmt_short(a)}, {fmt_short(b)}, {fmt_short(c)}),\\ n \\cdot n = {fmt_short(nn)}:\\ "
        f"\\mathrm{{Ref}}(n) = I - 2 n n^T/(n \\cdot n);\\ \\text{{a point of the plane }} "
        f"P_0 = -D n/(n \\cdot n) = {point_text(p0, True)}",
    )
    factors = (core,) if d == 0 else (_t(p0, -1), core, _t(p0))
    label = f"reflect about the plane {fmt_short(a)}x + {fmt_short(b)}y + {fmt_short(c)}z + {fmt_short(d)} = 0"
    return Stage(label, factors, (work,), True)


def _shear(words: _Words) -> Stage:
    axis = words.take().lower() if words.more() else ""
    if axis not in space.SHEAR_AXES:
        raise InputError(f"shear needs its axis x, y or z, got {axis or 'nothing'!r}", "transforms")
    a, b = words.numbers(2, "shear")
    n = f"Sh{axis}({fmt_short(a)}, {fmt_short(b)})"
    factors, about = _about(words, "shear", Factor(n, n, space.shearing(axis, a, b)))
    return Stage(f"shear along {axis} by {fmt_short(a)}, {fmt_short(b)}{about}", factors, (), True)


def _stage(w: _Words, name: str, sense: int) -> Stage:
    if name == "translate":
        p = w.numbers(3, "translate")
        return Stage(f"translate by {point_text(p)}", (_t(p),), (), True)
    if name == "scale":
        s = w.numbers(1, "scale")
        if w.is_number():
            s += w.numbers(2, "scale")
        sx, sy, sz = s if len(s) == 3 else s * 3
        n = f"S({fmt_short(sx)}, {fmt_short(sy)}, {fmt_short(sz)})"
        factors, about = _about(w, "scale", Factor(n, n, space.scaling(sx, sy, sz)))
        return Stage(f"scale by {point_text((sx, sy, sz))}{about}", factors, (), True)
    if name in ("rotate-x", "rotate-y", "rotate-z"):
        return _rotate(w, name[-1], sense)
    if name == "rotate-axis":
        return _rotate_axis(w, sense)
    if name == "reflect":
        return _reflect(w)
    if name == "shear":
        return _shear(w)
    if name == "about":
        raise InputError("--about X Y Z must follow a scale, rotate or shear", "transforms")
    shown = name if name.startswith("-") else f"--{name}"
    raise InputError(
        f"unknown transformation {shown!r} (choose from {', '.join(NAMES)})", "transforms"
    )


def _not_a_number(word: str, counted: bool) -> None:
    """Refuse a word after the vertices that reads as a number but is not one (``nan``,
    ``inf``, past the limit), or any word that is not a transformation where a vertex is
    short of its z (``counted``: the vertices are whole, so the word is a transformation's
    name, checked as such)."""
    if word.lower().lstrip("-") in NAMES:
        return
    try:
        parse_number(word)
    except ValueError as err:
        if "is not a number" not in str(err) or not counted:
            raise InputError(f"vertices: {err}", "vertices") from None


def parse(words: Sequence[str], sense: int = 1) -> tuple[list[Point3], list[Stage]]:
    """The vertices the words start with, and the transformations after them, in order.

    >>> pts, stages = parse(["0", "0", "0", "1", "1", "1", "--rotate-z", "90", "--translate", "1", "0", "0"])
    >>> pts, [s.label for s in stages]
    ([(0, 0, 0), (1, 1, 1)], ['rotate by 90° about the z axis', 'translate by (1, 0, 0)'])
    """
    if any(not word.strip() for word in words):
        raise InputError(
            "empty value '' where a number or a transformation is expected", "transforms"
        )
    w = _Words(words)
    coords: list[Fraction] = []
    while w.is_number():
        coords.append(w.numbers(1, "vertices")[0])
    if w.more():
        _not_a_number(w.words[w.i], len(coords) % 3 == 0)
    if len(coords) % 3:
        raise InputError(f"vertices are x y z triples: got {len(coords)} coordinates", "vertices")
    if len(coords) > 3 * MAX_POINTS:
        raise InputError(f"at most {MAX_POINTS} vertices, got {len(coords) // 3}", "vertices")
    points = [tuple(simplify(v) for v in coords[i : i + 3]) for i in range(0, len(coords), 3)]
    stages: list[Stage] = []
    while w.more():
        word = w.take()
        stages.append(
            _stage(w, word.lower() if word.startswith("-") else word.lower().lstrip("-"), sense)
        )
        if len(stages) > MAX_TRANSFORMS:
            raise InputError(
                f"at most {MAX_TRANSFORMS} transformations can be composed", "transforms"
            )
    return points, stages  # type: ignore[return-value]


def solid_of(points: Sequence[Point3], solid: str | None) -> Solid:
    """The solid the answer works on: a named one, or the vertices given."""
    if solid is not None:
        if points:
            raise InputError("give the vertices or a named solid, not both", "solid")
        if solid not in space.SOLIDS:
            raise InputError(
                f"unknown solid {solid!r} (choose from {', '.join(space.SOLIDS)})", "solid"
            )
        return space.SOLIDS[solid]
    if not points:
        raise InputError("no vertices given (X1 Y1 Z1 ... or a named solid)", "vertices")
    return space.given_solid(points)


# --- the answer's parts, shared with the projections -----------------------------------------


class Written(NamedTuple):
    """How the conventions write a matrix and a product: row vectors show the transposes."""

    row: bool

    def shown(self, m: Matrix4) -> Matrix4:
        return space.transpose(m) if self.row else m

    def product(self, names: Sequence[str]) -> str:
        """The names of factors applied in the order given, written as a product."""
        return "·".join(names if self.row else reversed(names))

    @property
    def law(self) -> str:
        return "P' = P·M" if self.row else "P' = M·P"


def stage_matrices(
    stages: Sequence[Stage], written: Written, prefix: str = "M"
) -> tuple[list[Quantity], list[tuple[str, ...]], list[Matrix4]]:
    """Each stage's working and its matrix (column form), and the matrices' table rows."""
    primes = {
        p for st in stages for f in st.factors for r in f.matrix for v in r for p in root_primes(v)
    }
    if len(primes) > MAX_ROOT_PRIMES:
        raise InputError(
            f"the matrices' square roots have {len(primes)} different primes (at most "
            f"{MAX_ROOT_PRIMES}: the exact products would grow as 2^{len(primes)} terms)",
            "transforms",
        )
    derived: list[Quantity] = []
    rows: list[tuple[str, ...]] = []
    mats: list[Matrix4] = []
    for i, stage in enumerate(stages, 1):
        mi = space.compose([f.matrix for f in stage.factors])
        mats.append(mi)
        derived.extend(q._replace(key=f"{q.key}{i}") for q in stage.working)
        tex = written.product([f.tex for f in stage.factors]).replace("·", "\\cdot ")
        shown = written.shown(mi)
        if len(stage.factors) > 1:
            for f in stage.factors:
                rows += matrix_rows(f.text, "", written.shown(f.matrix))
        rows += matrix_rows(f"{prefix}{i}", stage.label, shown)
        derived.append(
            worked(
                f"{prefix}{i}",
                matrix_json(shown),
                f"{prefix}_{{{i}}} = {tex} = {matrix_tex(shown)}",
            )
        )
    return derived, rows, mats


def composite(
    mats: Sequence[Matrix4],
    written: Written,
    derived: list[Quantity],
    rows: list[tuple[str, ...]],
    always: bool = True,
) -> tuple[Matrix4, str, Matrix4]:
    """The composite of the stages' matrices, its order written and the matrix as shown; its
    working and table rows added to ``derived`` and ``rows`` (``always``: even of one)."""
    m = space.compose(mats)
    order = written.product([f"M{i}" for i in range(1, len(mats) + 1)])
    shown = written.shown(m)
    if always or len(mats) > 1:
        derived.append(
            worked(
                "M",
                matrix_json(shown),
                "M = " + order.replace("·", " \\cdot ") + f" = {matrix_tex(shown)}",
            )
        )
        rows += matrix_rows("M", f"composite {order}", shown)
    return m, order, shown


MATRIX_COLUMNS = (
    heading("matrix", r"\text{matrix}", role="label"),
    heading("work", r"\text{transformation}", role="given"),
    *(heading(f"c{j}", rf"\text{{col }} {j}") for j in range(1, 5)),
)


def vertices_given(s: Solid) -> tuple[Quantity, ...]:
    return tuple(
        worked(
            lab,
            [json_scalar(v) for v in p],
            f"{lab} = {point_text(p, True)}",
        )
        for lab, p in zip(s.labels, s.vertices, strict=True)
    )


def irrational(points: Sequence[Sequence[Scalar]]) -> bool:
    return any(isinstance(simplify(v), Radical) for p in points for v in p)


def approx_point(p: Sequence[Scalar]) -> str:
    return "(" + ", ".join(fmt(approx(v)) for v in p) + ")"


def notes_of(
    convention: str | None, used: dict[str, str], knobs: tuple[str, ...], exact: bool
) -> list[str]:
    notes = [convention_notes(convention, used, knobs)]
    if not exact:
        notes.append(
            "sin and cos of this angle are rounded half up to 6 decimals; everything after that is exact."
        )
    return notes


def conventions(
    convention: str | None, given: dict[str, str | None]
) -> tuple[dict[str, str], int, Written]:
    used = resolve(convention, given)
    return used, (1 if used["sense"] == "standard" else -1), Written(used["vectors"] == "row")


# --- the answer -------------------------------------------------------------------------------


def transform_solution(
    words: Sequence[str],
    solid: str | None = None,
    convention: str | None = None,
    **given: str | None,
) -> Solution:
    """The worked answer of the composite of the transformations in ``words`` applied to the
    vertices the words start with (or to ``solid``).

    >>> sol = transform_solution("--rotate-z 90 --translate 1 0 0".split(), "unit-cube")
    >>> sol.data["matrix"][:2], sol.data["after"][6]
    ([[0, -1, 0, 1], [1, 0, 0, 0]], [0, 1, 1])
    """
    used, sense, written = conventions(convention, given)
    points, stages = parse(words, sense)
    s = solid_of(points, solid)
    if not stages:
        raise InputError(f"no transformation given (choose from {', '.join(NAMES)})", "transforms")
    derived, mat_rows, mats = stage_matrices(stages, written)
    m, order, shown = composite(mats, written, derived, mat_rows)
    after = [space.apply(m, p) for p in s.vertices]
    det = space.determinant(m)
    derived.append(worked("det", json_scalar(det), f"\\det M = {text(det, True)}"))
    rough = irrational(after)
    cols = [
        heading("vertex", r"\text{vertex}", role="label"),
        heading("before", "P = (x, y, z)", role="given"),
        heading("after", "P' = (x', y', z')"),
    ]
    if rough:
        cols.append(heading("approx", r"P' \text{ (approx.)}"))

    def vertex_rows() -> list[tuple[str, ...]]:
        return [
            (lab, point_text(p), point_text(q), *((approx_point(q),) if rough else ()))
            for lab, p, q in zip(s.labels, s.vertices, after, strict=True)
        ]

    notes = notes_of(convention, used, ("vectors", "axes", "sense"), all(st.exact for st in stages))
    notes.append(
        f"{written.law} with P = [x, y, z, 1]; the transformation given first is applied first: "
        f"M = {order}. A transformation about a fixed point p is T(p)·X·T(-p) (column form)."
    )
    if rough:
        notes.append("Values with square roots are exact (sqrt(3)/3 = 1/sqrt(3)).")
    labels = ", then ".join(st.label for st in stages)
    return Solution(
        primitive="3d-transform",
        algorithm="homogeneous",
        title=f"3D transformation of {s.title}: {labels}",
        given=vertices_given(s),
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(
            tables=(
                Table(f"Matrices ({written.law})", MATRIX_COLUMNS, lambda: mat_rows),
                Table("Vertices before and after", tuple(cols), vertex_rows),
            )
        ),
        plot=Plot(),
        data={
            "conventions": used,
            "matrix": matrix_json(shown),
            "determinant": json_scalar(det),
            "before": [[json_scalar(v) for v in p] for p in s.vertices],
            "after": [[json_scalar(v) for v in p] for p in after],
            "edges": [list(e) for e in s.edges],
        },
    )
