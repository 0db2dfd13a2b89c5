"""Line drawing: the basic (direct) method, the simple DDA and Bresenham's algorithm.

Each algorithm is a generator of :class:`~scanconv.records.Step` records, valid in all eight
octants; :func:`line_solution` wraps one of them with the given and derived values an exam
answer writes above the table. Coordinates are ``(x, y)`` with y up (see
:mod:`scanconv.records`).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from fractions import Fraction

from .numeric import Number, fmt_exact, fmt_paren, fmt_short, fmt_value, normalize, round_half_up
from .records import Column, Move, Pixel, Quantity, Solution, Step, new_step

ALGORITHMS = ("bresenham", "dda", "basic")
"""The line algorithms, by their ``--algo`` names."""


def bresenham(x1: int, y1: int, x2: int, y2: int) -> Iterator[Step]:
    """Bresenham's line algorithm, textbook form, all octants.

    Yields one step per unit of the major axis; ``Step.pixel`` is ``(x_{k+1}, y_{k+1})`` and
    ``Step.extra`` is ``(p_{k+1},)``. The start pixel is not a step: it is plotted before the
    loop (see :func:`line_solution`, whose ``pixels()`` include it).

    Notes
    -----
    Hearn & Baker's form, generalised by symmetry. The major axis is x when |Δy| <= |Δx|
    (so 45 degree lines step in x), otherwise y. The walk starts at the end point with the
    smaller major coordinate; the end points are swapped if needed, as the notes say. With
    Δmajor and Δminor the absolute differences:

    * ``p0 = 2 Δminor - Δmajor``
    * ``p_k < 0``: keep the minor coordinate, ``p_{k+1} = p_k + 2 Δminor``
    * ``p_k >= 0``: step the minor coordinate toward the far end point,
      ``p_{k+1} = p_k + 2 Δminor - 2 Δmajor``

    A tie (``p_k = 0``, the ideal line exactly half-way between two pixels) steps the minor
    axis. Integers only.

    References: Bresenham, IBM Systems Journal 4(1), 1965; Hearn & Baker, *Computer Graphics*,
    section 3-5.

    Examples
    --------
    The notes' example (their printed table is wrong; see ``docs/errata.md``):

    >>> for s in bresenham(2, 2, 10, 6):
    ...     print(s.k, s.p, s.decision.value, s.pixel, s.extra[0])
    0 0 NE (3, 3) -8
    1 -8 E (4, 3) 0
    2 0 NE (5, 4) -8
    3 -8 E (6, 4) 0
    4 0 NE (7, 5) -8
    5 -8 E (8, 5) 0
    6 0 NE (9, 6) -8
    7 -8 E (10, 6) 0
    """
    # bresenham(2, 2, 10, 6) -> p: 0 -8 0 -8 0 -8 0 -8 ; pixels (3,3) (4,3) (5,4) ... (10,6)
    # bresenham(2, 2, 5, 10) -> steep: p: -2 4 -6 0 -10 -4 2 -8 ; moves N/NE
    x1, y1, x2, y2, steep, dmaj, dmin, s, stay, move = _orient(x1, y1, x2, y2)
    inc_keep, inc_step = 2 * dmin, 2 * dmin - 2 * dmaj
    x, y, p = x1, y1, 2 * dmin - dmaj
    # The hot path of every long table (benchmarks/bench.py measures it): one loop per major
    # axis so no step tests `steep`, and the record constructor bound to local names.
    make, cls = new_step, Step
    # Each record holds p_k, then p becomes p_{k+1} inside the tuple (the `:=`).
    if steep:
        for k in range(dmaj):
            y += 1
            if p < 0:
                yield make(cls, (k, p, stay, (x, y), (p := p + inc_keep,)))
            else:
                x += s
                yield make(cls, (k, p, move, (x, y), (p := p + inc_step,)))
        return
    for k in range(dmaj):
        x += 1
        if p < 0:
            yield make(cls, (k, p, stay, (x, y), (p := p + inc_keep,)))
        else:
            y += s
            yield make(cls, (k, p, move, (x, y), (p := p + inc_step,)))


def _orient(x1: int, y1: int, x2: int, y2: int) -> tuple:
    """Swap the end points so the major coordinate increases; name the two moves.

    Returns ``(x1, y1, x2, y2, steep, dmaj, dmin, s, stay, move)`` where ``s`` is the sign of
    the minor step, ``stay`` the move when p_k < 0 and ``move`` the move when p_k >= 0.

    >>> _orient(10, 6, 2, 2)[:4], _orient(0, 0, -3, 7)[-2:]
    ((2, 2, 10, 6), (<Move.N: 'N'>, <Move.NW: 'NW'>))
    """
    dx, dy = x2 - x1, y2 - y1
    steep = abs(dy) > abs(dx)
    if (dy if steep else dx) < 0:
        x1, y1, x2, y2, dx, dy = x2, y2, x1, y1, -dx, -dy
    if steep:
        s = 1 if dx >= 0 else -1
        return x1, y1, x2, y2, True, dy, abs(dx), s, Move.N, Move.from_delta(s, 1)
    s = 1 if dy >= 0 else -1
    return x1, y1, x2, y2, False, dx, abs(dy), s, Move.E, Move.from_delta(1, s)


def dda(x1: Number, y1: Number, x2: Number, y2: Number) -> Iterator[Step]:
    """The simple DDA, from P1 to P2 as given, with exact increments.

    ``Step.extra`` is ``(x_k, y_k, round_half_up(x_k), round_half_up(y_k))``; there are
    ``steps + 1`` rows, the first plotting P1 and the last P2.

    Notes
    -----
    ``steps = max(|Δx|, |Δy|)`` (rounded up to an integer if the end points are not integers),
    ``x_inc = Δx / steps``, ``y_inc = Δy / steps``; ``x_{k+1} = x_k + x_inc`` and
    ``y_{k+1} = y_k + y_inc`` as exact fractions, so no rounding error accumulates. Pixels are
    ``floor(v + 1/2)`` (round half up) of each coordinate. P1 = P2 gives one row.

    Examples
    --------
    >>> from scanconv.numeric import fmt
    >>> for s in dda(2, 2, 10, 6):
    ...     print(s.k, *(fmt(v, 3) for v in s.extra[:2]), s.pixel)
    0 2.000 2.000 (2, 2)
    1 3.000 2.500 (3, 3)
    2 4.000 3.000 (4, 3)
    3 5.000 3.500 (5, 4)
    4 6.000 4.000 (6, 4)
    5 7.000 4.500 (7, 5)
    6 8.000 5.000 (8, 5)
    7 9.000 5.500 (9, 6)
    8 10.000 6.000 (10, 6)
    """
    # dda(2, 2, 10, 6) -> y: 2 2.5 3 3.5 4 4.5 5 5.5 6 ; rounded: 2 3 3 4 4 5 5 6 6
    steps = dda_steps(x1, y1, x2, y2)
    xi, yi = dda_increments(x1, y1, x2, y2)
    for k in range(steps + 1):
        x = normalize(x1 + k * xi)  # exact: k * inc, not repeated addition
        y = normalize(y1 + k * yi)
        px, py = round_half_up(x), round_half_up(y)
        yield Step(k, None, None, (px, py), (x, y, px, py))


def _abs(v: Number) -> Fraction:
    """``|v|`` as a Fraction (keeps the type checker exact about ``int | Fraction``)."""
    return abs(Fraction(v))


def dda_steps(x1: Number, y1: Number, x2: Number, y2: Number) -> int:
    """``max(|Δx|, |Δy|)``, rounded up for non-integer end points.

    >>> dda_steps(2, 2, 5, 10)
    8
    """
    return math.ceil(max(_abs(x2 - x1), _abs(y2 - y1)))


def dda_increments(x1: Number, y1: Number, x2: Number, y2: Number) -> tuple[Number, Number]:
    """``(Δx / steps, Δy / steps)``; ``(0, 0)`` for a single point.

    >>> dda_increments(2, 2, 5, 10)
    (Fraction(3, 8), 1)
    """
    steps = dda_steps(x1, y1, x2, y2)
    if steps == 0:
        return 0, 0
    return normalize(Fraction(x2 - x1) / steps), normalize(Fraction(y2 - y1) / steps)


def basic(x1: Number, y1: Number, x2: Number, y2: Number) -> Iterator[Step]:
    """The direct method: step the major axis by 1, solve the line equation, round.

    ``Step.extra`` is ``(major, minor_exact, minor_rounded)``: ``(x, y, round_half_up(y))``
    when x is the major axis, ``(y, x, round_half_up(x))`` when y is.

    Notes
    -----
    The major coordinate runs over the pixel centres from ``round_half_up(P1)`` to
    ``round_half_up(P2)`` in the direction given; the minor coordinate is computed exactly from
    ``y = y1 + m (x - x1)`` (or ``x = x1 + (y - y1) / m`` on steep lines) and rounded half up.

    Examples
    --------
    The notes' example (2, 2) -> (8, 5):

    >>> from scanconv.numeric import fmt
    >>> for s in basic(2, 2, 8, 5):
    ...     print(s.extra[0], fmt(s.extra[1], 1), s.pixel)
    2 2.0 (2, 2)
    3 2.5 (3, 3)
    4 3.0 (4, 3)
    5 3.5 (5, 4)
    6 4.0 (6, 4)
    7 4.5 (7, 5)
    8 5.0 (8, 5)
    """
    # basic(2, 2, 8, 5) -> y: 2 2.5 3 3.5 4 4.5 5 ; rounded: 2 3 3 4 4 5 5
    dx, dy = x2 - x1, y2 - y1
    steep = _abs(dy) > _abs(dx)
    a1, b1, a2, db, da = (y1, x1, y2, dx, dy) if steep else (x1, y1, x2, dy, dx)
    start, end = round_half_up(a1), round_half_up(a2)
    direction = 1 if end >= start else -1
    slope = Fraction(db) / da if da else Fraction(0)
    for k, a in enumerate(range(start, end + direction, direction)):
        b = normalize(b1 + slope * (a - a1))
        rb = round_half_up(b)
        pixel = (rb, a) if steep else (a, rb)
        yield Step(k, None, None, pixel, (a, b, rb))


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
    steep = _abs(dy) > _abs(dx)
    axis = "y" if steep else "x"
    rel, tex_rel = (">", ">") if steep else ("<=", r"\le")
    return Quantity(
        "major_axis",
        axis,
        f"major axis: {axis}, since |Δy| = {fmt_short(_abs(dy))} {rel} |Δx| = {fmt_short(_abs(dx))}",
        f"\\text{{major axis: }} {axis}, \\quad |\\Delta y| = {fmt_short(_abs(dy))} {tex_rel} "
        f"|\\Delta x| = {fmt_short(_abs(dx))}",
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
    sx, sy, ex, ey, steep, dmaj, dmin, sign, stay, move = _orient(ix1, iy1, ix2, iy2)
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
    ceil_note = "" if max(_abs(dx), _abs(dy)) == steps_n else f", rounded up to {steps_n}"
    derived = [
        _diff("x", "x", x1, x2, "dx"),
        _diff("y", "y", y1, y2, "dy"),
        _slope(dx, dy),
        _major(dx, dy),
        Quantity(
            "steps",
            steps_n,
            f"steps = max(|Δx|, |Δy|) = max({fmt_short(_abs(dx))}, {fmt_short(_abs(dy))}) = {steps_n}"
            + ceil_note,
            f"\\text{{steps}} = \\max(|\\Delta x|, |\\Delta y|) = \\max({fmt_short(_abs(dx))}, "
            f"{fmt_short(_abs(dy))}) = {steps_n}",
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
    steep = _abs(dy) > _abs(dx)
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
