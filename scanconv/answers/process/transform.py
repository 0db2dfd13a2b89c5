"""The worked answer of a composite 2D transformation in homogeneous coordinates.

Each transformation is shown as its matrix with the numbers substituted, then the composite
``M = Mn···M2·M1`` (column vectors: ``P' = M·P``, so the first transformation given is the
rightmost factor), then every point before and after. sin and cos are exact at multiples of 15
degrees (``√2/2``, ``√3/2``, written ``sqrt(2)/2``), otherwise rounded to 6 decimals.

Transformations are given as words (the command line's options without their dashes)::

    translate TX TY | scale S [SY] | rotate ANGLE | shear SHX SHY   (each may add: about X Y)
    reflect x-axis | y-axis | origin | y=x | y=-x | line X1 Y1 X2 Y2

An ANGLE is in degrees (``90``, ``-30``, ``12.5deg``) or radians (``pi/4``, ``3pi/2``,
``1.2rad``).
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from fractions import Fraction
from typing import Any, NamedTuple

from ...algorithms.radical import Radical, Scalar, approx, simplify
from ...algorithms.transform import (
    REFLECTIONS,
    TRIG_PLACES,
    Matrix,
    Point,
    apply,
    compose,
    cos_sin,
    determinant,
    inverse,
    reflection_through_origin,
    rotation,
    scaling,
    shearing,
    translation,
)
from ...core.checks import InputError
from ...core.numeric import Number, fmt, fmt_short, parse_number, round_half_up
from ...core.records import Column, Plot, Quantity, Solution, Table, Walk
from ...core.working import ascii_text
from ._shared import (
    approx_text,
    check_points,
    json_scalar,
    matrix_json,
    matrix_rows,
    matrix_tex,
    matrix_text,
    point_text,
    shapes_figure,
    text,
)

MAX_TRANSFORMS = 20
"""Most transformations composed (exact entries grow with each product)."""

NAMES = ("translate", "scale", "rotate", "reflect", "shear")
"""The transformations, by name."""

# --- parsing the transformations --------------------------------------------------------------


class Factor(NamedTuple):
    """A basic matrix: its name (``T(2, 1)``) in text and TeX, and its entries."""

    text: str
    tex: str
    matrix: Matrix


class Stage(NamedTuple):
    """One transformation as given: what it is, its factors (applied right to left), and the
    working shown for it (sin and cos, a reflection line's direction)."""

    label: str
    factors: tuple[Factor, ...]
    working: tuple[Quantity, ...]
    exact: bool


_PI = re.compile(r"([+-]?)([0-9./]*)\*?pi(?:/([0-9]+))?(?:rad)?")


def parse_angle(word: str) -> tuple[Fraction | None, float, str]:
    """``(degrees if exact else None, radians, label)`` of an angle word.

    >>> parse_angle("pi/4")[0], parse_angle("-30")[2], parse_angle("1.5rad")[0]
    (Fraction(45, 1), '-30°', None)
    """
    w = word.strip().lower().replace("°", "deg").replace("π", "pi")
    m = _PI.fullmatch(w)
    try:
        if m:
            coef = parse_number(m.group(2)) if m.group(2) else Fraction(1)
            coef = -coef if m.group(1) == "-" else coef
            deg = 180 * coef / int(m.group(3) or 1)
            return deg, float(deg) * math.pi / 180, f"{word} = {fmt_short(deg)}°"
        if w.endswith("rad"):
            rad = float(parse_number(w[:-3]))
            return None, rad, f"{w[:-3]} rad ≈ {fmt(Fraction(math.degrees(rad)))}°"
        deg = parse_number(w.removesuffix("deg"))
    except (ValueError, ZeroDivisionError):
        raise InputError(
            f"{word!r} is not an angle (degrees, or radians: pi/4, 1.2rad)", "transforms"
        ) from None
    return deg, float(deg) * math.pi / 180, f"{fmt_short(deg)}°"


class _Words:
    def __init__(self, words: Sequence[str]) -> None:
        split = [w for word in words for w in word.replace(",", " ").split()]
        # "--rotate=90" and "--rotate 90" (the command line's spelling) read as "rotate 90"
        split = [p for w in split for p in (w.split("=", 1) if w.startswith("--") else [w])]
        self.words = [w[2:] if w.startswith("--") else w for w in split]
        self.i = 0

    def more(self) -> bool:
        return self.i < len(self.words)

    def peek(self) -> str:
        return self.words[self.i].lower() if self.more() else ""

    def take(self) -> str:
        self.i += 1
        return self.words[self.i - 1]

    def is_number(self) -> bool:
        try:
            parse_number(self.peek())
        except ValueError:
            return False
        return self.more()

    def numbers(self, n: int, what: str) -> list[Fraction]:
        out = []
        for _ in range(n):
            if not self.is_number():
                try:
                    parse_number(self.peek())
                except ValueError as err:  # a number out of range or too long: say so
                    if "out of range" in str(err) or "longer than" in str(err):
                        raise InputError(f"{what}: {err}", "transforms") from None
                got = repr(self.peek()) if self.more() else "nothing"
                raise InputError(f"{what} needs {n} numbers, got {got}", "transforms")
            out.append(parse_number(self.take()))
        return out


def _t(p: Sequence[Scalar], sign: int = 1) -> Factor:
    x, y = (sign * p[0], sign * p[1])
    s = f"T({text(x)}, {text(y)})"
    return Factor(s, s, translation(x, y))


def _about(words: _Words, name: str, core: Factor) -> tuple[tuple[Factor, ...], str]:
    """``core`` about a point if ``about X Y`` follows: ``T(p)·core·T(-p)``."""
    if words.peek() != "about":
        return (core,), ""
    words.take()
    p = words.numbers(2, f"{name} about")
    return (_t(p, -1), core, _t(p)), f" about {point_text((p[0], p[1]))}"


def _rounded(v: float) -> Fraction:
    scale = 10**TRIG_PLACES
    return Fraction(round_half_up(Fraction(v) * scale), scale)


def _tex_deg(s: str) -> str:
    return s.replace("°", "^\\circ").replace("≈", "\\approx")


def _rotate(words: _Words) -> Stage:
    if not words.more():
        raise InputError("rotate needs an angle", "transforms")
    deg, rad, label = parse_angle(words.take())
    if deg is not None:
        c, s, exact = cos_sin(deg)
        name = f"{fmt_short(deg)}°"
    else:
        c, s, exact = _rounded(math.cos(rad)), _rounded(math.sin(rad)), False
        name = label
    how = "" if exact else f" (rounded half up to {TRIG_PLACES} decimals)"
    trig = Quantity(
        "trig",
        (json_scalar(c), json_scalar(s)),
        f"θ = {label}: cos θ = {text(c)}{approx_text(c)}, sin θ = {text(s)}{approx_text(s)}{how}",
        f"\\theta = {_tex_deg(label)}: \\cos\\theta = {text(c, True)}, "
        f"\\sin\\theta = {text(s, True)}",
    )
    r = rotation(c, s)
    core = Factor(f"R({name})", f"R({_tex_deg(name)})", r)
    factors, about = _about(words, "rotate", core)
    return Stage(f"rotate by {label}{about}", factors, (trig,), exact)


def _reflect(words: _Words) -> Stage:
    axis = words.take().lower() if words.more() else ""
    axis = {"x": "x-axis", "y": "y-axis"}.get(axis, axis)
    if axis in REFLECTIONS:
        name = f"Ref({axis})"
        return Stage(f"reflect about {axis}", (Factor(name, name, REFLECTIONS[axis]),), (), True)
    if axis != "line":
        choices = ", ".join([*REFLECTIONS, "line X1 Y1 X2 Y2"])
        raise InputError(
            f"cannot reflect about {axis or 'nothing'!r} (choose from {choices})", "transforms"
        )
    x1, y1, x2, y2 = words.numbers(4, "reflect line")
    dx, dy = x2 - x1, y2 - y1
    if dx == 0 and dy == 0:
        raise InputError("reflect line needs two different points", "transforms")
    ref = reflection_through_origin(dx, dy)
    n = dx * dx + dy * dy
    work = Quantity(
        "reflection",
        None,
        f"direction (dx, dy) = ({fmt_short(dx)}, {fmt_short(dy)}): cos 2θ = (dx² - dy²)/(dx² + dy²)"
        f" = {fmt_short(dx * dx - dy * dy)}/{fmt_short(n)}, sin 2θ = 2·dx·dy/(dx² + dy²) = "
        f"{fmt_short(2 * dx * dy)}/{fmt_short(n)}",
        f"(d_x, d_y) = ({fmt_short(dx)}, {fmt_short(dy)}): \\cos 2\\theta = "
        f"\\frac{{d_x^2 - d_y^2}}{{d_x^2 + d_y^2}} = {text(ref[0][0], True)}, \\sin 2\\theta = "
        f"\\frac{{2 d_x d_y}}{{d_x^2 + d_y^2}} = {text(ref[0][1], True)}",
    )
    line = f"the line through ({fmt_short(x1)}, {fmt_short(y1)}) and ({fmt_short(x2)}, {fmt_short(y2)})"
    core = Factor("Ref(2θ)", "\\mathrm{Ref}(2\\theta)", ref)
    factors = (core,) if x1 == 0 and y1 == 0 else (_t((x1, y1), -1), core, _t((x1, y1)))
    return Stage(f"reflect about {line}", factors, (work,), True)


def parse_transforms(words: Sequence[str]) -> tuple[Stage, ...]:
    """The stages of a list of words, in the order given.

    >>> [s.label for s in parse_transforms(["rotate", "90", "about", "2", "1", "translate", "3", "0"])]
    ['rotate by 90° about (2, 1)', 'translate by (3, 0)']
    """
    w = _Words(words)
    stages: list[Stage] = []
    while w.more():
        name = w.take().lower().lstrip("-")
        if name == "translate":
            tx, ty = w.numbers(2, "translate")
            stages.append(
                Stage(f"translate by ({fmt_short(tx)}, {fmt_short(ty)})", (_t((tx, ty)),), (), True)
            )
        elif name == "scale":
            (sx,) = w.numbers(1, "scale")
            sy = w.numbers(1, "scale")[0] if w.is_number() else sx
            s = f"S({fmt_short(sx)}, {fmt_short(sy)})"
            factors, about = _about(w, "scale", Factor(s, s, scaling(sx, sy)))
            stages.append(
                Stage(f"scale by ({fmt_short(sx)}, {fmt_short(sy)}){about}", factors, (), True)
            )
        elif name == "shear":
            shx, shy = w.numbers(2, "shear")
            s = f"Sh({fmt_short(shx)}, {fmt_short(shy)})"
            factors, about = _about(w, "shear", Factor(s, s, shearing(shx, shy)))
            stages.append(
                Stage(
                    f"shear by shx = {fmt_short(shx)}, shy = {fmt_short(shy)}{about}",
                    factors,
                    (),
                    True,
                )
            )
        elif name == "rotate":
            stages.append(_rotate(w))
        elif name == "reflect":
            stages.append(_reflect(w))
        elif name == "about":
            raise InputError("'about X Y' must follow a scale, rotate or shear", "transforms")
        else:
            raise InputError(
                f"unknown transformation {name!r} (choose from {', '.join(NAMES)})", "transforms"
            )
        if len(stages) > MAX_TRANSFORMS:
            raise InputError(
                f"at most {MAX_TRANSFORMS} transformations can be composed", "transforms"
            )
    if not stages:
        raise InputError(f"no transformation given (choose from {', '.join(NAMES)})", "transforms")
    return tuple(stages)


# --- the answer -------------------------------------------------------------------------------


def _wrap(s: str) -> str:
    return f"({s})" if (" " in s or s.startswith("-")) else s


def row_working(row: Sequence[Scalar], p: Point) -> str:
    """``a·x + b·y + c`` with the numbers substituted (ASCII), and its value."""
    a, b, c = row
    value = simplify(a * p[0] + b * p[1] + c)
    parts = f"{_wrap(text(a))}*{_wrap(text(p[0]))} + {_wrap(text(b))}*{_wrap(text(p[1]))} + {_wrap(text(c))}"
    return f"{parts} = {text(value)}"


def product_text(factors: Sequence[Factor], tex: bool = False) -> str:
    """The factors in written order (the first applied is the rightmost)."""
    return ("\\cdot " if tex else "·").join(f.tex if tex else f.text for f in reversed(factors))


_MATRIX_COLUMNS = (
    Column("matrix", "matrix", r"\text{matrix}"),
    Column("work", "transformation", r"\text{transformation}"),
    Column("c1", "col 1", r"\text{col } 1"),
    Column("c2", "col 2", r"\text{col } 2"),
    Column("c3", "col 3", r"\text{col } 3"),
)


def _stage_work(stages: Sequence[Any], mats: Sequence[Matrix]) -> list[Quantity]:
    """Each stage's working and its matrix M_i."""
    derived: list[Quantity] = []
    for i, (stage, mi) in enumerate(zip(stages, mats, strict=True), 1):
        derived.extend(q._replace(key=f"{q.key}{i}") for q in stage.working)
        derived.append(
            Quantity(
                f"M{i}",
                matrix_json(mi),
                f"M{i} = {product_text(stage.factors)} = {matrix_text(mi)}",
                f"M_{i} = {product_text(stage.factors, True)} = {matrix_tex(mi)}",
            )
        )
    return derived


def _inverse_parts(m: Matrix) -> tuple[list[Quantity], Matrix]:
    """The determinant and the inverse of ``m``, worked (``InputError`` if it is singular)."""
    det = determinant(m)
    (a, b, _), (d, e, _), _ = m
    work = f"det M = a*e - b*d = {_wrap(text(a))}*{_wrap(text(e))} - {_wrap(text(b))}*{_wrap(text(d))} = {text(det)}"
    if det == 0:
        raise InputError(f"the composite matrix is singular ({work}): it has no inverse", "inverse")
    inv = inverse(m)
    return [
        Quantity("det", json_scalar(det), work, f"\\det M = ae - bd = {text(det, True)}"),
        Quantity(
            "M_inverse",
            matrix_json(inv),
            f"M⁻¹ = (1/det M)·adj M = {matrix_text(inv)}   (M⁻¹·M = I, checked exactly)",
            f"M^{{-1}} = \\frac{{1}}{{\\det M}} \\operatorname{{adj}} M = {matrix_tex(inv)}",
        ),
    ], inv


def _points_table(
    points: Sequence[Any], after: Sequence[Any], m: Matrix, irrational: bool
) -> Table:
    """Each point before and after, with the two rows of M worked on it."""
    pt_cols = [
        Column("point", "point", r"\text{point}", role="label"),
        Column("point_before", "P = (x, y)", "P = (x, y)", role="given"),
        Column(
            "work", "x' = m11*x + m12*y + m13", "x' = m_{11} x + m_{12} y + m_{13}", role="working"
        ),
        Column(
            "arithmetic",
            "y' = m21*x + m22*y + m23",
            "y' = m_{21} x + m_{22} y + m_{23}",
            role="working",
        ),
        Column("point_after", "P' = (x', y')", "P' = (x', y')"),
    ]
    if irrational:
        pt_cols.append(Column("point_approx", "P' (approx.)", r"P' \text{ (approx.)}"))

    def pt_rows() -> list[tuple[str, ...]]:
        out = []
        for i, (p, q) in enumerate(zip(points, after, strict=True), 1):
            row = [
                f"P{i}",
                point_text(p),
                row_working(m[0], p),
                row_working(m[1], p),
                point_text(q),
            ]
            if irrational:
                row.append(f"({fmt(approx(q[0]))}, {fmt(approx(q[1]))})")
            out.append(tuple(row))
        return out

    return Table("Points before and after", tuple(pt_cols), pt_rows)


def transform_solution(
    coords: Sequence[Number], transforms: Sequence[str] | str, *, inverse_too: bool = False
) -> Solution:
    """The worked answer of the composite of ``transforms`` applied to the points ``coords``
    (``x1 y1 x2 y2 ...``).

    >>> sol = transform_solution([0, 0, 4, 0, 4, 3], "rotate 90 about 2 1, translate 3 0")
    >>> for q in sol.derived:
    ...     print(q.text)
    θ = 90°: cos θ = 0, sin θ = 1
    M1 = T(2, 1)·R(90°)·T(-2, -1) = [[0, -1, 3], [1, 0, -1], [0, 0, 1]]
    M2 = T(3, 0) = [[1, 0, 3], [0, 1, 0], [0, 0, 1]]
    M = M2·M1 = [[0, -1, 6], [1, 0, -1], [0, 0, 1]]
    >>> sol.data["after"]
    [[6, -1], [6, 3], [3, 3]]
    """
    stages = parse_transforms([transforms] if isinstance(transforms, str) else transforms)
    points = check_points(coords)
    mats = [compose([f.matrix for f in s.factors]) for s in stages]
    m = compose(mats)
    derived = _stage_work(stages, mats)
    order = "·".join(f"M{i}" for i in range(len(mats), 0, -1))
    derived.append(
        Quantity(
            "M",
            matrix_json(m),
            f"M = {order} = {matrix_text(m)}",
            f"M = {_tex_order(len(mats))} = {matrix_tex(m)}",
        )
    )
    after = [apply(m, p) for p in points]
    mat_rows = [
        r
        for i, (s, mi) in enumerate(zip(stages, mats, strict=True), 1)
        for r in matrix_rows(f"M{i}", s.label, mi)
    ]
    mat_rows += matrix_rows("M", f"composite {order}", m)
    data: dict[str, Any] = {
        "matrix": matrix_json(m),
        "after": [[json_scalar(v) for v in p] for p in after],
    }
    if inverse_too:
        inv_work, inv = _inverse_parts(m)
        derived += inv_work
        mat_rows += matrix_rows("M^-1", "inverse of M", inv)
        data["inverse"] = matrix_json(inv)
    irrational = any(isinstance(simplify(v), Radical) for p in after for v in p)
    exact = all(s.exact for s in stages)
    notes = [
        "Column vectors: P' = M·P with P = [x, y, 1]^T, so the transformation given first is "
        f"the rightmost factor: M = {order}.",
        "Angles are counter-clockwise with y up; a rotation or scaling about a point p is "
        "T(p)·X·T(-p): move p to the origin, transform, move back.",
    ]
    if not exact:
        notes.append(
            f"sin and cos of this angle are rounded half up to {TRIG_PLACES} decimals; everything after that is exact."
        )
    if irrational:
        notes.append(
            "Values with square roots are exact (sqrt(2)/2 = cos 45°); the grid rounds them half up."
        )
    labels = ", then ".join(s.label for s in stages)
    matrices = Table("Matrices (column vectors, P' = M.P)", _MATRIX_COLUMNS, lambda: mat_rows)
    return Solution(
        primitive="transform",
        algorithm="homogeneous",
        title=ascii_text(f"2D transformation: {labels}"),
        given=tuple(
            Quantity(
                f"P{i}",
                [json_scalar(v) for v in p],
                f"P{i} = {point_text(p)}",
                f"P_{{{i}}} = {point_text(p, True)}",
            )
            for i, p in enumerate(points, 1)
        ),
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(tables=(matrices, _points_table(points, after, m, irrational))),
        plot=Plot(
            figures=shapes_figure(
                points,
                after,
                "# = after (P'), o = before (P), @ = both",
                "Before (o) and after (#), vertices rounded half up:",
            )
        ),
        data=data,
    )


def _tex_order(n: int) -> str:
    return " ".join(f"M_{{{i}}}" for i in range(n, 0, -1))
