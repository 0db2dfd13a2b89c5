"""The worked answer of a line: given and derived values around a line algorithm's steps."""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction

from ..algorithms.lines import (
    ALGORITHMS,
    abs_value,
    basic,
    bresenham,
    dda,
    dda_increments,
    dda_steps,
    orient,
)
from ..core.numeric import (
    Number,
    fmt_exact,
    fmt_paren,
    fmt_short,
    fmt_value,
    normalize,
    round_half_up,
)
from ..core.records import Column, Pixel, Quantity, Solution, Step

# --- Solutions: the exam answer around the steps -------------------------------------------


def _once(pixels: Iterator[Pixel]) -> Iterator[Pixel]:
    """Drop a pixel equal to the one before it (DDA rows can round to the same pixel when the
    end points are fractional); a monotone walk never revisits an older pixel.

    >>> list(_once(iter([(1, 0), (1, 0), (2, 0)])))
    [(1, 0), (2, 0)]
    """
    last = None
    for p in pixels:
        if p != last:
            yield p
        last = p


def _diff(name: str, tex: str, a: Number, b: Number, key: str) -> Quantity:
    """``Δx = x₂ - x₁ = 10 - 2 = 8``."""
    v = normalize(b - a)
    return Quantity(
        key,
        v,
        f"Δ{name} = {name}2 - {name}1 = {fmt_short(b)} - {fmt_paren(a)} = {fmt_short(v)}",
        f"\\Delta {tex} = {tex}_2 - {tex}_1 = {fmt_short(b)} - {fmt_paren(a)} = {fmt_short(v)}",
    )


def _slope(dx: Number, dy: Number) -> Quantity:
    if dx == 0:
        return Quantity(
            "m",
            None,
            "m = Δy / Δx is undefined (vertical line)",
            r"m = \Delta y / \Delta x \text{ is undefined (vertical line)}",
        )
    m = normalize(Fraction(dy) / dx)
    return Quantity(
        "m",
        m,
        f"m = Δy / Δx = {fmt_short(dy)} / {fmt_short(dx)} = {fmt_value(m)}",
        f"m = \\frac{{\\Delta y}}{{\\Delta x}} = \\frac{{{fmt_short(dy)}}}{{{fmt_short(dx)}}} = "
        + fmt_value(m).replace("≈", "\\approx"),
    )


def _major(dx: Number, dy: Number) -> Quantity:
    steep = abs_value(dy) > abs_value(dx)
    axis = "y" if steep else "x"
    rel, tex_rel = (">", ">") if steep else ("<=", r"\le")
    return Quantity(
        "major_axis",
        axis,
        f"major axis: {axis}, since |Δy| = {fmt_short(abs_value(dy))} {rel} |Δx| = {fmt_short(abs_value(dx))}",
        f"\\text{{major axis: }} {axis}, \\quad |\\Delta y| = {fmt_short(abs_value(dy))} {tex_rel} "
        f"|\\Delta x| = {fmt_short(abs_value(dx))}",
    )


def _given(x1: Number, y1: Number, x2: Number, y2: Number) -> tuple[Quantity, ...]:
    p1, p2 = (normalize(x1), normalize(y1)), (normalize(x2), normalize(y2))
    return (
        Quantity(
            "P1",
            p1,
            f"P1 = ({fmt_short(x1)}, {fmt_short(y1)})",
            f"P_1 = ({fmt_short(x1)}, {fmt_short(y1)})",
        ),
        Quantity(
            "P2",
            p2,
            f"P2 = ({fmt_short(x2)}, {fmt_short(y2)})",
            f"P_2 = ({fmt_short(x2)}, {fmt_short(y2)})",
        ),
    )


def _bbox(*pts: tuple[Number, Number]) -> tuple[int, int, int, int]:
    xs = [round_half_up(p[0]) for p in pts]
    ys = [round_half_up(p[1]) for p in pts]
    return min(xs), min(ys), max(xs), max(ys)


def _title(name: str, x1: Number, y1: Number, x2: Number, y2: Number) -> str:
    return f"{name}: ({fmt_short(x1)}, {fmt_short(y1)}) to ({fmt_short(x2)}, {fmt_short(y2)})"


def line_solution(algo: str, x1: Number, y1: Number, x2: Number, y2: Number) -> Solution:
    """The worked solution of a line with one of :data:`ALGORITHMS`.

    Raises ``ValueError`` for an unknown algorithm or a non-integer end point with
    ``bresenham``.

    >>> sol = line_solution("bresenham", 2, 2, 10, 6)
    >>> for q in sol.derived[-3:]:
    ...     print(q.text)
    p0 = 2Δy - Δx = 2·4 - 8 = 0
    2Δy = 2·4 = 8   (added when p_k < 0)
    2Δy - 2Δx = 2·4 - 2·8 = -8   (added when p_k >= 0)
    >>> list(sol.pixels())[:4]
    [(2, 2), (3, 3), (4, 3), (5, 4)]
    """
    if algo == "bresenham":
        return _bresenham_solution(x1, y1, x2, y2)
    if algo == "dda":
        return _dda_solution(x1, y1, x2, y2)
    if algo == "basic":
        return _basic_solution(x1, y1, x2, y2)
    raise ValueError(f"unknown line algorithm {algo!r} (choose from {', '.join(ALGORITHMS)})")


def _bresenham_solution(x1: Number, y1: Number, x2: Number, y2: Number) -> Solution:
    for v, n in ((x1, "x1"), (y1, "y1"), (x2, "x2"), (y2, "y2")):
        if normalize(v) != int(v):
            raise ValueError(
                f"bresenham needs integer end points, got {n} = {fmt_exact(v)} "
                "(use --algo dda or basic for fractional end points)"
            )
    ix1, iy1, ix2, iy2 = int(x1), int(y1), int(x2), int(y2)
    sx, sy, ex, ey, steep, dmaj, dmin, sign, stay, move = orient(ix1, iy1, ix2, iy2)
    swapped = (sx, sy) != (ix1, iy1)
    dx, dy = ex - sx, ey - sy  # after the swap, as the working is written
    maj, mnr = ("y", "x") if steep else ("x", "y")
    dmin_s = f"|Δ{mnr}|" if sign < 0 else f"Δ{mnr}"
    dmin_t = f"|\\Delta {mnr}|" if sign < 0 else f"\\Delta {mnr}"
    p0 = 2 * dmin - dmaj
    inc_keep, inc_step = 2 * dmin, 2 * dmin - 2 * dmaj
    derived = [
        _diff("x", "x", sx, ex, "dx"),
        _diff("y", "y", sy, ey, "dy"),
        _slope(dx, dy),
        _major(dx, dy),
        Quantity(
            "p0",
            p0,
            f"p0 = 2{dmin_s} - Δ{maj} = 2·{dmin} - {dmaj} = {p0}",
            f"p_0 = 2{dmin_t} - \\Delta {maj} = 2 \\cdot {dmin} - {dmaj} = {p0}",
        ),
        Quantity(
            "inc_keep",
            inc_keep,
            f"2{dmin_s} = 2·{dmin} = {inc_keep}   (added when p_k < 0)",
            f"2{dmin_t} = 2 \\cdot {dmin} = {inc_keep} \\quad (\\text{{added when }} p_k < 0)",
        ),
        Quantity(
            "inc_step",
            inc_step,
            f"2{dmin_s} - 2Δ{maj} = 2·{dmin} - 2·{dmaj} = {inc_step}   (added when p_k >= 0)",
            f"2{dmin_t} - 2\\Delta {maj} = 2 \\cdot {dmin} - 2 \\cdot {dmaj} = {inc_step} "
            f"\\quad (\\text{{added when }} p_k \\ge 0)",
        ),
    ]
    notes = [f"Start at ({sx}, {sy}), plotted before the first step."]
    if swapped:
        notes.insert(
            0,
            f"End points swapped so that {maj} increases along the walk: "
            f"(x1, y1) = ({sx}, {sy}), (x2, y2) = ({ex}, {ey}).",
        )
    notes.append(
        f"p_k < 0 chooses {stay}, p_k >= 0 chooses {move}; a tie (p_k = 0) steps {mnr} too."
    )

    def steps() -> Iterator[Step]:
        return bresenham(ix1, iy1, ix2, iy2)

    def pixels() -> Iterator[Pixel]:
        yield (sx, sy)
        for s in bresenham(ix1, iy1, ix2, iy2):
            yield s.pixel

    return Solution(
        primitive="line",
        algorithm="bresenham",
        title=_title("Bresenham's line algorithm", ix1, iy1, ix2, iy2),
        given=_given(ix1, iy1, ix2, iy2),
        derived=tuple(derived),
        columns=(
            Column("k", "k", "k"),
            Column("p", "p_k", "p_k"),
            Column("decision", "decision", r"\text{decision}"),
            Column("pixel", "(x_{k+1}, y_{k+1})", "(x_{k+1}, y_{k+1})"),
            Column("p_next", "p_{k+1}", "p_{k+1}"),
        ),
        extra_keys=("p_next",),
        steps=steps,
        pixels=pixels,
        bbox=_bbox((ix1, iy1), (ix2, iy2)),
        geometry={"line": (ix1, iy1, ix2, iy2)},
        notes=tuple(notes),
    )


def _dda_solution(x1: Number, y1: Number, x2: Number, y2: Number) -> Solution:
    dx, dy = normalize(x2 - x1), normalize(y2 - y1)
    steps_n = dda_steps(x1, y1, x2, y2)
    xi, yi = dda_increments(x1, y1, x2, y2)
    ceil_note = "" if max(abs_value(dx), abs_value(dy)) == steps_n else f", rounded up to {steps_n}"
    derived = [
        _diff("x", "x", x1, x2, "dx"),
        _diff("y", "y", y1, y2, "dy"),
        _slope(dx, dy),
        _major(dx, dy),
        Quantity(
            "steps",
            steps_n,
            f"steps = max(|Δx|, |Δy|) = max({fmt_short(abs_value(dx))}, {fmt_short(abs_value(dy))}) = {steps_n}"
            + ceil_note,
            f"\\text{{steps}} = \\max(|\\Delta x|, |\\Delta y|) = \\max({fmt_short(abs_value(dx))}, "
            f"{fmt_short(abs_value(dy))}) = {steps_n}",
        ),
    ]
    if steps_n:
        for name, d, inc in (("x", dx, xi), ("y", dy, yi)):
            derived.append(
                Quantity(
                    f"{name}_inc",
                    inc,
                    f"{name}_inc = Δ{name} / steps = {fmt_short(d)} / {steps_n} = {fmt_value(inc)}",
                    f"{name}_{{inc}} = \\frac{{\\Delta {name}}}{{\\text{{steps}}}} = "
                    f"\\frac{{{fmt_short(d)}}}{{{steps_n}}} = "
                    + fmt_value(inc).replace("≈", "\\approx"),
                )
            )
    notes = (
        "x_{k+1} = x_k + x_inc and y_{k+1} = y_k + y_inc, computed exactly;"
        " pixels are round half up, floor(v + 1/2).",
    )
    return Solution(
        primitive="line",
        algorithm="dda",
        title=_title("Simple DDA line algorithm", x1, y1, x2, y2),
        given=_given(x1, y1, x2, y2),
        derived=tuple(derived),
        columns=(
            Column("k", "k", "k"),
            Column("x", "x_k", "x_k", 3),
            Column("y", "y_k", "y_k", 3),
            Column("round_x", "round(x_k)", r"\operatorname{round}(x_k)"),
            Column("round_y", "round(y_k)", r"\operatorname{round}(y_k)"),
            Column("pixel", "pixel (x, y)", r"\text{pixel } (x, y)"),
        ),
        extra_keys=("x", "y", "round_x", "round_y"),
        steps=lambda: dda(x1, y1, x2, y2),
        pixels=lambda: _once(s.pixel for s in dda(x1, y1, x2, y2)),
        bbox=_bbox((x1, y1), (x2, y2)),
        geometry={"line": (x1, y1, x2, y2)},
        notes=notes,
    )


def _basic_solution(x1: Number, y1: Number, x2: Number, y2: Number) -> Solution:
    dx, dy = normalize(x2 - x1), normalize(y2 - y1)
    steep = abs_value(dy) > abs_value(dx)
    derived = [
        _diff("x", "x", x1, x2, "dx"),
        _diff("y", "y", y1, y2, "dy"),
        _slope(dx, dy),
        _major(dx, dy),
    ]
    if steep:
        inv = normalize(Fraction(dx) / dy)
        derived.append(
            Quantity(
                "equation",
                inv,
                f"x = x1 + (Δx / Δy)(y - y1) = {fmt_short(x1)} + {fmt_value(inv)}·(y - {fmt_paren(y1)})",
                f"x = x_1 + \\frac{{\\Delta x}}{{\\Delta y}}(y - y_1) = {fmt_short(x1)} + "
                f"{fmt_short(inv)} (y - {fmt_paren(y1)})",
            )
        )
        maj, mnr = "y", "x"
    else:
        m = normalize(Fraction(dy) / dx) if dx else 0
        derived.append(
            Quantity(
                "equation",
                m,
                f"y = y1 + m(x - x1) = {fmt_short(y1)} + {fmt_value(m)}·(x - {fmt_paren(x1)})",
                f"y = y_1 + m(x - x_1) = {fmt_short(y1)} + {fmt_short(m)} (x - {fmt_paren(x1)})",
            )
        )
        maj, mnr = "x", "y"
    return Solution(
        primitive="line",
        algorithm="basic",
        title=_title("Line by the basic (direct) method", x1, y1, x2, y2),
        given=_given(x1, y1, x2, y2),
        derived=tuple(derived),
        columns=(
            Column(maj, maj, maj),
            Column(mnr, f"{mnr} (calculated)", f"{mnr} \\text{{ (calculated)}}", 3),
            Column(f"round_{mnr}", f"{mnr} (rounded)", f"{mnr} \\text{{ (rounded)}}"),
            Column("pixel", "pixel (x, y)", r"\text{pixel } (x, y)"),
        ),
        extra_keys=(maj, mnr, f"round_{mnr}"),
        steps=lambda: basic(x1, y1, x2, y2),
        pixels=lambda: (s.pixel for s in basic(x1, y1, x2, y2)),
        bbox=_bbox((x1, y1), (x2, y2)),
        geometry={"line": (x1, y1, x2, y2)},
        notes=(f"Each {mnr} is computed exactly and rounded half up, floor(v + 1/2).",),
    )
