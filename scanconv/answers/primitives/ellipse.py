"""The worked answer of an ellipse: both regions' tables, the 4-way symmetry table and the
pixels."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from fractions import Fraction
from itertools import dropwhile, takewhile
from typing import TYPE_CHECKING, Any, NamedTuple

from ...algorithms.conventions import convention_note, resolve
from ...algorithms.ellipses import (
    MAX_AXIS,
    images,
    midpoint_ellipse,
    quarter,
    region1_end,
    symmetric_pixels,
)
from ...core import lazy
from ...core.checks import InputError, check_integer
from ...core.ideal import IdealEllipse
from ...core.numeric import Number, fmt_paren, fmt_short, round_c_cast
from ...core.records import (
    Code,
    Column,
    Pixel,
    Plot,
    Quantity,
    Solution,
    Step,
    Table,
    Theory,
    Walk,
    heading,
    step_getter,
    worked,
)
from .. import methods
from ..asked import EllipseKnobs, EllipseQuestion, knob_values
from .circle import symmetry_table

if TYPE_CHECKING:
    from ..theory import derivations as theory
else:  # only --derive and --algorithm need it
    theory = lazy.module("scanconv.answers.theory.derivations")

# --- the Solution -----------------------------------------------------------------------------


def _region_columns(p: str) -> tuple[Column, ...]:
    return (
        heading("k", "k", role="label"),
        heading("p", f"{p}_k"),
        heading("pixel", "(x_{k+1}, y_{k+1})"),
        heading("two_ry2_x", "2r_y^2 x_{k+1}"),
        heading("two_rx2_y", "2r_x^2 y_{k+1}"),
    )


_EXTRA = ("region", "two_ry2_x", "two_rx2_y")


class _Ellipse(NamedTuple):
    """The checked question: semi-axes, centre, conventions and where region 1 ends."""

    rx: int
    ry: int
    xc: int
    yc: int
    loop: str
    tie: str
    p0: str
    x0: int
    y0: int


def _checked(rx: Number, ry: Number, xc: Number, yc: Number, knobs: dict[str, str]) -> _Ellipse:
    """The question with its numbers checked, and the end of region 1."""
    irx = check_integer(rx, "rx", negative=False, param="rx")
    iry = check_integer(ry, "ry", negative=False, param="ry")
    ixc, iyc = check_integer(xc, "xc", param="xc"), check_integer(yc, "yc", param="yc")
    if max(irx, iry) > MAX_AXIS:
        raise InputError(
            f"semi-axes of the midpoint ellipse must be at most {MAX_AXIS:.0e} "
            f"(got rx = {irx}, ry = {iry}): the working needs the end of region 1 first",
            "rx" if irx > MAX_AXIS else "ry",
        )
    loop, tie, p0s = knobs["loop"], knobs["tie"], knobs["p0"]
    x0, y0 = region1_end(irx, iry, loop, tie, p0s)
    return _Ellipse(irx, iry, ixc, iyc, loop, tie, p0s, x0, y0)


def _given(e: _Ellipse) -> tuple[Quantity, ...]:
    return (
        worked("rx", e.rx, f"r_x = {e.rx}"),
        worked("ry", e.ry, f"r_y = {e.ry}"),
        worked("center", (e.xc, e.yc), f"\\text{{centre }} (x_c, y_c) = ({e.xc}, {e.yc})"),
    )


def _start_p(e: _Ellipse, key: str, v: Number, tex: str) -> Quantity:
    """A region's first p, ``= v`` and, with ``p0 = rounded``, the integer it starts from."""
    if e.p0 == "exact" or round_c_cast(v) == v:
        shown = fmt_short(v)
    else:
        shown = f"{fmt_short(v)} \\to {round_c_cast(v)} \\text{{ (rounded)}}"
    return worked(key, v if e.p0 == "exact" else round_c_cast(v), f"{tex} = {shown}")


def _derived(e: _Ellipse) -> tuple[Quantity, ...]:
    """The squares, where region 1 runs, each region's first p (p2_0 only if region 2 steps)."""
    rx2, ry2, x0, y0 = e.rx * e.rx, e.ry * e.ry, e.x0, e.y0
    cmp = r"\le" if e.loop == "inclusive" else "<"
    p1 = quarter(4 * ry2 - 4 * rx2 * e.ry + rx2)
    p2 = quarter(ry2 * (2 * x0 + 1) ** 2 + 4 * rx2 * (y0 - 1) ** 2 - 4 * rx2 * ry2)
    half = Fraction(2 * x0 + 1, 2)
    derived = (
        worked(
            "squares",
            (rx2, ry2, 2 * rx2, 2 * ry2),
            f"r_x^2 = {rx2},\\ r_y^2 = {ry2},\\ 2r_x^2 = {2 * rx2},\\ 2r_y^2 = {2 * ry2}",
        ),
        worked(
            "region1",
            (2 * rx2 * e.ry,),
            f"\\text{{region 1 from }} (0, {e.ry}) \\text{{ while }} 2r_y^2 x {cmp} 2r_x^2 y\\ "
            f"(2r_x^2 y \\text{{ starts at }} {2 * rx2 * e.ry})",
        ),
        _start_p(
            e,
            "p1_0",
            p1,
            f"p1_0 = r_y^2 - r_x^2 \\cdot r_y + \\tfrac{{r_x^2}}{{4}} = {ry2} - {rx2} \\cdot {e.ry} + "
            f"\\tfrac{{{rx2}}}{{4}}",
        ),
        worked(
            "region2_start",
            (x0, y0),
            f"\\text{{region 2 starts at }} (x_0, y_0) = ({x0}, {y0})"
            f"\\text{{, the last point of region 1}}",
        ),
        _start_p(
            e,
            "p2_0",
            p2,
            f"p2_0 = r_y^2(x_0 + \\tfrac12)^2 + r_x^2(y_0 - 1)^2 - r_x^2 r_y^2 = "
            f"{ry2} \\cdot {fmt_short(half)}^2 + {rx2} \\cdot {fmt_paren(y0 - 1)}^2 - "
            f"{rx2} \\cdot {ry2}",
        ),
    )
    if y0 == 0:  # region 1 ended on the x axis: region 2 has no steps, p2_0 is not used
        return derived[:-1]
    return derived


def _notes(e: _Ellipse) -> list[str]:
    """Each region's rule, the start point, a completed tip and the symmetry."""
    lt1, gt2 = (r"\le", r"\ge") if e.tie == "keep" else ("<", ">")
    notes = [
        f"Region 1: $p1_k {lt1} 0 \\to (x+1, y)$, "
        "$p1_{k+1} = p1_k + 2r_y^2 x_{k+1} + r_y^2$; "
        "else $(x+1, y-1)$, $p1_{k+1} = p1_k + 2r_y^2 x_{k+1} - 2r_x^2 y_{k+1} + r_y^2$.",
        f"Region 2: $p2_k {gt2} 0 \\to (x, y-1)$, "
        "$p2_{k+1} = p2_k - 2r_x^2 y_{k+1} + r_x^2$; "
        "else $(x+1, y-1)$, $p2_{k+1} = p2_k + 2r_y^2 x_{k+1} - 2r_x^2 y_{k+1} + r_x^2$; "
        "until $y = 0$.",
        f"The start point $(0, {e.ry})$ is plotted before the first step.",
    ]
    if e.y0 == 0 and e.x0 < e.rx:
        notes.append(
            f"Region 1 reached y = 0 at x = {e.x0} < rx = {e.rx}: the textbook loops stop here; "
            f"the tip is completed along y = 0 to ({e.rx}, 0) (rows without p, decision E)."
        )
    notes.append("Each quadrant point is mirrored into 4 pixels; a pixel is listed once.")
    return notes


def _tables(
    e: _Ellipse, steps: Callable[[], Iterator[Step]], points: Callable[[], Iterator[Pixel]]
) -> tuple[Table, ...]:
    """Region 1's and region 2's step tables and the 4-way symmetry table."""
    get1 = step_getter(_region_columns("p1"), _EXTRA)
    get2 = step_getter(_region_columns("p2"), _EXTRA)

    def region1() -> Iterator[tuple[Any, ...]]:
        return (get1(s) for s in takewhile(lambda s: s.extra[0] == 1, steps()))

    def region2() -> Iterator[tuple[Any, ...]]:
        return (get2(s) for s in dropwhile(lambda s: s.extra[0] == 1, steps()))

    return (
        Table("Region 1 (slope magnitude below 1)", _region_columns("p1"), region1),
        Table("Region 2 (slope magnitude 1 or more)", _region_columns("p2"), region2),
        symmetry_table(points, images, e.xc, e.yc),
    )


def ellipse_solution(
    rx: Number,
    ry: Number,
    xc: Number = 0,
    yc: Number = 0,
    *,
    loop: str | None = None,
    tie: str | None = None,
    p0: str | None = None,
    convention: str | None = None,
    derive: bool = False,
    pseudocode: bool = False,
    annotate: bool = False,
) -> Solution:
    """The worked solution of the midpoint ellipse with semi-axes ``rx``, ``ry``.

    ``loop`` is the region-1 loop convention (``"strict"``: while 2ry²x < 2rx²y, or
    ``"inclusive"``: <=), ``tie`` what p = 0 chooses (``"step"``: SE in both regions, or
    ``"keep"``: E in region 1 and S in region 2), ``p0`` how each region's first p is taken
    (``"exact"`` quarters, or ``"rounded"`` as Hearn & Baker's C code), ``convention`` a named
    preset; ``derive`` adds the derivation,
    ``pseudocode`` the algorithm as a listing, ``annotate`` the note naming the conventions.

    Raises ``ValueError`` for a negative or non-integer semi-axis or centre. ``rx = ry = 0``
    plots the centre; one zero semi-axis gives the segment between the tips.

    >>> sol = ellipse_solution(8, 6)
    >>> for q in sol.derived[2:4]:
    ...     print(q.text)
    p1₀ = r_y² - rₓ²·r_y + rₓ²/4 = 36 - 64·6 + 64/4 = -332
    region 2 starts at (x₀, y₀) = (7, 3), the last point of region 1
    >>> [len(list(t.rows())) for t in sol.tables]
    [7, 3, 11]
    >>> sum(1 for _ in sol.pixels()), sol.bbox
    (40, (-8, -6, 8, 6))
    """

    knobs = resolve("ellipse", "midpoint", convention, {"loop": loop, "tie": tie, "p0": p0})
    irx = check_integer(rx, "rx", negative=False, param="rx")
    iry = check_integer(ry, "ry", negative=False, param="ry")
    ixc, iyc = check_integer(xc, "xc", param="xc"), check_integer(yc, "yc", param="yc")
    q = EllipseQuestion("midpoint", irx, iry, ixc, iyc, EllipseKnobs(**knobs), convention)
    rec = methods.method("ellipse", "midpoint")
    derivation = rec.load("derivation") if derive else None
    listing = rec.load("pseudocode") if pseudocode else None
    sol: Solution = rec.load("answer")(q)
    if annotate:
        sol.notes = (*sol.notes, convention_note("ellipse", convention, knobs))
        sol.data = {"conventions": knobs}
    sol.theory = Theory(
        (theory.DERIVATION, *derivation(q)) if derivation is not None else (),
        (listing(q),) if listing is not None else (),
    )
    sol.question = q
    return sol


# --- The pieces the ellipse record names: each takes the question --------------------------


def rows(q: EllipseQuestion) -> int:
    """Both regions' rows: region 1 ends where the slope is -1, at x = rx^2 / sqrt(rx^2 +
    ry^2); region 2 has about ry^2 / sqrt(rx^2 + ry^2) steps (20000 x 20000: 28,287 rows).

    >>> rows(EllipseQuestion("midpoint", 8, 6))
    12
    """
    rx, ry = float(abs(q.rx)), float(abs(q.ry))
    if max(rx, ry) > MAX_AXIS:
        raise InputError(f"semi-axes of the midpoint ellipse must be at most {MAX_AXIS:.0e}")
    h = math.hypot(rx, ry) or 1.0
    return math.ceil((rx * rx + ry * ry) / h) + 2


def midpoint_derivation(q: EllipseQuestion) -> tuple[Quantity, ...]:
    """``--derive``: each region's p from the ellipse's equation at the midpoint."""
    return theory.ellipse_derivation(q.rx, q.ry)


def midpoint_pseudocode(q: EllipseQuestion) -> Code:
    """``--algorithm``: both regions' loops, with the question's conventions."""
    return theory.ellipse_code(str(q.knobs.loop), str(q.knobs.tie))


def midpoint_practice(q: EllipseQuestion) -> str:
    """A practice question's wording."""
    where = "centred at the origin" if (q.xc, q.yc) == (0, 0) else f"centred at ({q.xc}, {q.yc})"
    return (
        f"Draw the ellipse with rx = {q.rx} and ry = {q.ry} {where} with the midpoint ellipse "
        "algorithm: give the step tables of regions 1 and 2."
    )


def midpoint_answer(q: EllipseQuestion) -> Solution:
    """The midpoint ellipse (record ``ellipse/midpoint``) with its conventions."""
    e = _checked(q.rx, q.ry, q.xc, q.yc, knob_values(q.knobs))
    derived = _derived(e)
    notes = _notes(e)

    def steps() -> Iterator[Step]:
        return midpoint_ellipse(e.rx, e.ry, e.loop, e.tie, e.p0)

    def points() -> Iterator[Pixel]:
        yield (0, e.ry)
        for st in midpoint_ellipse(e.rx, e.ry, e.loop, e.tie, e.p0):
            yield st.pixel

    tables = _tables(e, steps, points)
    return Solution(
        primitive="ellipse",
        algorithm="midpoint",
        title=f"Midpoint ellipse algorithm: rx = {e.rx}, ry = {e.ry}, centre ({e.xc}, {e.yc})",
        given=_given(e),
        derived=derived,
        notes=tuple(notes),
        walk=Walk(
            columns=(heading("region", r"\text{region}", role="label"), *_region_columns("p")),
            extra_keys=_EXTRA,
            steps=steps,
            shown=False,
            tables=tables,
            regions="column",
            region_p=("p1_k", "p2_k"),  # the p columns of the region tables
            symmetry=4,
            center=(e.xc, e.yc),
            next_pixel=True,  # _region_columns: row k plots (x_{k+1}, y_{k+1})
        ),
        plot=Plot(
            pixels=lambda: symmetric_pixels(points(), e.xc, e.yc),
            bbox=(e.xc - e.rx, e.yc - e.ry, e.xc + e.rx, e.yc + e.ry),
            marks=((e.xc, e.yc),),
            ideal=(IdealEllipse(e.xc, e.yc, e.rx, e.ry),),
        ),
    )
