"""The worked answer of a line: given and derived values around a line algorithm's steps."""

import math
from collections.abc import Iterator
from fractions import Fraction
from typing import TYPE_CHECKING, NamedTuple

from ...algorithms.conventions import ROUNDING_TEXT, convention_note
from ...algorithms.lines import (
    ALGORITHMS,
    abs_value,
    basic,
    bresenham,
    bresenham_notes,
    bresenham_terms,
    increments,
    orient,
    orient_from_p1,
)
from ...core import lazy
from ...core.checks import InputError
from ...core.ideal import IdealLine
from ...core.numeric import (
    Number,
    fmt_exact,
    fmt_paren,
    fmt_short,
    fmt_value,
    normalize,
    round_half_up,
)
from ...core.records import (
    Pixel,
    Plot,
    Quantity,
    Solution,
    Step,
    Theory,
    Walk,
    heading,
    rule,
    worked,
)
from ..asked import LineQuestion, knob_values, line_question
from ..methods import Method, method

if TYPE_CHECKING:
    from ..theory import derivations as theory
else:  # theory: only --derive and --algorithm
    theory = lazy.module("scanconv.answers.theory.derivations")

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


def _tex_value(v: Number) -> str:
    """:func:`fmt_value` as TeX: ``1/3 \\approx 0.333``."""
    return fmt_value(v).replace("≈", "\\approx")


def _diff(name: str, a: Number, b: Number, key: str) -> Quantity:
    """``Δx = x₂ - x₁ = 10 - 2 = 8``."""
    v = normalize(b - a)
    return worked(
        key,
        v,
        f"\\Delta {name} = {name}_2 - {name}_1 = {fmt_short(b)} - {fmt_paren(a)} = {fmt_short(v)}",
    )


def _slope(dx: Number, dy: Number) -> Quantity:
    if dx == 0 and dy == 0:  # both end points the same pixel: a point, not a line
        return worked("m", None, r"m \text{ is undefined: } P_1 = P_2 \text{ (a single point)}")
    if dx == 0:
        return worked("m", None, r"m = \Delta y / \Delta x \text{ is undefined (vertical line)}")
    m = normalize(Fraction(dy) / dx)
    return worked(
        "m",
        m,
        f"m = \\frac{{\\Delta y}}{{\\Delta x}} = \\frac{{{fmt_short(dy)}}}{{{fmt_short(dx)}}} = "
        + _tex_value(m),
    )


def _major(dx: Number, dy: Number) -> Quantity:
    steep = abs_value(dy) > abs_value(dx)
    axis = "y" if steep else "x"
    rel = ">" if steep else r"\le"
    return worked(
        "major_axis",
        axis,
        f"\\text{{major axis: }} {axis}, \\text{{ since }} |\\Delta y| = {fmt_short(abs_value(dy))} "
        f"{rel} |\\Delta x| = {fmt_short(abs_value(dx))}",
    )


def _substituted(b1: Number, slope: Number, a: str, a1: Number) -> str:
    """``2 + 0.5 \\cdot (x - 2)``; a slope that is not a short decimal is written exactly, then
    approximately: ``2 + 1/3 \\cdot (x - 2) \\approx 2 + 0.333 \\cdot (x - 2)``."""
    exact, _, approx = fmt_value(slope).partition(" ≈ ")
    line = f"{fmt_short(b1)} + {{}} \\cdot ({a} - {fmt_paren(a1)})"
    return line.format(exact) + (f" \\approx {line.format(approx)}" if approx else "")


def _given(x1: Number, y1: Number, x2: Number, y2: Number) -> tuple[Quantity, ...]:
    p1, p2 = (normalize(x1), normalize(y1)), (normalize(x2), normalize(y2))
    return (
        worked("P1", p1, f"P_1 = ({fmt_short(x1)}, {fmt_short(y1)})"),
        worked("P2", p2, f"P_2 = ({fmt_short(x2)}, {fmt_short(y2)})"),
    )


def _bbox(*pts: tuple[Number, Number]) -> tuple[int, int, int, int]:
    xs = [round_half_up(p[0]) for p in pts]
    ys = [round_half_up(p[1]) for p in pts]
    return min(xs), min(ys), max(xs), max(ys)


def _title(name: str, x1: Number, y1: Number, x2: Number, y2: Number) -> str:
    return f"{name}: ({fmt_short(x1)}, {fmt_short(y1)}) to ({fmt_short(x2)}, {fmt_short(y2)})"


def line_solution(
    algo: str,
    x1: Number,
    y1: Number,
    x2: Number,
    y2: Number,
    *,
    rounding: str | None = None,
    tie: str | None = None,
    start: str | None = None,
    scale: str | None = None,
    ends: str | None = None,
    convention: str | None = None,
    layout: str = "textbook",
    derive: bool = False,
    pseudocode: bool = False,
    annotate: bool = False,
) -> Solution:
    """The worked solution of a line with one of :data:`ALGORITHMS`.

    ``rounding`` (dda, basic), ``tie`` (bresenham) and ``start`` (bresenham, dda: ``"swap"``
    to walk from the end with the smaller major coordinate, ``"given"`` from P1) and ``scale`` (midpoint: ``"integer"`` d = 2F(M) or ``"half"`` d = F(M)) and ``ends`` (wu:
    ``"full"`` or ``"coverage"``) are the conventions
    (:mod:`scanconv.algorithms.conventions`), ``convention`` a named preset; ``layout`` is
    ``"notes"`` (Bresenham: row k plots (x_k, y_k), row 0 the start pixel) or ``"textbook"``;
    ``derive`` adds the derivation, ``pseudocode`` the algorithm as a listing; ``annotate``
    adds the notes naming the conventions used and the course notes' errata (the API's answers
    have them; a pipeline stage that embeds a line leaves them out).

    Raises ``ValueError`` for an unknown algorithm, a convention that does not apply to it, or
    a non-integer end point with ``bresenham``.

    >>> sol = line_solution("bresenham", 2, 2, 10, 6)
    >>> for q in sol.derived[-3:]:
    ...     print(q.text)
    p₀ = 2Δy - Δx = 2·4 - 8 = 0
    2Δy = 2·4 = 8   (added when pₖ < 0)
    2Δy - 2Δx = 2·4 - 2·8 = -8   (added when pₖ ≥ 0)
    >>> list(sol.pixels())[:4]
    [(2, 2), (3, 3), (4, 3), (5, 4)]
    """
    if algo not in ALGORITHMS:
        raise InputError(
            f"unknown line algorithm {algo!r} (choose from {', '.join(ALGORITHMS)})", "algo"
        )
    if layout not in ("notes", "textbook"):
        raise InputError(f"unknown layout {layout!r} (choose from notes, textbook)", "layout")
    knobs = {"rounding": rounding, "tie": tie, "start": start, "scale": scale, "ends": ends}
    q = line_question(
        algo, x1, y1, x2, y2, given=knobs, convention=convention, layout=layout
    )._replace(annotate=annotate)
    rec = method("line", algo)
    # each piece asked for is loaded first: a method without it is refused before any work
    derivation = rec.load("derivation") if derive else None
    listing = rec.load("pseudocode") if pseudocode else None
    sol: Solution = rec.load("answer")(q)
    if derivation is not None or listing is not None:
        sol.theory = Theory(
            derivation(q) if derivation is not None else sol.theory.derivation,
            (*sol.theory.code, listing(q)) if listing is not None else sol.theory.code,
        )
    sol.question = q
    return sol


def annotated(sol: Solution, q: LineQuestion) -> Solution:
    """``sol`` with the notes naming the conventions and the course notes' erratum for this
    line (its record's ``errata``), when the question asks for them (``q.annotate``)."""
    if not q.annotate:
        return sol
    knobs = knob_values(q.knobs)
    extra = [note for note in (convention_note("line", q.convention, knobs),) if note]
    erratum = method("line", q.algo).load("errata")(q)
    if erratum:
        extra.append(erratum)
    sol.notes = (*sol.notes, *extra)
    sol.data = {**sol.data, "conventions": knobs, "layout": q.layout}
    return sol


# --- The pieces the line records name: each takes the question -----------------------------


def rows(q: LineQuestion) -> int:
    """The rows of a line's step table: one a unit step of the major axis, and the start.

    >>> rows(LineQuestion("dda", 0, 0, 10, 3))
    11
    """
    dx, dy = abs(Fraction(q.x2 - q.x1)), abs(Fraction(q.y2 - q.y1))
    return math.ceil(max(dx, dy)) + 1


def _swap_rule(maj: str, x1: Number, y1: Number, x2: Number, y2: Number) -> Quantity:
    """The end points swapped so that the major coordinate increases (said first, so that
    every line below uses the swapped names)."""
    return rule(
        "swap",
        f"\\text{{swap the end points so that }} {maj} \\text{{ increases: }} "
        f"(x_1, y_1) = ({fmt_short(x1)}, {fmt_short(y1)}), \\ "
        f"(x_2, y_2) = ({fmt_short(x2)}, {fmt_short(y2)})",
    )


def _integer_ends(x1: Number, y1: Number, x2: Number, y2: Number) -> tuple[int, int, int, int]:
    for v, n in ((x1, "x1"), (y1, "y1"), (x2, "x2"), (y2, "y2")):
        if normalize(v) != int(v):
            raise InputError(
                f"bresenham needs integer end points, got {n} = {fmt_exact(v)} "
                "(the dda and basic algorithms take fractional end points)",
                n,
            )
    return int(x1), int(y1), int(x2), int(y2)


class _Walk(NamedTuple):
    """Bresenham's walk as the working writes it: from (sx, sy) to (ex, ey)."""

    sx: int
    sy: int
    ex: int
    ey: int
    steep: bool
    dmaj: int
    dmin: int
    sign: int
    stay: str
    move: str
    swapped: bool
    backward: bool
    """Walked from P1 as given, the major coordinate decreasing (``start = "given"``)."""

    @property
    def names(self) -> tuple[str, str]:
        """The major and the minor coordinate."""
        return ("y", "x") if self.steep else ("x", "y")


def _walk(ix1: int, iy1: int, ix2: int, iy2: int, start: str) -> _Walk:
    sx, sy, ex, ey, steep, dmaj, dmin, sign, stay, move = orient(ix1, iy1, ix2, iy2)
    swapped = (sx, sy) != (ix1, iy1)
    backward = swapped and start == "given"  # walk from P1, the major coordinate decreasing
    if backward:
        sx, sy, ex, ey = ix1, iy1, ix2, iy2
        _, _, _, sign, stay, move = orient_from_p1(ix1, iy1, ix2, iy2)
        swapped = False
    return _Walk(sx, sy, ex, ey, steep, dmaj, dmin, sign, str(stay), str(move), swapped, backward)


def _bresenham_derived(w: _Walk, tie: str) -> tuple[Quantity, ...]:
    """Δx, Δy, the slope, p₀ and the two increments, after the swap if there is one."""
    dx, dy = w.ex - w.sx, w.ey - w.sy  # after the swap, as the working is written
    maj, mnr = w.names
    dmin, dmaj = w.dmin, w.dmaj
    dmin_t = f"|\\Delta {mnr}|" if w.sign < 0 else f"\\Delta {mnr}"
    dmaj_t = f"|\\Delta {maj}|" if w.backward else f"\\Delta {maj}"
    p0, inc_keep, inc_step, _ = bresenham_terms(dmaj, dmin)
    lt, ge = ("\\le", ">") if tie == "keep" else ("<", "\\ge")
    return (
        *((_swap_rule(maj, w.sx, w.sy, w.ex, w.ey),) if w.swapped else ()),
        _diff("x", w.sx, w.ex, "dx"),
        _diff("y", w.sy, w.ey, "dy"),
        _slope(dx, dy),
        _major(dx, dy),
        worked("p0", p0, f"p_0 = 2{dmin_t} - {dmaj_t} = 2 \\cdot {dmin} - {dmaj} = {p0}"),
        worked(
            "inc_keep",
            inc_keep,
            f"2{dmin_t} = 2 \\cdot {dmin} = {inc_keep} \\quad (\\text{{added when }} p_k {lt} 0)",
        ),
        worked(
            "inc_step",
            inc_step,
            f"2{dmin_t} - 2{dmaj_t} = 2 \\cdot {dmin} - 2 \\cdot {dmaj} = {inc_step} "
            f"\\quad (\\text{{added when }} p_k {ge} 0)",
        ),
    )


def _bresenham_line_notes(w: _Walk, tie: str, layout: str) -> tuple[str, ...]:
    """Where the walk starts, which way it goes and what p chooses (a tie included)."""
    maj, mnr = w.names
    if layout == "notes":
        notes = [
            f"Row $k$ plots $(x_k, y_k)$ and decides on $p_k$; row 0 is the start "
            f"$({w.sx}, {w.sy})$, the last row the end point (no decision)."
        ]
    else:
        notes = [f"Start at $({w.sx}, {w.sy})$, plotted before the first step."]
    if w.backward:
        notes.append(
            f"Walked from $P_1$ as given, ${maj}$ decreasing by 1 each step (no swap); the "
            "decisions are the swapped walk's, but a tie is now seen from the other end."
        )
    if tie == "keep":
        notes.append(
            f"$p_k \\le 0$ chooses {w.stay}, $p_k > 0$ chooses {w.move}; a tie ($p_k = 0$) "
            f"keeps ${mnr}$."
        )
    else:
        notes.append(
            f"$p_k < 0$ chooses {w.stay}, $p_k \\ge 0$ chooses {w.move}; a tie ($p_k = 0$) "
            f"steps ${mnr}$ too."
        )
    return tuple(notes)


def _bresenham_solution(
    x1: Number,
    y1: Number,
    x2: Number,
    y2: Number,
    tie: str = "step",
    layout: str = "textbook",
    start: str = "swap",
) -> Solution:
    ix1, iy1, ix2, iy2 = _integer_ends(x1, y1, x2, y2)
    w = _walk(ix1, iy1, ix2, iy2, start)

    def steps() -> Iterator[Step]:
        if layout == "notes":
            return bresenham_notes(ix1, iy1, ix2, iy2, tie, start)
        return bresenham(ix1, iy1, ix2, iy2, tie, start)

    def pixels() -> Iterator[Pixel]:
        yield (w.sx, w.sy)
        for s in bresenham(ix1, iy1, ix2, iy2, tie, start):
            yield s.pixel

    after = layout != "notes"  # the textbooks' rows: row k plots the pixel its decision reaches
    pixel_head = "(x_{k+1}, y_{k+1})" if after else "(x_k, y_k)"
    return Solution(
        primitive="line",
        algorithm="bresenham",
        title=_title("Bresenham's line algorithm", ix1, iy1, ix2, iy2),
        given=_given(ix1, iy1, ix2, iy2),
        derived=_bresenham_derived(w, tie),
        notes=_bresenham_line_notes(w, tie, layout),
        walk=Walk(
            columns=(
                heading("k", "k", role="label"),
                heading("p", "p_k"),
                heading("decision", r"\text{decision}"),
                heading("pixel", pixel_head),
                heading("p_next", "p_{k+1}"),
            ),
            extra_keys=("p_next",),
            steps=steps,
            next_pixel=after,
        ),
        plot=Plot(
            pixels=pixels,
            bbox=_bbox((ix1, iy1), (ix2, iy2)),
            ideal=(IdealLine(ix1, iy1, ix2, iy2),),
        ),
    )


def _steps_rule(rec: Method, dx: Number, dy: Number, steps_n: int) -> Quantity:
    """The number of steps as the method's record writes it (its ``steps`` fact, a TeX
    template of ``{adx}``, ``{ady}``, ``{longest}``, ``{n}`` and ``{steps}``), else the simple
    DDA's ``max(|Δx|, |Δy|)``, rounded up for fractional end points."""
    adx, ady = abs_value(dx), abs_value(dy)
    longest = max(adx, ady)
    template = rec.fact("steps")
    if template:
        text = template.format(
            adx=fmt_short(adx),
            ady=fmt_short(ady),
            longest=fmt_short(longest),
            n=max(steps_n.bit_length() - 1, 0),
            steps=steps_n,
        )
        return worked("steps", steps_n, text)
    ceil_note = "" if longest == steps_n else f"{fmt_short(longest)},\\ \\text{{rounded up to }} "
    return worked(
        "steps",
        steps_n,
        f"\\text{{steps}} = \\max(|\\Delta x|, |\\Delta y|) = \\max({fmt_short(adx)}, "
        f"{fmt_short(ady)}) = {ceil_note}{steps_n}",
    )


def _dda_derived(
    rec: Method, x1: Number, y1: Number, x2: Number, y2: Number, swapped: bool, steps_n: int
) -> tuple[Quantity, ...]:
    """Δx, Δy, the slope, the number of steps and the increments (from the walk's start)."""
    dx, dy = normalize(x2 - x1), normalize(y2 - y1)
    xi, yi = increments(x1, y1, x2, y2, steps_n)
    incs = (
        worked(
            f"{name}_inc",
            inc,
            f"{name}_{{inc}} = \\frac{{\\Delta {name}}}{{\\text{{steps}}}} = "
            f"\\frac{{{fmt_short(d)}}}{{{steps_n}}} = " + _tex_value(inc),
        )
        for name, d, inc in (("x", dx, xi), ("y", dy, yi))
    )
    maj = "y" if abs_value(dy) > abs_value(dx) else "x"
    return (
        *((_swap_rule(maj, x1, y1, x2, y2),) if swapped else ()),
        _diff("x", x1, x2, "dx"),
        _diff("y", y1, y2, "dy"),
        _slope(dx, dy),
        _major(dx, dy),
        _steps_rule(rec, dx, dy, steps_n),
        *(incs if steps_n else ()),
    )


_DDA_COLUMNS = (
    heading("k", "k", role="label"),
    heading("x", "x_k", 3),
    heading("y", "y_k", 3),
    heading("round_x", r"\operatorname{round}(x_k)"),
    heading("round_y", r"\operatorname{round}(y_k)"),
    heading("pixel", r"\text{pixel } (x, y)"),
)


def _dda_solution(q: LineQuestion) -> Solution:
    """A DDA-family line: its record's generator steps both coordinates by Δ/steps from the
    walk's start, ``steps`` being the record's row estimate less the start row (exact for
    this family: the simple DDA's ``max(|Δx|, |Δy|)``, the symmetric DDA's ``2^n``)."""
    rec = method("line", q.algo)
    generator = rec.load("generator")
    rounding, start = q.knobs.rounding or "half-up", q.knobs.start or "given"
    x1, y1, x2, y2 = asked = q.points
    dx, dy = normalize(x2 - x1), normalize(y2 - y1)
    steep = abs_value(dy) > abs_value(dx)
    swapped = start == "swap" and (dy if steep else dx) < 0
    if swapped:  # walk from the end with the smaller major coordinate
        x1, y1, x2, y2 = x2, y2, x1, y1
    steps_n = rec.load("rows")(q) - 1
    notes = (
        "$x_{k+1} = x_k + x_{inc}$ and $y_{k+1} = y_k + y_{inc}$, computed exactly;"
        + (
            r" pixels are round half up, $\lfloor v + 1/2 \rfloor$."
            if rounding == "half-up"
            else f" pixels are {ROUNDING_TEXT[rounding]}."
        ),
    )
    title = rec.fact("heading") or rec.title[:1].upper() + rec.title[1:]
    return Solution(
        primitive="line",
        algorithm=q.algo,
        title=_title(title, *asked),
        given=_given(*asked),
        derived=_dda_derived(rec, x1, y1, x2, y2, swapped, steps_n),
        notes=notes,
        walk=Walk(
            columns=_DDA_COLUMNS,
            extra_keys=("x", "y", "round_x", "round_y"),
            steps=lambda: generator(x1, y1, x2, y2, rounding),
        ),
        plot=Plot(
            pixels=lambda: _once(s.pixel for s in generator(x1, y1, x2, y2, rounding)),
            bbox=_bbox((x1, y1), (x2, y2)),
            ideal=(IdealLine(x1, y1, x2, y2),),
        ),
    )


def _basic_solution(
    x1: Number, y1: Number, x2: Number, y2: Number, rounding: str = "half-up"
) -> Solution:
    dx, dy = normalize(x2 - x1), normalize(y2 - y1)
    steep = abs_value(dy) > abs_value(dx)
    derived = [
        _diff("x", x1, x2, "dx"),
        _diff("y", y1, y2, "dy"),
        _slope(dx, dy),
        _major(dx, dy),
    ]
    if steep:
        inv = normalize(Fraction(dx) / dy)
        derived.append(
            worked(
                "equation",
                inv,
                r"x = x_1 + \frac{\Delta x}{\Delta y}(y - y_1) = " + _substituted(x1, inv, "y", y1),
            )
        )
        maj, mnr = "y", "x"
    else:
        m = normalize(Fraction(dy) / dx) if dx else 0
        derived.append(
            worked("equation", m, "y = y_1 + m(x - x_1) = " + _substituted(y1, m, "x", x1))
        )
        maj, mnr = "x", "y"
    return Solution(
        primitive="line",
        algorithm="basic",
        title=_title("Line by the basic (direct) method", x1, y1, x2, y2),
        given=_given(x1, y1, x2, y2),
        derived=tuple(derived),
        notes=(f"Each {mnr} is computed exactly and {ROUNDING_TEXT[rounding]}.",),
        walk=Walk(
            columns=(
                heading(maj, maj),
                heading(mnr, f"{mnr} \\text{{ (calculated)}}", 3),
                heading(f"round_{mnr}", f"{mnr} \\text{{ (rounded)}}"),
                heading("pixel", r"\text{pixel } (x, y)"),
            ),
            extra_keys=(maj, mnr, f"round_{mnr}"),
            steps=lambda: basic(x1, y1, x2, y2, rounding),
        ),
        plot=Plot(
            pixels=lambda: (s.pixel for s in basic(x1, y1, x2, y2, rounding)),
            bbox=_bbox((x1, y1), (x2, y2)),
            ideal=(IdealLine(x1, y1, x2, y2),),
        ),
    )


# --- The answer builders the method records name (one signature for every line method) -----


def bresenham_answer(q: LineQuestion) -> Solution:
    """Bresenham's line (record ``line/bresenham``) with its conventions."""
    return annotated(
        _bresenham_solution(*q.points, str(q.knobs.tie), q.layout, str(q.knobs.start)), q
    )


def dda_answer(q: LineQuestion) -> Solution:
    """A DDA-family line (record ``line/dda``, and any line record naming this answer with
    its own generator, row estimate and ``steps`` fact); it has one layout."""
    return annotated(_dda_solution(q), q)


def basic_answer(q: LineQuestion) -> Solution:
    """The basic line algorithm (record ``line/basic``); it has one layout."""
    return annotated(_basic_solution(*q.points, str(q.knobs.rounding)), q)
