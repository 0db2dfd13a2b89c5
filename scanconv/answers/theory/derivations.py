"""The theory parts of an answer: the derivation of the decision parameter with this input's
numbers substituted (``derive``), the pseudocode of exactly the variant used (``pseudocode``),
the notes' errata notes, and the comparison points the notes' comparison questions expect.

Derivations are worked :class:`~scanconv.core.records.Quantity` items (TeX, single source);
pseudocode is a :class:`~scanconv.core.records.Code` listing (ASCII lines, indented), which
every format shows as code (:class:`~scanconv.document.Pseudocode`).
"""

from __future__ import annotations

from fractions import Fraction

from ...core.numeric import Number, fmt_paren, fmt_short, normalize
from ...core.records import Code, Quantity, Table, heading, rule, worked
from .errata import ERRATA as ERRATA
from .errata import circle_errata as circle_errata
from .errata import line_errata as line_errata

DERIVATION = rule("derivation", r"\text{Derivation, with this input's numbers:}")
"""The line that opens a derivation in the working."""

# --- the notes' mistakes ----------------------------------------------------------------------


def pseudocode(title: str, lines: list[str]) -> Code:
    """A pseudocode listing: the one place an answer's ``--algorithm`` piece is made.

    >>> pseudocode("t", ["a", "  bc"])
    Code(title='t', lines=('a', '  bc'))
    """
    return Code(title, tuple(lines))


def bresenham_line_code(
    steep: bool, sign: int, swapped: bool, tie: str, backward: bool = False
) -> Code:
    """Bresenham's line for this input's octant (``backward``: walked from P1 as given, the
    major coordinate decreasing, instead of ``swapped``)."""
    maj, mnr = ("y", "x") if steep else ("x", "y")
    slope = sign
    if backward:  # the minor step's sign as seen walking from P1
        sign = -sign
    d_min = f"|d{mnr}|" if sign < 0 else f"d{mnr}"
    d_maj = f"|d{maj}|" if backward else f"d{maj}"
    cmp = "<=" if tie == "keep" else "<"
    step = f"{mnr} = {mnr} - 1" if sign < 0 else f"{mnr} = {mnr} + 1"
    lines = [
        *(
            ["swap the end points so that " + maj + " increases"]
            if swapped and not backward
            else []
        ),
        (f"|d{maj}| = |{maj}2 - {maj}1|;  " if backward else f"d{maj} = {maj}2 - {maj}1;  ")
        + (f"|d{mnr}| = |{mnr}2 - {mnr}1|" if sign < 0 else f"d{mnr} = {mnr}2 - {mnr}1"),
        f"p = 2*{d_min} - {d_maj}",
        "x = x1;  y = y1;  plot(x, y)",
        f"repeat {d_maj} times:",
        f"    {maj} = {maj} - 1" if backward else f"    {maj} = {maj} + 1",
        f"    if p {cmp} 0:  p = p + 2*{d_min}",
        f"    else:  {step};  p = p + 2*{d_min} - 2*{d_maj}",
        "    plot(x, y)",
        "end repeat",
    ]
    return pseudocode(_code_title("Bresenham's line", steep, slope), lines)


def _code_title(name: str, steep: bool, sign: int) -> str:
    axis = "|m| > 1, y is the major axis" if steep else "|m| <= 1, x is the major axis"
    slope = "negative slope" if sign < 0 else "non-negative slope"
    return f"Algorithm: {name} ({axis}, {slope})"


def dda_code(steep: bool, sign: int, rounding: str, swapped: bool = False) -> Code:
    """The simple DDA for this input's major axis (``swapped``: the end points were swapped
    so that the major coordinate increases)."""
    rnd = {"trunc": "trunc", "c-cast": "(int)(v + 0.5) of"}.get(rounding, f"round ({rounding})")
    maj = "y" if steep else "x"
    lines = [
        *([f"swap the end points so that {maj} increases"] if swapped else []),
        "dx = x2 - x1;  dy = y2 - y1",
        "steps = max(|dx|, |dy|)" + ("   (= |dy|: y is the major axis)" if steep else ""),
        "x_inc = dx / steps;  y_inc = dy / steps",
        "x = x1;  y = y1",
        f"plot({rnd} x, {rnd} y)",
        "repeat steps times:",
        "    x = x + x_inc;  y = y + y_inc",
        f"    plot({rnd} x, {rnd} y)",
        "end repeat",
    ]
    return pseudocode(_code_title("simple DDA", steep, sign), lines)


def basic_code(steep: bool, rounding: str) -> Code:
    maj, mnr = ("y", "x") if steep else ("x", "y")
    eq = "x = x1 + (y - y1) * dx / dy" if steep else "y = y1 + m * (x - x1)"
    lines = [
        "dx = x2 - x1;  dy = y2 - y1;  m = dy / dx",
        f"for {maj} = {maj}1 to {maj}2 (step 1):",
        f"    {eq}",
        f"    plot the pixel with {mnr} rounded ({rounding})",
    ]
    return pseudocode("Algorithm: the basic (direct) method", lines)


def circle_code(method: str, knobs: dict[str, str]) -> Code | None:
    """The circle method with the knob values used."""
    tie = knobs.get("tie", "step")
    cmp = "<=" if tie == "keep" else "<"
    loop = "x <= y" if knobs.get("loop") == "inclusive" else "x < y"
    if method == "midpoint":
        old = knobs.get("update") == "old"
        p0 = "5/4 - r" if knobs.get("p0") == "5/4-r" else "1 - r"
        lines = [
            f"x = 0;  y = r;  p = {p0}",
            "plot the 8 symmetric points of (x, y)",
            f"while {loop}:",
            f"    if p {cmp} 0:",
            "        p = p + 2*x + 3;  x = x + 1" if old else "        x = x + 1;  p = p + 2*x + 1",
            "    else:",
            "        p = p + 2*(x - y) + 5;  x = x + 1;  y = y - 1"
            if old
            else "        x = x + 1;  y = y - 1;  p = p + 2*x - 2*y + 1",
            "    plot the 8 symmetric points of (x, y)",
            "end while",
        ]
        return pseudocode("Algorithm: midpoint circle", lines)
    if method == "general":
        lines = [
            "x = 0;  y = r;  p = 0",
            "plot the 8 symmetric points of (x, y)",
            f"while {loop}:",
            f"    if p {cmp} 0:  x = x + 1;  p = p + 2*x + 1",
            "    else:  x = x + 1;  y = y - 1;  p = p + 2*x - 2*y + 1",
            "    plot the 8 symmetric points of (x, y)",
            "end while",
        ]
        return pseudocode("Algorithm: the notes' general method", lines)
    if method == "bresenham":
        lines = [
            "x = 0;  y = r;  d = 3 - 2*r",
            "while x <= y:",
            "    plot the 8 symmetric points of (x, y)",
            f"    if d {cmp} 0:  d = d + 4*x + 6",
            "    else:  d = d + 4*(x - y) + 10;  y = y - 1",
            "    x = x + 1",
            "end while",
        ]
        return pseudocode("Algorithm: Bresenham's circle (d0 = 3 - 2r)", lines)
    if method == "polynomial":
        lines = [
            "for x = 0, 1, 2, ...:",
            "    y = sqrt(r*r - x*x)",
            f"    if x > round(y): stop   (rounding: {knobs.get('rounding', 'half-up')})",
            "    plot the 8 symmetric points of (x, round(y))",
        ]
        return pseudocode("Algorithm: the polynomial (square-root) method", lines)
    if method == "trig":
        lines = [
            "dtheta = 1 / r",
            "for theta = 90 deg, 90 deg - dtheta, ... towards 45 deg:",
            "    x = r*cos(theta);  y = r*sin(theta)",
            "    plot the 8 symmetric points of (round(x), round(y))",
        ]
        return pseudocode("Algorithm: the parametric (trigonometric) method", lines)
    if method == "symmetric-dda":
        lines = [
            "n such that 2^(n-1) <= r < 2^n;  e = 2^(-n)",
            "x = 0;  y = r",
            "while round(x) <= round(y):",
            "    plot the 8 symmetric points of (round(x), round(y))",
            "    x = x + e*y;  y = y - e*x   (the new x)",
        ]
        return pseudocode("Algorithm: the symmetric DDA", lines)
    return None


def ellipse_code(loop: str, tie: str = "step") -> Code:
    cmp = "<=" if loop == "inclusive" else "<"
    lt1, gt2 = ("<=", ">=") if tie == "keep" else ("<", ">")
    lines = [
        "x = 0;  y = ry;  p1 = ry^2 - rx^2*ry + rx^2/4",
        f"while 2*ry^2*x {cmp} 2*rx^2*y:          (region 1)",
        "    x = x + 1",
        f"    if p1 {lt1} 0:  p1 = p1 + 2*ry^2*x + ry^2",
        "    else:  y = y - 1;  p1 = p1 + 2*ry^2*x - 2*rx^2*y + ry^2",
        "    plot the 4 symmetric points of (x, y)",
        "p2 = ry^2*(x + 1/2)^2 + rx^2*(y - 1)^2 - rx^2*ry^2",
        "while y > 0:                              (region 2)",
        "    y = y - 1",
        f"    if p2 {gt2} 0:  p2 = p2 - 2*rx^2*y + rx^2",
        "    else:  x = x + 1;  p2 = p2 + 2*ry^2*x - 2*rx^2*y + rx^2",
        "    plot the 4 symmetric points of (x, y)",
    ]
    return pseudocode("Algorithm: midpoint ellipse", lines)


# --- derivations ------------------------------------------------------------------------------


def bresenham_line_derivation(
    u0: int, v0: int, dmaj: int, dmin: int, steep: bool, sign: int
) -> tuple[Quantity, ...]:
    """The decision parameter from d1 - d2, in the octant's frame, numbers substituted.

    ``(u0, v0)`` is the start point in that frame (x the major axis, y increasing).

    >>> for q in bresenham_line_derivation(2, 2, 8, 4, False, 1)[-3:]:
    ...     print(q.text)
    pₖ = Δx(d₁ - d₂) = 2Δy·xₖ - 2Δx·yₖ + c = 8xₖ - 16yₖ + 16
    pₖ₊₁ - pₖ = 2Δy - 2Δx(yₖ₊₁ - yₖ) = 8 or 8 - 16 = -8
    p₀ = 2Δy·x₀ - 2Δx·y₀ + c = 2Δy - Δx = 2·4 - 8 = 0
    """
    m = normalize(Fraction(dmin, dmaj)) if dmaj else 0
    b = normalize(v0 - m * u0)
    c = int(2 * dmin + dmaj * (2 * b - 1))
    frame = []
    if steep:
        frame.append("x \\text{ and } y \\text{ swapped (y is the major axis)}")
    if sign < 0:
        frame.append("y \\text{ mirrored } (\\Delta y = |\\Delta y|)")
    out = []
    if frame:
        out.append(rule("d_frame", "\\text{derived in the first octant: }" + ",\\ ".join(frame)))
    a, bb = 2 * dmin, 2 * dmaj
    out += [
        worked(
            "d_line",
            (m, b),
            f"y = mx + b,\\ m = \\frac{{\\Delta y}}{{\\Delta x}} = \\frac{{{dmin}}}{{{dmaj}}} = "
            f"{fmt_short(m)},\\ b = y_0 - m x_0 = {v0} - {fmt_short(m)} \\cdot {fmt_paren(u0)} = "
            f"{fmt_short(b)}",
        ),
        rule(
            "d_distances",
            "d_1 = y - y_k = m(x_k + 1) + b - y_k,\\ d_2 = (y_k + 1) - y = y_k + 1 - m(x_k + 1) - b",
        ),
        rule("d_difference", "d_1 - d_2 = 2m(x_k + 1) - 2y_k + 2b - 1"),
        worked(
            "d_pk",
            c,
            f"p_k = \\Delta x(d_1 - d_2) = 2\\Delta y \\cdot x_k - 2\\Delta x \\cdot y_k + c = "
            f"{a}x_k - {bb}y_k {'-' if c < 0 else '+'} {abs(c)}",
        ),
        worked(
            "d_increment",
            (a, a - bb),
            f"p_{{k+1}} - p_k = 2\\Delta y - 2\\Delta x(y_{{k+1}} - y_k) = {a} \\text{{ or }} "
            f"{a} - {bb} = {a - bb}",
        ),
        worked(
            "d_p0",
            a - dmaj,
            f"p_0 = 2\\Delta y \\cdot x_0 - 2\\Delta x \\cdot y_0 + c = 2\\Delta y - \\Delta x = "
            f"2 \\cdot {dmin} - {dmaj} = {a - dmaj}",
        ),
    ]
    return tuple(out)


def dda_derivation(dx: Number, dy: Number, steps: int) -> tuple[Quantity, ...]:
    """The DDA increments from y = mx + b."""
    out = [
        rule(
            "d_line",
            "y = mx + b \\rightarrow y_{k+1} - y_k = m(x_{k+1} - x_k)",
        ),
    ]
    if steps:
        xi, yi = normalize(Fraction(dx) / steps), normalize(Fraction(dy) / steps)
        out.append(
            worked(
                "d_increments",
                (xi, yi),
                f"\\text{{one unit along the major axis: }} x_{{k+1}} = x_k + "
                f"\\frac{{{fmt_short(dx)}}}{{{steps}}},\\ y_{{k+1}} = y_k + "
                f"\\frac{{{fmt_short(dy)}}}{{{steps}}}\\ (\\Delta x_k = {fmt_short(xi)},\\ "
                f"\\Delta y_k = {fmt_short(yi)})",
            )
        )
    return tuple(out)


def midpoint_circle_derivation(r: int, p0: str) -> tuple[Quantity, ...]:
    """The midpoint circle's p from f(x + 1, y - 1/2), numbers substituted."""
    exact = Fraction(5, 4) - r
    return (
        rule("d_f", "f(x, y) = x^2 + y^2 - r^2 \\quad (< 0 \\text{ inside}, > 0 \\text{ outside})"),
        rule("d_pk", "p_k = f(x_k + 1, y_k - \\tfrac12) = (x_k + 1)^2 + (y_k - \\tfrac12)^2 - r^2"),
        worked(
            "d_p0",
            exact,
            f"p_0 = f(1, r - \\tfrac12) = 1 + (r - \\tfrac12)^2 - r^2 = \\tfrac54 - r = "
            f"\\tfrac54 - {r} = {fmt_short(exact)}"
            + ("" if p0 == "5/4-r" else f" \\rightarrow 1 - r = {1 - r} \\text{{ (integers)}}"),
        ),
        rule(
            "d_update",
            "p_{k+1} = p_k + 2(x_k + 1) + (y_{k+1}^2 - y_k^2) - (y_{k+1} - y_k) + 1",
        ),
        rule(
            "d_cases",
            "y_{k+1} = y_k: p_{k+1} = p_k + 2x_{k+1} + 1;\\ y_{k+1} = y_k - 1: "
            "p_{k+1} = p_k + 2x_{k+1} + 1 - 2y_{k+1}",
        ),
    )


def general_circle_derivation(r: int) -> tuple[Quantity, ...]:
    return (
        rule("d_f", "p = f(x, y) = x^2 + y^2 - r^2 \\text{ at the current point}"),
        worked("d_p0", 0, f"p_0 = f(0, r) = 0^2 + {r}^2 - {r}^2 = 0"),
        rule(
            "d_update",
            "f(x + 1, y) - f(x, y) = 2x + 1,\\ f(x + 1, y - 1) - f(x, y) = 2x - 2y + 2 "
            "\\text{ (old x, y)}",
        ),
        rule(
            "d_box",
            "\\text{the notes' box adds } 2x + 1 \\text{ and } 2x - 2y + 1 \\text{ with the new x "
            "and y, so after one step p is no longer } f(x, y)",
        ),
    )


def bresenham_circle_derivation(r: int) -> tuple[Quantity, ...]:
    return (
        rule("d_f", "f(x, y) = x^2 + y^2 - r^2"),
        rule(
            "d_dk",
            "d_k = f(x_k + 1, y_k) + f(x_k + 1, y_k - 1) = 2f(x_k + 1, y_k - \\tfrac12) + \\tfrac12",
        ),
        worked(
            "d_d0",
            3 - 2 * r,
            f"d_0 = f(1, r) + f(1, r - 1) = 1 + 1 + (r - 1)^2 - r^2 = 3 - 2r = 3 - 2 \\cdot {r} = "
            f"{3 - 2 * r}",
        ),
        rule("d_update", "d < 0: d + 4x_k + 6;\\ d \\ge 0: d + 4(x_k - y_k) + 10"),
    )


def ellipse_derivation(rx: int, ry: int) -> tuple[Quantity, ...]:
    rx2, ry2 = rx * rx, ry * ry
    p1 = normalize(ry2 - rx2 * ry + Fraction(rx2, 4))
    return (
        worked(
            "d_f",
            (rx2, ry2),
            f"f(x, y) = r_y^2 x^2 + r_x^2 y^2 - r_x^2 r_y^2 = {ry2}x^2 + {rx2}y^2 - {rx2 * ry2}",
        ),
        rule(
            "d_regions",
            "\\frac{dy}{dx} = -\\frac{2r_y^2 x}{2r_x^2 y}: \\text{region 1 while } 2r_y^2 x < 2r_x^2 y "
            "\\text{ (slope above } -1)",
        ),
        worked(
            "d_p1",
            p1,
            f"p1_0 = f(1, r_y - \\tfrac12) = r_y^2 - r_x^2 r_y + \\tfrac{{r_x^2}}{{4}} = {ry2} - "
            f"{rx2} \\cdot {ry} + \\tfrac{{{rx2}}}{{4}} = {fmt_short(p1)}",
        ),
        rule("d_p1k", "p1_k = f(x_k + 1, y_k - \\tfrac12),\\ p2_k = f(x_k + \\tfrac12, y_k - 1)"),
    )


# --- comparison theory ------------------------------------------------------------------------


def theory_table(
    title: str, heads: tuple[str, str, str], rows: list[tuple[str, str, str]]
) -> Table:
    cols = tuple(heading(f"col{i}", f"\\text{{{h}}}") for i, h in enumerate(heads))
    data = tuple(rows)
    return Table(title=title, columns=cols, rows=lambda: data)


LINE_THEORY = [
    ("arithmetic", "floating point (x_inc, y_inc)", "integer additions only"),
    ("operations per step", "two additions and two roundings", "one comparison, one addition"),
    ("rounding", "round(x), round(y) every step", "none (decision parameter)"),
    ("error", "round-off accumulates along the line", "no accumulated error"),
    ("speed", "slower", "faster"),
    ("accuracy", "less accurate (jagged)", "accurate: nearest pixel"),
    ("hardware", "needs floating point", "suits integer hardware"),
]

CIRCLE_THEORY = [
    ("arithmetic", "floating point (notes)", "integer only"),
    ("decision", "p = x^2 + y^2 - r^2 at the point", "p at the midpoint (p0 = 1 - r)"),
    ("speed", "slower", "faster"),
    ("accuracy", "points can drift inside", "nearest pixel each column"),
    ("symmetry", "8-way", "8-way"),
    ("use", "small radius, teaching", "real-time, hardware"),
]

CURVE_THEORY = [
    ("control", "global: a point moves the whole curve", "local: only nearby spans"),
    ("degree", "n - 1 for n control points", "chosen independently (p)"),
    ("end points", "passes through first and last", "clamped: yes; unclamped: no"),
    ("basis", "Bernstein polynomials", "piecewise B-spline basis (knots)"),
    ("convex hull", "whole curve in the hull", "each span in its p + 1 points' hull"),
]
