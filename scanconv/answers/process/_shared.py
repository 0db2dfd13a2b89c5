"""Shared pieces of the scan-conversion process answers (transform, viewport, clip,
pipeline): exact values, points, matrices and rectangles as text, the input checks of points
and rectangles, and the small figures of shapes drawn under an answer.

Values with square roots are written in ASCII (``sqrt(2)/2``) so that table cells stay ASCII
in every format; TeX gets ``\\frac{\\sqrt{2}}{2}``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, NamedTuple

from ...algorithms.clipping import Point as NumPoint
from ...algorithms.clipping import Rect
from ...algorithms.radical import Radical, Scalar, approx, round_half_up_exact, simplify
from ...algorithms.transform import Point, outline
from ...core.checks import InputError
from ...core.numeric import Number, fmt, fmt_short, normalize, round_half_up
from ...core.records import PixelFigure, Quantity, Table
from ...core.working import ascii_text

MAX_POINTS = 100
"""Most points a transformation, or a window-to-viewport mapping, is applied to."""


def _terms(v: Radical, tex: bool) -> list[tuple[bool, str]]:
    out = []
    for root, c in v.terms:
        if not c:
            continue
        n, d = abs(c.numerator), c.denominator
        if root == 1:
            body = (f"\\frac{{{n}}}{{{d}}}" if tex else f"{n}/{d}") if d != 1 else str(n)
        else:
            rt = f"\\sqrt{{{root}}}" if tex else f"sqrt({root})"
            num = rt if n == 1 else (f"{n}{rt}" if tex else f"{n}*{rt}")
            body = num if d == 1 else (f"\\frac{{{num}}}{{{d}}}" if tex else f"{num}/{d}")
        out.append((c < 0, body))
    return out


def text(v: Scalar, tex: bool = False) -> str:
    """An exact value: ``3``, ``1.5``, ``1/3``, ``sqrt(2)/2``, ``1/2 + sqrt(3)/2`` (ASCII), or
    the same in TeX.

    >>> from fractions import Fraction
    >>> text(Radical(Fraction(1, 2), 0, Fraction(-1, 2))), text(Radical(0, Fraction(3, 2)), True)
    ('1/2 - sqrt(3)/2', '\\\\frac{3\\\\sqrt{2}}{2}')
    """
    v = simplify(v)
    if not isinstance(v, Radical):
        return fmt_short(v)
    terms = _terms(v, tex)
    first_neg, first = terms[0]
    s = ("-" if first_neg else "") + first
    for neg, body in terms[1:]:
        s += f" {'-' if neg else '+'} {body}"
    return s


def approx_text(v: Scalar) -> str:
    """``≈ 0.707`` for an irrational value (3 decimals), ``""`` for a rational one."""
    v = simplify(v)
    return f" ≈ {fmt(approx(v))}" if isinstance(v, Radical) else ""


def json_scalar(v: Scalar) -> Any:
    """A rational as a number, an irrational value as its exact text."""
    v = simplify(v)
    return text(v) if isinstance(v, Radical) else v


def point_text(p: Point, tex: bool = False) -> str:
    """``(x, y)`` exactly."""
    return f"({text(p[0], tex)}, {text(p[1], tex)})"


def matrix_text(m: Sequence[Sequence[Scalar]]) -> str:
    """``[[1, 0, 3], [0, 1, -1], [0, 0, 1]]``."""
    return "[" + ", ".join("[" + ", ".join(text(v) for v in row) + "]" for row in m) + "]"


def matrix_tex(m: Sequence[Sequence[Scalar]]) -> str:
    """A ``bmatrix``."""
    rows = " \\\\ ".join(" & ".join(text(v, True) for v in row) for row in m)
    return f"\\begin{{bmatrix}} {rows} \\end{{bmatrix}}"


def matrix_json(m: Sequence[Sequence[Scalar]]) -> list[list[Any]]:
    return [[json_scalar(v) for v in row] for row in m]


def check_points(coords: Sequence[Number], param: str = "points") -> tuple[NumPoint, ...]:
    """``x y`` pairs as points: at least one, at most :data:`MAX_POINTS`."""
    if len(coords) % 2:
        raise InputError(
            f"points are x y pairs: got {len(coords)} coordinates, an odd number", param
        )
    n = len(coords) // 2
    if n == 0:
        raise InputError("at least one point (x y) is needed", param)
    if n > MAX_POINTS:
        raise InputError(f"at most {MAX_POINTS} points, got {n}", param)
    return tuple((coords[2 * i], coords[2 * i + 1]) for i in range(n))


def matrix_rows(name: str, what: str, m: Sequence[Sequence[Scalar]]) -> list[tuple[str, ...]]:
    """A matrix's rows as table rows (three for 2D, four for 3D), named on its first row."""
    return [
        (name if i == 0 else "", ascii_text(what) if i == 0 else "", *(text(v) for v in m[i]))
        for i in range(len(m))
    ]


def grid_bbox(*groups: Sequence[tuple[int, int]]) -> tuple[int, int, int, int]:
    xs = [p[0] for g in groups for p in g]
    ys = [p[1] for g in groups for p in g]
    return min(xs), min(ys), max(xs), max(ys)


FIGURE_SIDE = 40
"""The before/after and clipping figures are drawn only if they are at most this many cells
wide and high (a larger one would be mostly empty cells); the tables are complete anyway."""


def fits(bbox: tuple[int, int, int, int]) -> bool:
    """True if a figure of ``bbox`` (plus its one-cell margin) is small enough to draw."""
    return max(bbox[2] - bbox[0], bbox[3] - bbox[1]) + 3 <= FIGURE_SIDE


def rounded(points: Sequence[Point]) -> list[tuple[int, int]]:
    return [(round_half_up_exact(x), round_half_up_exact(y)) for x, y in points]


def shapes_figure(
    before: Sequence[Point], after: Sequence[Point], legend: str, title: str
) -> tuple[PixelFigure, ...]:
    """The outline of ``after`` as ``#`` over the outline of ``before`` as ``o`` (none if it
    does not :func:`fit <fits>`)."""
    b, a = rounded(before), rounded(after)
    box = grid_bbox(b, a)
    if not fits(box):
        return ()
    return (PixelFigure(tuple(outline(a)), tuple(outline(b)), box, legend, title),)


class Clipped(NamedTuple):
    """A line clipped against a window, as one method worked it: what an answer around it
    (the method's own, the rectangle's, the pipeline's clip stage) reads, typed."""

    working: list[Quantity]
    """The working, without its last line (the clipped segment, or the rejection)."""
    tables: list[Table]
    segment: tuple[NumPoint, NumPoint] | None
    """The clipped segment; ``None``: rejected."""


def check_rect(rect: Sequence[Number], what: str, param: str) -> Rect:
    """``(xmin, ymin, xmax, ymax)`` with ``xmin < xmax`` and ``ymin < ymax``, or InputError.

    >>> check_rect((4, 4, 10, 8), "window", "window")
    (4, 4, 10, 8)
    >>> check_rect((4, 4, 4, 8), "window", "window")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: window needs xmin < xmax, got xmin = 4, xmax = 4
    """
    if len(rect) != 4:
        raise InputError(f"{what} needs 4 numbers (xmin ymin xmax ymax), got {len(rect)}", param)
    x0, y0, x1, y1 = (normalize(v) for v in rect)
    if x0 >= x1:
        raise InputError(
            f"{what} needs xmin < xmax, got xmin = {fmt_short(x0)}, xmax = {fmt_short(x1)}", param
        )
    if y0 >= y1:
        raise InputError(
            f"{what} needs ymin < ymax, got ymin = {fmt_short(y0)}, ymax = {fmt_short(y1)}", param
        )
    return x0, y0, x1, y1


def factor(v: Number) -> str:
    """A number as a factor in substituted working: bracketed if negative or a fraction.

    >>> from fractions import Fraction
    >>> factor(2), factor(Fraction(10, 3)), factor(Fraction(-3, 2))
    ('2', '(10/3)', '(-1.5)')
    """
    s = fmt_short(v)
    return f"({s})" if s.startswith("-") or "/" in s else s


def pt(p: NumPoint) -> str:
    """``(7.8, 8)``, exactly (fractions that do not terminate stay fractions: ``335/7``)."""
    return f"({fmt_short(p[0])}, {fmt_short(p[1])})"


def pt_approx(p: NumPoint) -> str:
    """``(335/7, 80) ≈ (47.857, 80)`` where a coordinate does not terminate."""
    exact = pt(p)
    if "/" not in exact:
        return exact
    return f"{exact} ≈ ({fmt(p[0]) if '/' in fmt_short(p[0]) else fmt_short(p[0])}, " + (
        f"{fmt(p[1]) if '/' in fmt_short(p[1]) else fmt_short(p[1])})"
    )


def rect_text(r: Rect) -> str:
    return f"({fmt_short(r[0])}, {fmt_short(r[1])})-({fmt_short(r[2])}, {fmt_short(r[3])})"


def rect_quantity(key: str, r: Rect, sub: str = "") -> Quantity:
    """``window: xmin = 4, ymin = 4, xmax = 10, ymax = 8`` (``sub`` = ``w``: ``xwmin``, ...)."""
    names = [f"{a}{sub}{b}" for b in ("min", "max") for a in ("x", "y")]
    texs = [f"{a}_{{{sub}\\{b}}}" for b in ("min", "max") for a in ("x", "y")]
    return Quantity(
        key,
        list(r),
        f"{key}: " + ", ".join(f"{n} = {fmt_short(v)}" for n, v in zip(names, r, strict=True)),
        f"\\text{{{key}: }} "
        + ", ".join(f"{n} = {fmt_short(v)}" for n, v in zip(texs, r, strict=True)),
    )


def point_quantity(key: str, p: NumPoint) -> Quantity:
    return Quantity(key, list(p), f"{key} = {pt(p)}", f"{key[0]}_{{{key[1:]}}} = {pt(p)}")


def clip_figure(
    kept: Sequence[NumPoint], window: Rect, others: Sequence[NumPoint], what: str
) -> tuple[PixelFigure, ...]:
    """The window's border as ``o`` and a clipped shape's outline as ``#`` (rounded half up):
    :func:`window_figure` of the rectangle's corners."""
    x0, y0, x1, y1 = window
    return window_figure(kept, [(x0, y0), (x1, y0), (x1, y1), (x0, y1)], others, what)


def window_figure(
    kept: Sequence[NumPoint], window: Sequence[NumPoint], others: Sequence[NumPoint], what: str
) -> tuple[PixelFigure, ...]:
    """A polygon window's border as ``o`` and a clipped shape's outline as ``#`` (rounded half
    up), for a window of any shape (a rectangle's: :func:`clip_figure`)."""
    win = [(round_half_up(x), round_half_up(y)) for x, y in window]
    shape = [(round_half_up(x), round_half_up(y)) for x, y in kept]
    box = grid_bbox(win, shape, [(round_half_up(x), round_half_up(y)) for x, y in others])
    legend = f"# = {what}, o = window edge, @ = both"
    title = f"The window (o) and the {what} (#), rounded half up:"
    if not kept:
        title = f"The window (o); the {what} is empty:"
    if not fits(box):
        return ()
    return (PixelFigure(tuple(outline(shape)), tuple(outline(win)), box, legend, title),)
