"""The worked answer of a circle: the method's octant table, the 8-way symmetry table and
the pixels."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ...algorithms.circles import (
    ALIASES,
    FLOAT_METHODS,
    METHODS,
    SDDA_MAX_RADIUS,
    bresenham,
    general,
    images,
    midpoint,
    symmetric_pixels,
)
from ...algorithms.conventions import ROUNDING_TEXT, convention_note, resolve, rounder
from ...core import lazy
from ...core.checks import InputError, check_integer
from ...core.ideal import IdealCircle
from ...core.numeric import (
    Number,
    fmt_value,
    normalize,
)
from ...core.records import (
    Move,
    Pixel,
    Plot,
    Quantity,
    Solution,
    Step,
    Table,
    Theory,
    Walk,
    heading,
    rule,
    worked,
)
from .. import methods
from ..asked import CircleKnobs, CircleQuestion, knob_values
from . import circle_float as float_parts
from .circle_float import Parts, pixels_of

if TYPE_CHECKING:
    from ..theory import derivations as theory
else:  # only --derive and --algorithm need it
    theory = lazy.module("scanconv.answers.theory.derivations")

SYMMETRY_HEADS = (
    "(x_c+x, y_c+y)",
    "(x_c-x, y_c+y)",
    "(x_c+x, y_c-y)",
    "(x_c-x, y_c-y)",
    "(x_c+y, y_c+x)",
    "(x_c-y, y_c+x)",
    "(x_c+y, y_c-x)",
    "(x_c-y, y_c-x)",
)
"""Headings (TeX) of the symmetry tables, in the notes' order (the ellipse uses the first 4)."""


def symmetry_table(
    points: Callable[[], Iterable[Pixel]],
    mirror: Callable[[int, int, int, int], tuple[Pixel, ...]],
    xc: int,
    yc: int,
) -> Table:
    """The n-way symmetry table: one row per computed point (a repeated point once), its
    images in the columns. ``mirror`` is :func:`images` (8-way) or the ellipse's (4-way)."""
    n = len(mirror(0, 0, 0, 0))

    def rows() -> Iterator[tuple[Pixel, ...]]:
        last = None
        for p in points():
            if p != last:
                yield (p, *mirror(p[0], p[1], xc, yc))
            last = p

    return Table(
        title=f"{n}-way symmetry about the centre ({xc}, {yc})",
        # the images follow from the octant's points (the step table asks them): working
        columns=(
            heading("point", "(x, y)", role="working"),
            *(
                heading(f"point_{i}", tex, role="working")
                for i, tex in enumerate(SYMMETRY_HEADS[:n], 1)
            ),
        ),
        rows=rows,
    )


def _circle_given(r: int, xc: int, yc: int) -> tuple[Quantity, ...]:
    return (
        worked("r", r, f"r = {r}"),
        worked("center", (xc, yc), f"\\text{{centre }} (x_c, y_c) = ({xc}, {yc})"),
    )


def _start(r: int) -> Quantity:
    return worked("start", (0, r), f"\\text{{start }} (x_0, y_0) = (0, r) = (0, {r})")


def _circle_method(method: str, rounding: str | None, layout: str) -> tuple[str, str | None]:
    """The method's name (an alias resolved) and its rounding rule, checked."""
    method = ALIASES.get(method, method)
    if method not in METHODS:
        names = ", ".join((*METHODS, *ALIASES))
        raise InputError(f"unknown circle method {method!r} (choose from {names})", "method")
    if rounding is not None and method not in FLOAT_METHODS:
        rounder(rounding)
        if rounding != "half-up":
            raise InputError(
                f"a rounding rule applies only to {', '.join(FLOAT_METHODS)}; "
                f"{method} uses integers only",
                "rounding",
            )
        rounding = None
    if layout not in ("notes", "textbook"):
        raise InputError(f"unknown layout {layout!r} (choose from notes, textbook)", "layout")
    return method, rounding


def _circle_numbers(r: Number, xc: Number, yc: Number) -> tuple[int, int, int]:
    """The radius and the centre as integers, checked."""
    ir = check_integer(r, "radius", negative=False, param="r")
    ixc, iyc = check_integer(xc, "xc", param="xc"), check_integer(yc, "yc", param="yc")
    return ir, ixc, iyc


def sdda_radius(r: int) -> int:
    """The symmetric DDA's radius, bounded (its exact fractions grow by 2n bits a step)."""
    if r > SDDA_MAX_RADIUS:
        raise InputError(
            f"symmetric-dda computes exact fractions that grow by about 2n bits per step; "
            f"the radius must be at most {SDDA_MAX_RADIUS} (got {r})",
            "r",
        )
    return r


# --- The pieces the circle records name: each takes the question ---------------------------


def midpoint_parts(q: CircleQuestion) -> Parts:
    """The midpoint circle's octant table and working."""
    return _midpoint_parts(q.r, knob_values(q.knobs), q.layout)


def general_parts(q: CircleQuestion) -> Parts:
    """The notes' general method's octant table and working."""
    return _general_parts(q.r, knob_values(q.knobs))


def bresenham_parts(q: CircleQuestion) -> Parts:
    """Bresenham's circle (d0 = 3 - 2r): its octant table and working."""
    return _bresenham_parts(q.r, str(q.knobs.tie), str(q.knobs.xstep))


def polynomial_parts(q: CircleQuestion) -> Parts:
    """The polynomial method's octant table and working."""
    return float_parts.polynomial_parts(q.r, str(q.knobs.rounding))


def trig_parts(q: CircleQuestion) -> Parts:
    """The trigonometric method's octant table and working."""
    return float_parts.trig_parts(q.r, str(q.knobs.rounding))


def symmetric_dda_parts(q: CircleQuestion) -> Parts:
    """The symmetric DDA's octant table and working (its radius bounded)."""
    return float_parts.sdda_parts(sdda_radius(q.r), str(q.knobs.rounding))


def circle_solution(
    method: str,
    r: Number,
    xc: Number = 0,
    yc: Number = 0,
    rounding: str | None = None,
    *,
    tie: str | None = None,
    p0: str | None = None,
    loop: str | None = None,
    update: str | None = None,
    xstep: str | None = None,
    convention: str | None = None,
    layout: str = "textbook",
    derive: bool = False,
    pseudocode: bool = False,
    annotate: bool = False,
) -> Solution:
    """The worked solution of a circle with one of :data:`METHODS` (or an alias).

    ``rounding``, ``tie``, ``p0``, ``loop`` and ``update`` are the conventions
    (:mod:`scanconv.algorithms.conventions`; a knob that does not apply to the method is an
    error), ``convention`` a named preset. ``layout="notes"`` prints the midpoint circle in the
    notes' rows (k, x, y, p, decision, point: row 0 the start point); ``derive`` adds the
    derivation, ``pseudocode`` the algorithm as a listing, ``annotate`` the notes naming the
    conventions and the course notes' errata.

    Raises ``ValueError`` for an unknown method or rounding rule, a negative or non-integer
    radius or centre, a rounding rule other than half-up with an integer method, and a radius
    above :data:`SDDA_MAX_RADIUS` with the symmetric DDA.

    >>> sol = circle_solution("midpoint", 5, 10, 10)
    >>> print(sol.derived[1].text)
    p₀ = 1 - r = 1 - 5 = -4
    >>> [s.pixel for s in sol.steps()]
    [(1, 5), (2, 5), (3, 4), (4, 3)]
    >>> list(sol.pixels())[:6]
    [(10, 15), (10, 5), (15, 10), (5, 10), (11, 15), (9, 15)]
    >>> sum(1 for _ in sol.pixels()), sol.bbox
    (28, (5, 5, 15, 15))
    """

    method, rounding = _circle_method(method, rounding, layout)
    knobs = resolve(
        "circle",
        method,
        convention,
        {
            "rounding": rounding,
            "tie": tie,
            "p0": p0,
            "loop": loop,
            "update": update,
            "xstep": xstep,
        },
    )
    rounding = knobs.get("rounding", "half-up")
    ir, ixc, iyc = _circle_numbers(r, xc, yc)
    q = CircleQuestion(method, ir, ixc, iyc, CircleKnobs(**knobs), layout, convention)
    rec = methods.method("circle", method)
    derivation = rec.load("derivation") if derive else None
    listing = rec.load("pseudocode") if pseudocode else None
    title, derived, columns, extra_keys, steps, points, notes, after = rec.load("answer")(q)
    notes = _circle_notes(method, notes, rounding)
    added = Theory(
        (theory.DERIVATION, *derivation(q)) if derivation is not None else (),
        (listing(q),) if listing is not None else (),
    )
    data: dict[str, Any] = {"rounding": rounding} if method in FLOAT_METHODS else {}
    if annotate:
        notes = (*notes, convention_note("circle", convention, knobs))
        erratum = rec.load("errata")(q)
        if erratum:
            notes = (*notes, erratum)
        data = {**data, "conventions": knobs, "layout": layout}
    pixels = _once_each if knobs.get("loop") == "inclusive" else _as_is
    sol = Solution(
        primitive="circle",
        algorithm=method,
        title=f"{title}: r = {ir}, centre ({ixc}, {iyc})",
        given=_circle_given(ir, ixc, iyc),
        derived=derived,
        notes=notes,
        walk=Walk(
            columns=columns,
            extra_keys=extra_keys,
            steps=steps,
            tables=(symmetry_table(points, images, ixc, iyc),),
            symmetry=8,
            center=(ixc, iyc),
            next_pixel=after,  # the method's Parts.next_pixel
        ),
        plot=Plot(
            pixels=lambda: pixels(symmetric_pixels(points(), ixc, iyc)),
            bbox=(ixc - ir, iyc - ir, ixc + ir, iyc + ir),
            marks=((ixc, iyc),),
            ideal=(IdealCircle(ixc, iyc, ir),),
        ),
        theory=added,
        data=data,
    )
    sol.question = q
    return sol


def _circle_notes(method: str, notes: tuple[str, ...], rounding: str) -> tuple[str, ...]:
    """The method's notes, its rounding rule (a float method) and the 8-way symmetry's."""
    if method in FLOAT_METHODS:
        notes = (*notes, _rounding_note(rounding))
    return (
        *notes,
        "Each octant point is mirrored into 8 pixels about the centre; a pixel is listed "
        "once, the first time it is plotted.",
    )


def _as_is(pixels: Iterator[Pixel]) -> Iterator[Pixel]:
    return pixels


def _once_each(pixels: Iterator[Pixel]) -> Iterator[Pixel]:
    """Each pixel once: a loop run while x <= y can step past the diagonal and repeat the
    images of an earlier point, which the previous-point check alone does not catch."""
    seen: set[Pixel] = set()
    for p in pixels:
        if p not in seen:
            seen.add(p)
            yield p


def _rounding_note(rounding: str) -> str:
    return f"Coordinates are {ROUNDING_TEXT[rounding]}."


def _midpoint_derived(r: int, knobs: dict[str, str]) -> tuple[Number, tuple[Quantity, ...]]:
    """p₀ and the working: the start, p₀, what each sign of p chooses and the loop."""
    tie, loop = knobs["tie"], knobs["loop"]
    lt, ge = (r"\le", ">") if tie == "keep" else ("<", r"\ge")
    if knobs["p0"] == "5/4-r":
        p0: Number = Fraction(5, 4) - r
        p0_q = worked("p0", p0, f"p_0 = \\tfrac54 - r = \\tfrac54 - {r} = {fmt_value(p0)}")
    else:
        p0 = 1 - r
        p0_q = worked("p0", p0, f"p_0 = 1 - r = 1 - {r} = {p0}")
    if knobs["update"] == "old":
        inc_e, inc_se = "2x_k + 3", "2x_k - 2y_k + 5"
    else:
        inc_e, inc_se = "2x_{k+1} + 1", "2x_{k+1} + 1 - 2y_{k+1}"
    return p0, (
        _start(r),
        p0_q,
        rule(
            "if_negative",
            f"p_k {lt} 0: \\text{{next point }} (x_k + 1, y_k)\\ (\\text{{E}}),\\ "
            f"p_{{k+1}} = p_k + {inc_e}",
        ),
        rule(
            "otherwise",
            f"p_k {ge} 0: \\text{{next point }} (x_k + 1, y_k - 1)\\ (\\text{{SE}}),\\ "
            f"p_{{k+1}} = p_k + {inc_se}",
        ),
        rule(
            "loop", r"\text{continue while } x " + (r"\le" if loop == "inclusive" else "<") + " y"
        ),
    )


def _midpoint_notes(
    r: int, knobs: dict[str, str], layout: str, last: Pixel | None
) -> tuple[str, ...]:
    """Where the table starts, what p₀ = 1 - r decides and a last point past the diagonal."""
    if layout == "notes":
        first = (
            f"Row $k$ plots $(x_k, y_k)$ and decides on $p_k$; row 0 is the start point $(0, {r})$."
        )
    else:
        first = f"The start point $(0, {r})$ is plotted before the first step."
    notes = [first]
    if knobs["p0"] == "1-r":
        notes.append(
            "$p_0 = 1 - r$ is $5/4 - r$ rounded to an integer; every $p_k$ is an integer and the "
            "decisions are those of $5/4 - r$."
            if knobs["tie"] == "step"
            else "$p_0 = 1 - r$: every $p_k$ is an integer; with $p_k \\le 0$ keeping $y$, $p_k = 0$ "
            "decides differently from $5/4 - r$ (which is then $1/4 > 0$)."
        )
    if last is not None and last[0] > last[1]:
        notes.append(
            f"The last point {last} lies past the diagonal; its 8 images are those of "
            f"({last[1]}, {last[0]}), already plotted."
        )
    return tuple(notes)


_MIDPOINT_NOTES_COLUMNS = (
    heading("k", "k", role="label"),
    heading("x_k", "x_k"),
    heading("y_k", "y_k"),
    heading("p", "p_k"),
    heading("decision", r"\text{decision}"),
    heading("pixel", r"\text{plot } (x_k, y_k)"),
)
_MIDPOINT_COLUMNS = (
    heading("k", "k", role="label"),
    heading("p", "p_k"),
    heading("pixel", "(x_{k+1}, y_{k+1})"),
    heading("two_x", "2x_{k+1}"),
    heading("two_y", "2y_{k+1}"),
)


def _notes_rows(r: int, p0: Number, gen: Callable[[], Iterator[Step]]) -> Iterator[Step]:
    """The notes' layout: row k plots (x_k, y_k) and decides on p_k; a last row without a
    decision."""
    pt, k, p = (0, r), 0, p0
    for st in gen():
        yield Step(st.k, st.p, st.decision, pt, pt)
        x, y = st.pixel
        assert st.p is not None  # the midpoint circle decides every step
        p = st.p + 2 * x + 1 - (2 * y if st.decision == Move.SE else 0)
        pt, k = st.pixel, st.k + 1
    yield Step(k, normalize(p), None, pt, pt)


def _midpoint_parts(r: int, knobs: dict[str, str], layout: str) -> Parts:
    p0, derived = _midpoint_derived(r, knobs)

    def gen() -> Iterator[Step]:
        return midpoint(r, knobs["tie"], knobs["p0"], knobs["loop"], knobs["update"])

    notes = _midpoint_notes(r, knobs, layout, _last(gen()))
    if layout == "notes":

        def steps() -> Iterator[Step]:
            return _notes_rows(r, p0, gen)

        def points() -> Iterator[Pixel]:
            return (st.pixel for st in steps())

        return Parts(
            "Midpoint circle algorithm",
            derived,
            _MIDPOINT_NOTES_COLUMNS,
            ("x_k", "y_k"),
            steps,
            points,
            notes,
        )

    def textbook_points() -> Iterator[Pixel]:
        yield (0, r)
        for st in gen():
            yield st.pixel

    return Parts(
        "Midpoint circle algorithm",
        derived,
        _MIDPOINT_COLUMNS,
        ("two_x", "two_y"),
        gen,
        textbook_points,
        notes,
        next_pixel=True,  # _MIDPOINT_COLUMNS: row k plots (x_{k+1}, y_{k+1})
    )


def _general_parts(r: int, knobs: dict[str, str]) -> Parts:
    tie, loop = knobs["tie"], knobs["loop"]
    lt, ge = (r"\le", ">") if tie == "keep" else ("<", r"\ge")
    derived = (
        _start(r),
        worked("p0", 0, f"p_0 = x^2 + y^2 - r^2 = 0^2 + {r}^2 - {r}^2 = 0 \\text{{ at }} (0, {r})"),
        rule(
            "if_negative",
            f"p {lt} 0: \\text{{E}},\\ x = x + 1,\\ p = p + 2x + 1",
        ),
        rule(
            "otherwise",
            f"p {ge} 0: \\text{{SE}},\\ x = x + 1,\\ y = y - 1,\\ p = p + 2x - 2y + 1 "
            r"\ (\text{the new } x, y)",
        ),
        rule(
            "loop", r"\text{continue while } x " + (r"\le" if loop == "inclusive" else "<") + " y"
        ),
    )
    notes = (
        "The notes' general method, run as its algorithm box states it: p is decided at the "
        "current point (p0 = 0 at (0, r)), not at the midpoint, which pulls the octant inside "
        "the circle; the last row is the point where the loop stops.",
        "p = x^2 + y^2 - r^2 holds at (0, r) only: the updates add 2x + 1 and 2x - 2y + 1 "
        "with the new x and y, as the box prints them.",
    )

    def steps() -> Iterator[Step]:
        return general(r, tie, loop)

    columns = (
        heading("k", "k", role="label"),
        heading("x_k", "x"),
        heading("y_k", "y"),
        heading("p", "p"),
        heading("decision", r"\text{decision}"),
        heading("next", r"\text{next } (x, y)"),
    )

    def points() -> Iterator[Pixel]:
        return (st.pixel for st in general(r, tie, loop))

    return Parts(
        "Circle by the notes' general method",
        derived,
        columns,
        ("x_k", "y_k", "next"),
        steps,
        points,
        notes,
    )


def _last(steps: Iterator[Step]) -> Pixel | None:
    """The last step's pixel, if there are few steps (the note is for small answers only)."""
    last = None
    for i, s in enumerate(steps):
        if i > 1000:
            return None
        last = s.pixel
    return last


def _bresenham_parts(r: int, tie: str, xstep: str = "last") -> Parts:
    d0 = 3 - 2 * r
    lt, ge = (r"\le", ">") if tie == "keep" else ("<", r"\ge")
    x, xy = ("x_{k+1}", "x_{k+1} - y_{k+1}") if xstep == "first" else ("x_k", "x_k - y_k")
    derived = (
        _start(r),
        worked("d0", d0, f"d_0 = 3 - 2r = 3 - 2 \\cdot {r} = {d0}"),
        rule(
            "if_negative",
            f"d_k {lt} 0: d_{{k+1}} = d_k + 4{x} + 6," + r"\ y_{k+1} = y_k\ (\text{E})",
        ),
        rule(
            "otherwise",
            f"d_k {ge} 0: d_{{k+1}} = d_k + 4({xy}) + 10," + r"\ y_{k+1} = y_k - 1\ (\text{SE})",
        ),
        rule("loop", r"x_{k+1} = x_k + 1;\ \text{plot } (x_k, y_k) \text{ while } x \le y"),
    )
    columns = (
        heading("k", "k", role="label"),
        heading("p", "d_k"),
        heading("decision", r"\text{decision}"),
        heading("pixel", "(x_k, y_k)"),
    )
    notes: tuple[str, ...] = (
        "Each row plots (x_k, y_k); d_k and the decision give the next point.",
    )

    if xstep == "first":
        notes = (
            *notes,
            "x is stepped before d is updated (the widely copied code): its increments are 4 "
            "larger than Bresenham's, so its d values, and some of its points, differ.",
        )

    def steps() -> Iterator[Step]:
        return bresenham(r, tie, xstep)

    return Parts(
        "Bresenham's circle algorithm", derived, columns, (), steps, pixels_of(steps), notes
    )
