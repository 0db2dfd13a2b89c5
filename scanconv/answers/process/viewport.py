"""The worked answer of a window-to-viewport mapping: sx, sy, tx, ty with the numbers
substituted, the composite matrix, every point mapped, and the distortion when sx != sy.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction

from ...algorithms.clipping import Point, Rect
from ...algorithms.transform import compose, scaling, translation, viewport_scale
from ...core.numeric import Number, fmt_paren, fmt_short, normalize, round_half_up
from ...core.records import Column, Plot, Quantity, Solution, Table, Walk
from ._shared import (
    check_points,
    check_rect,
    factor,
    matrix_rows,
    matrix_tex,
    matrix_text,
    pt,
    pt_approx,
    rect_quantity,
    rect_text,
    shapes_figure,
)


def scale_parts(w: Rect, v: Rect) -> list[Quantity]:
    """sx, sy, tx, ty with their working, and the aspect-ratio remark."""
    sx, sy, tx, ty = viewport_scale(w, v)
    out = []
    for axis, s, i in (("x", sx, 0), ("y", sy, 1)):
        lo_v, hi_v, lo_w, hi_w = v[i], v[i + 2], w[i], w[i + 2]
        out.append(
            Quantity(
                f"s{axis}",
                normalize(s),
                f"s{axis} = ({axis}vmax - {axis}vmin)/({axis}wmax - {axis}wmin) = "
                f"({fmt_short(hi_v)} - {fmt_paren(lo_v)})/({fmt_short(hi_w)} - {fmt_paren(lo_w)}) = {fmt_short(s)}",
                f"s_{axis} = \\frac{{{axis}_{{v\\max}} - {axis}_{{v\\min}}}}{{{axis}_{{w\\max}} - "
                f"{axis}_{{w\\min}}}} = \\frac{{{fmt_short(hi_v - lo_v)}}}{{{fmt_short(hi_w - lo_w)}}} = {fmt_short(s)}",
            )
        )
    for axis, s, t, i in (("x", sx, tx, 0), ("y", sy, ty, 1)):
        out.append(
            Quantity(
                f"t{axis}",
                t,
                f"t{axis} = {axis}vmin - s{axis}·{axis}wmin = {fmt_short(v[i])} - {fmt_short(s)}·{fmt_paren(w[i])} = {fmt_short(t)}",
                f"t_{axis} = {axis}_{{v\\min}} - s_{axis} {axis}_{{w\\min}} = {fmt_short(t)}",
            )
        )
    m = compose([translation(-w[0], -w[1]), scaling(sx, sy), translation(v[0], v[1])])
    out.append(
        Quantity(
            "M",
            [list(r) for r in m],
            f"M = T({fmt_short(v[0])}, {fmt_short(v[1])})·S({fmt_short(sx)}, {fmt_short(sy)})·"
            f"T({fmt_short(-w[0])}, {fmt_short(-w[1])}) = {matrix_text(m)}",
            f"M = T(x_{{v\\min}}, y_{{v\\min}}) S(s_x, s_y) T(-x_{{w\\min}}, -y_{{w\\min}}) = {matrix_tex(m)}",
        )
    )
    ratio = Fraction(sx) / Fraction(sy)
    if sx == sy:
        text = f"sx = sy = {fmt_short(sx)}: shapes keep their proportions (no distortion)"
    else:
        aw = Fraction(w[2] - w[0]) / Fraction(w[3] - w[1])
        av = Fraction(v[2] - v[0]) / Fraction(v[3] - v[1])
        text = (
            f"sx != sy: the picture is distorted; width/height is {fmt_short(aw)} for the window "
            f"but {fmt_short(av)} for the viewport, so every shape's width-to-height ratio is "
            f"multiplied by sx/sy = {fmt_short(ratio)}"
        )
    out.append(Quantity("aspect", normalize(ratio), text, f"s_x / s_y = {fmt_short(ratio)}"))
    return out


_COLUMNS = (
    Column("point", "point", r"\text{point}"),
    Column("point_world", "(xw, yw)", "(x_w, y_w)"),
    Column("work", "xv = sx*xw + tx", "x_v = s_x x_w + t_x"),
    Column("arithmetic", "yv = sy*yw + ty", "y_v = s_y y_w + t_y"),
    Column("point_view", "(xv, yv)", "(x_v, y_v)"),
    Column("pixel", "pixel", r"\text{pixel}"),
)


def mapping_table(points: Sequence[tuple[str, Point]], w: Rect, v: Rect, title: str) -> Table:
    """One row per point: the substituted mapping, the exact result and its pixel."""
    sx, sy, tx, ty = viewport_scale(w, v)
    rows = []
    for name, (x, y) in points:
        xv, yv = normalize(sx * x + tx), normalize(sy * y + ty)
        rows.append(
            (
                name,
                pt((x, y)),
                f"{factor(sx)}*{factor(x)} + {factor(tx)} = {fmt_short(xv)}",
                f"{factor(sy)}*{factor(y)} + {factor(ty)} = {fmt_short(yv)}",
                pt((xv, yv)),
                (round_half_up(xv), round_half_up(yv)),
            )
        )
    return Table(title, _COLUMNS, lambda: rows)


def viewport_solution(
    coords: Sequence[Number], window: Sequence[Number], viewport: Sequence[Number]
) -> Solution:
    """The worked window-to-viewport mapping of the points ``x1 y1 ...`` (the window's four
    corners if none are given).

    >>> sol = viewport_solution([], (0, 0, 10, 10), (100, 100, 150, 200))
    >>> [q.text for q in sol.derived[:2]]
    ['sx = (xvmax - xvmin)/(xwmax - xwmin) = (150 - 100)/(10 - 0) = 5', 'sy = (yvmax - yvmin)/(ywmax - ywmin) = (200 - 100)/(10 - 0) = 10']
    >>> sol.data["mapped"]
    [[100, 100], [150, 100], [150, 200], [100, 200]]
    """
    w = check_rect(window, "window", "window")
    v = check_rect(viewport, "viewport", "viewport")
    if coords:
        points = tuple((normalize(x), normalize(y)) for x, y in check_points(coords))
    else:
        points = ((w[0], w[1]), (w[2], w[1]), (w[2], w[3]), (w[0], w[3]))
    sx, sy, tx, ty = viewport_scale(w, v)
    mapped = [(normalize(sx * x + tx), normalize(sy * y + ty)) for x, y in points]
    named = [(f"P{i}", p) for i, p in enumerate(points, 1)]
    notes = [
        "xv = xvmin + (xw - xwmin)·sx and yv = yvmin + (yw - ywmin)·sy: the window's corners "
        "go to the viewport's corners, and relative positions are kept.",
        "Pixels are the mapped coordinates rounded half up, floor(v + 1/2).",
    ]
    if not coords:
        notes.insert(0, "No points were given: the window's four corners are mapped.")
    return Solution(
        primitive="viewport",
        algorithm="window-to-viewport",
        title=f"Window-to-viewport mapping: window {rect_text(w)} to viewport {rect_text(v)}",
        given=(rect_quantity("window", w, "w"), rect_quantity("viewport", v, "v")),
        derived=(
            *scale_parts(w, v),
            *(
                Quantity(f"{n}_view", list(q), f"{n}' = {pt_approx(q)}", f"{n}' = {pt(q)}")
                for (n, _), q in zip(named, mapped, strict=True)
            ),
        ),
        notes=tuple(notes),
        walk=Walk(
            tables=(
                Table(
                    "The composite matrix",
                    (
                        Column("matrix", "matrix", r"\text{matrix}"),
                        Column("work", "mapping", r"\text{mapping}"),
                        Column("c1", "col 1", r"\text{col } 1"),
                        Column("c2", "col 2", r"\text{col } 2"),
                        Column("c3", "col 3", r"\text{col } 3"),
                    ),
                    lambda: matrix_rows(
                        "M",
                        "T(xvmin, yvmin).S(sx, sy).T(-xwmin, -ywmin)",
                        compose(
                            [translation(-w[0], -w[1]), scaling(sx, sy), translation(v[0], v[1])]
                        ),
                    ),
                ),
                mapping_table(named, w, v, "Points mapped to the viewport"),
            )
        ),
        plot=Plot(
            figures=shapes_figure(
                [(v[0], v[1]), (v[2], v[1]), (v[2], v[3]), (v[0], v[3])],
                mapped,
                "# = mapped points, o = viewport edge, @ = both",
                "The viewport (o) and the mapped points (#), rounded half up:",
            )
        ),
        data={"mapped": [list(q) for q in mapped], "scale": [sx, sy], "translate": [tx, ty]},
    )
