"""Side-by-side comparisons: every algorithm for one primitive, and why their pixels differ.

The notes ask "Compare DDA and Bresenham's line algorithms"; :func:`compare_lines` answers with
evidence: one row per major-axis coordinate, the ideal line's exact value there, the pixel each
method plots, and, where they differ, the reason (a tie broken differently, a DDA sample that is
not on a pixel centre, ...), each reason explained once in the notes with its numbers.
:func:`compare_circles` does the same for the circle methods over the first octant.

A comparison is a :class:`~scanconv.core.records.Solution` with no step table: its table is a
secondary :class:`~scanconv.core.records.Table`, and its text figure marks the pixels on which the
methods disagree.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..core import lazy
from ..core.checks import InputError, check_integer
from ..core.ideal import IdealCircle, IdealLine
from ..core.numeric import Number, fmt, fmt_short, normalize
from ..core.records import Pixel, PixelFigure, Plot, Solution, Table, Walk, heading
from .methods import METHODS, compared, method

if TYPE_CHECKING:
    from ..algorithms import circles
    from . import asked
    from .primitives import circle, line
    from .theory import derivations as th
else:
    circles = lazy.module("scanconv.algorithms.circles")
    circle = lazy.module("scanconv.answers.primitives.circle")
    asked = lazy.module("scanconv.answers.asked")
    th = lazy.module("scanconv.answers.theory.derivations")
    line = lazy.module("scanconv.answers.primitives.line")

LINE_METHODS = compared("line")
"""The line algorithms compared, in the order of the table's columns (their records' order)."""

CIRCLE_METHODS = compared("circle")
"""The circle methods compared; the first is the reference the others are measured against."""

NAMES = {m.name: m.short for m in METHODS.values() if m.command in ("line", "circle") and m.short}
"""Display names of the methods (table headings), from their records."""

SHORT = {m.name: m.fact("tag") for m in METHODS.values() if m.command == "circle" and m.fact("tag")}
"""Names of the circle methods in reason tags (``trig off``, ``SDDA twice``), from their
records."""

REFERENCE = CIRCLE_METHODS[0]
"""The circle method the others are measured against (the first compared: the midpoint)."""

#: Reason tags shown in the table; the notes explain each one that occurs, with its numbers.
TIE = "tie"
DDA_OFF = "DDA off centre"
DDA_MANY = "DDA repeats"


def arithmetic(maj: str, mnr: str, negative: bool = False) -> tuple[tuple[str, str, str], ...]:
    """What each line method computes per pixel (the textbook forms), for a major axis.

    >>> arithmetic("x", "y")[2]
    ('Bresenham', 'p += 2dy or 2dy - 2dx', 'integers only')
    >>> arithmetic("y", "x", negative=True)[2][1]
    'p += 2|dx| or 2|dx| - 2dy'
    """
    d = f"|d{mnr}|" if negative else f"d{mnr}"
    return tuple(
        (m.short, m.fact("work").format(maj=maj, mnr=mnr, d=d), m.fact("arithmetic"))
        for m in (METHODS[f"line/{name}"] for name in LINE_METHODS)
        if m.fact("work")
    )


def _cell(values: list[int]) -> Any:
    """One method's minor coordinate(s) in a column: an int, ``None`` or ``"3, 4"``."""
    if not values:
        return None
    if len(values) == 1:
        return values[0]
    return ", ".join(str(v) for v in values)


def _group(pixels: Iterable[Pixel], steep: bool) -> dict[int, list[int]]:
    """Minor coordinates by major coordinate, each once, in plotting order."""
    out: dict[int, list[int]] = {}
    for x, y in pixels:
        a, b = (y, x) if steep else (x, y)
        col = out.setdefault(a, [])
        if b not in col:
            col.append(b)
    return out


def _first_rows(differing: list[tuple[Any, ...]]) -> Iterator[tuple[str, tuple[Any, ...]]]:
    """Each reason tag that occurs (the last cell of a row, tags joined by ", ") with the first
    row that has it: the example its note is worked on."""
    seen: set[str] = set()
    for row in differing:
        for tag in str(row[-1]).split(", "):
            if tag not in seen:
                seen.add(tag)
                yield tag, row


def _plotted(sol: Solution) -> list[Pixel]:
    """Every pixel a compared method plots (each of them plots some)."""
    return [] if sol.pixels is None else list(sol.pixels())


def _summary(sols: dict[str, Solution], differing: int, columns: int) -> str:
    """How many columns differ, and how many pixels each method plots."""
    counts = {m: len(set(_plotted(s))) for m, s in sols.items()}
    if not differing:
        return f"Every method plots the same pixels ({next(iter(counts.values()))})."
    return (
        f"The methods differ in {differing} of {_plural(columns, 'column')} ("
        + ", ".join(f"{NAMES[m]}: {_plural(n, 'pixel')}" for m, n in counts.items())
        + ")."
    )


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def _is_int(v: Number) -> bool:
    return Fraction(v).denominator == 1


MAX_LENGTH = 10**4
"""Largest major-axis length of ``compare line`` (about 2 s): unlike the step tables, a
comparison runs every method and groups its pixels before the first row."""

MAX_RADIUS = 2000
"""Largest radius of ``compare circle`` (a few seconds: five methods, the floating-point ones
with exact checks, all run before the first row)."""


def compare_lines(x1: Number, y1: Number, x2: Number, y2: Number, theory: bool = False) -> Solution:
    """The basic method, the DDA and Bresenham's algorithm side by side for one line.

    Bresenham's algorithm needs integer end points; with fractional ones only the basic
    method and the DDA are compared.

    Notes
    -----
    With integer end points the basic method and the DDA compute the same exact points
    (``y = y1 + m (x - x1)``: the DDA adds ``m`` where the basic method multiplies, and with
    exact fractions both land on the line), and both round half up, so they always agree.
    Bresenham's decision picks the pixel nearer the line too, so it differs from them only
    at exact ties (``p_k = 0``, the line half-way between two pixels): it steps the minor
    coordinate toward the end point, which is *down* on a line of negative slope, while
    rounding half up always goes up.

    Examples
    --------
    >>> sol = compare_lines(2, 8, 10, 4)
    >>> for row in list(sol.tables[0].rows())[:3]:  # x, y on the line, basic, DDA, Bresenham
    ...     print(row[:5], row[-1])
    (2, 8, 8, 8, 8) None
    (3, Fraction(15, 2), 8, 8, 7) tie
    (4, 7, 7, 7, 7) None
    """
    length = max(abs(Fraction(x2 - x1)), abs(Fraction(y2 - y1)))
    if length > MAX_LENGTH:
        raise InputError(
            f"compare line: the line is {fmt_short(length)} pixels long along its major axis; "
            f"at most {MAX_LENGTH} (every method runs before the first row)"
        )
    integer = all(_is_int(v) for v in (x1, y1, x2, y2))
    methods = LINE_METHODS if integer else LINE_METHODS[:2]
    sols = {m: line.line_solution(m, x1, y1, x2, y2) for m in methods}
    dx, dy = Fraction(x2 - x1), Fraction(y2 - y1)
    steep = abs(dy) > abs(dx)
    maj, mnr = ("y", "x") if steep else ("x", "y")
    a1, b1, a2 = (y1, x1, y2) if steep else (x1, y1, x2)
    da, db = (dy, dx) if steep else (dx, dy)
    slope = db / da if da else Fraction(0)

    def exact(a: int) -> Number:
        return normalize(b1 + slope * (a - a1))

    def groups() -> dict[str, dict[int, list[int]]]:
        return {m: _group(_plotted(sols[m]), steep) for m in methods}

    first = groups()
    majors = sorted(set().union(*first.values()), reverse=a2 < a1)

    def rows() -> Iterator[tuple[Any, ...]]:
        cols = groups()
        for a in majors:
            cells = [cols[m].get(a, []) for m in methods]
            reasons = _line_reasons(dict(zip(methods, cells, strict=True)))
            yield (a, exact(a), *(_cell(c) for c in cells), ", ".join(reasons) or None)

    differing = [r for r in rows() if r[-1] is not None]
    notes = _line_notes(sols, steep, maj, mnr, exact, differing, integer, len(majors))
    bres = sols.get("bresenham")
    derived = tuple(sols["dda"].derived) + (
        tuple(q for q in bres.derived if q.key in ("p0", "inc_keep", "inc_step")) if bres else ()
    )
    columns = (
        heading(maj, maj),
        heading(f"{mnr}_exact", f"{mnr} \\text{{ on the line}}", 3),
        *(heading(m, f"\\text{{{NAMES[m]}}}") for m in methods),
        heading("reason", r"\text{differ}"),
    )
    tables = [Table(f"Pixels side by side ({mnr} for each {maj})", columns, rows, stepped=True)]
    if integer:
        tables.append(
            Table(
                "Arithmetic per pixel",
                (
                    heading("method", r"\text{method}", role="label"),
                    heading("work", r"\text{per pixel}"),
                    heading("arithmetic", r"\text{arithmetic}"),
                ),
                lambda: iter(arithmetic(maj, mnr, da * db < 0)),
            )
        )
    all_pixels = {m: _plotted(sols[m]) for m in methods}
    return Solution(
        primitive="line",
        algorithm="compare",
        title=f"Line algorithms compared: ({fmt_short(x1)}, {fmt_short(y1)}) to "
        f"({fmt_short(x2)}, {fmt_short(y2)})",
        given=sols["dda"].given,
        derived=derived,
        notes=tuple(notes),
        walk=Walk(tables=(*tables, *_theory("line", theory))),
        plot=Plot(figures=_disagreement_figure(all_pixels), ideal=(IdealLine(x1, y1, x2, y2),)),
        data={"methods": list(methods), "columns_differing": len(differing)},
    )


def _line_reasons(cells: dict[str, list[int]]) -> list[str]:
    """The reason tags of one column (empty when every method agrees)."""
    ref, dda = cells["basic"], cells["dda"]
    out = []
    bres = cells.get("bresenham")
    if bres is not None and bres != ref:
        out.append(TIE)  # the only way they differ (see compare_lines' Notes; tested)
    if dda != ref:
        # The DDA's major coordinate moves by at most 1 a step, from P1 to P2 rounded half up,
        # so it covers the basic method's columns exactly; it differs within a column only.
        out.append(DDA_MANY if len(dda) > 1 else DDA_OFF)
    for name, cell in cells.items():  # the other methods, by their records' reason tags
        tag = METHODS[f"line/{name}"].fact("tag")
        if tag and cell != ref:
            out.append(f"{tag} {'repeats' if len(cell) > 1 else 'off'}")
    return out


def _other_note(
    tag: str, row: tuple[Any, ...], methods: list[str], mnr: str, at: str, e: Number
) -> str:
    """The note of a method's own reason tag (``SDDA off``): what it plots in the row's
    column, and what the basic method plots there."""
    short, kind = tag.rsplit(" ", 1)
    m = next(n for n in methods if METHODS[f"line/{n}"].fact("tag") == short)
    cell, ref = row[2 + methods.index(m)], row[2 + methods.index("basic")]
    what = f"{mnr} = {cell}" + (" (more than one point of its walk)" if kind == "repeats" else "")
    return (
        f"{tag[:1].upper()}{tag[1:]} (rows marked '{tag}'): the {METHODS[f'line/{m}'].title} "
        f"plots {what} at {at}, where the basic method plots {ref}, the pixel centre nearest "
        f"the line ({mnr} = {fmt_short(e)} at {at})."
    )


def _line_notes(
    sols: dict[str, Solution],
    steep: bool,
    maj: str,
    mnr: str,
    exact: Callable[[int], Number],
    differing: list[tuple[Any, ...]],
    integer: bool,
    columns: int,
) -> list[str]:
    """The summary, then one note per reason tag that occurs, with its first example."""
    notes = [_summary(sols, len(differing), columns)]
    if integer:
        notes.append(
            "With integer end points the basic method and the DDA compute the same exact "
            f"points, {mnr} = {mnr}1 + ({'dx/dy' if steep else 'dy/dx'})({maj} - {maj}1), "
            "and both round half up, so they agree; Bresenham picks the nearer pixel with "
            "integers only and can differ from them only at an exact tie."
        )
    else:
        others = [NAMES[m] for m in LINE_METHODS[3:] if m not in sols]  # after the notes' three
        notes.append(
            "Bresenham's algorithm needs integer end points; it is left out"
            + (
                f", and so {'is' if len(others) == 1 else 'are'} {', '.join(others)} "
                "(compared on integer end points only)."
                if others
                else "."
            )
        )
    bres = sols.get("bresenham")
    bres_p = _bresenham_p(bres, steep) if bres is not None else {}
    dda_pts = _dda_points(sols["dda"], steep)
    for tag, row in _first_rows(differing):
        a = row[0]
        e = exact(a)
        at = f"{maj} = {a}"
        if tag not in (TIE, DDA_OFF, DDA_MANY):
            notes.append(_other_note(tag, row, list(sols), mnr, at, e))
        elif tag == TIE:
            lo, hi = Fraction(e) - Fraction(1, 2), Fraction(e) + Fraction(1, 2)
            k, p = bres_p.get(a, (None, None))
            cell = row[2 + list(sols).index("bresenham")]  # its column, wherever it is
            lower = cell == normalize(lo)
            way = ("left" if lower else "right") if steep else ("down" if lower else "up")
            notes.append(
                f"Tie (rows marked 'tie'): at {at} the line is at {mnr} = {fmt_short(e)}, "
                f"half-way between {fmt_short(lo)} and {fmt_short(hi)}. Rounding half up "
                f"(basic, DDA) takes "
                f"{fmt_short(hi)}; Bresenham's p_{k} = {p} steps {mnr} toward the end point, "
                f"{way} to {cell}."
            )
        else:
            pts = dda_pts.get(a, [])
            shown = " and ".join(f"({fmt_short(x)}, {fmt_short(y)})" for x, y in pts)
            what = (
                f"samples the line at {shown}, not on the pixel centre {at}, and rounds "
                "both coordinates"
                if tag == DDA_OFF
                else f"has the points {shown}, which round to the same {at}"
            )
            notes.append(
                f"{tag[:1].upper()}{tag[1:]} (rows marked '{tag}'): the DDA {what}; the "
                f"basic method evaluates the line at the pixel centre ({mnr} = "
                f"{fmt_short(e)} at {at})."
            )
    return notes


def _bresenham_p(sol: Solution, steep: bool) -> dict[int, tuple[int, Any]]:
    """``(k, p_k)`` of the Bresenham step that plotted each major coordinate."""
    return {(s.pixel[1] if steep else s.pixel[0]): (s.k, s.p) for s in sol.steps()}


def _dda_points(sol: Solution, steep: bool) -> dict[int, list[tuple[Number, Number]]]:
    """The DDA's exact points ``(x_k, y_k)`` by the major coordinate of their pixel."""
    out: dict[int, list[tuple[Number, Number]]] = {}
    for s in sol.steps():
        out.setdefault(s.pixel[1] if steep else s.pixel[0], []).append(s.extra[:2])
    return out


def _disagreement_figure(pixels: dict[str, list[Pixel]]) -> tuple[PixelFigure, ...]:
    """A grid: ``#`` where every method plots the pixel, ``o`` where only some do."""
    sets = [set(p) for p in pixels.values()]
    union = set().union(*sets)
    if not union:
        return ()
    agreed = set.intersection(*sets)
    xs, ys = [p[0] for p in union], [p[1] for p in union]
    return (
        PixelFigure(
            tuple(sorted(agreed)),
            tuple(sorted(union - agreed)),
            (min(xs), min(ys), max(xs), max(ys)),
            legend="# = every method plots it, o = only some do (see the table)",
        ),
    )


# --- circles -------------------------------------------------------------------------------------


def compare_circles(r: Number, theory: bool = False) -> Solution:
    """Every circle method side by side over the first octant, measured against the midpoint.

    The 8 images of a point ``(x, y)`` depend only on ``{|x|, |y|}``, so two methods plot the
    same circle exactly when they plot the same points with ``0 <= x <= y``: the table has one
    row per x of that octant (x is its major axis), the circle's ``y = sqrt(r² - x²)`` (to 3
    decimals), and the y each method plots there. Where a method differs from the midpoint
    method (Bresenham's ``d0 = 3 - 2r`` never does), the row says how: ``off`` (its point in
    this column is not the rounded circle: the parametric method and the symmetric DDA sample
    off the pixel centres), ``skips`` or ``twice`` (no point, or two, in this column),
    ``stops`` (it ends at the 45 degree diagonal before the midpoint method does). The
    symmetric DDA is left out above its radius limit.

    Examples
    --------
    >>> sol = compare_circles(5)
    >>> for row in sol.tables[0].rows():
    ...     print(row[0], *row[2:])
    0 5 5 5 5 5 5 None
    1 5 5 5 4 5 5 general off
    2 5 5 5 4 5 5, 4 general off, SDDA twice
    3 4 4 4 3 4 4, 3 general off, SDDA twice
    """
    ir = check_integer(r, "radius", negative=False, param="r")
    if ir > MAX_RADIUS:
        raise InputError(
            f"compare circle: the radius must be at most {MAX_RADIUS} (got {ir}; "
            "every method runs before the first row)"
        )
    methods = tuple(m for m in CIRCLE_METHODS if _takes(m, ir))
    sols = {m: circle.circle_solution(m, ir) for m in methods}

    def octant(m: str) -> dict[int, list[int]]:
        pts = sorted(
            (p for p in _plotted(sols[m]) if 0 <= p[0] <= p[1]), key=lambda p: (p[0], -p[1])
        )
        return _group(pts, steep=False)

    cols = {m: octant(m) for m in methods}
    xs = sorted(set().union(*cols.values()))
    last = {m: max(cols[m], default=-1) for m in methods}

    def exact(x: int) -> Number:
        return normalize(circles.sqrt6(ir * ir - x * x))

    def rows() -> Iterator[tuple[Any, ...]]:
        for x in xs:
            cells = {m: cols[m].get(x, []) for m in methods}
            reasons = _circle_reasons(x, cells, last)
            yield (x, exact(x), *(_cell(cells[m]) for m in methods), ", ".join(reasons) or None)

    differing = [row for row in rows() if row[-1] is not None]
    notes = [_summary(sols, len(differing), len(xs))]
    notes.append(
        "Only the points with 0 <= x <= y are compared: the other seven octants are their "
        "mirror images, the same for every method. The midpoint method (p0 = 1 - r) and "
        "Bresenham's (d0 = 3 - 2r) decide on the same sign, so they always agree."
    )
    notes.extend(_circle_notes(sols, cols, differing, exact))
    derived = tuple(
        q
        for m in methods
        for q in sols[m].derived
        if q.key in ("p0", "d0", "equation", "dtheta", "epsilon")
    )
    columns = (
        heading("x", "x"),
        heading("y_exact", r"y = \sqrt{r^2 - x^2}", 3),
        *(heading(m, f"\\text{{{NAMES[m]}}}") for m in methods),
        heading("reason", r"\text{differ}"),
    )
    return Solution(
        primitive="circle",
        algorithm="compare",
        title=f"Circle methods compared: r = {ir}",
        given=sols[REFERENCE].given[:1],
        derived=derived,
        notes=tuple(notes),
        walk=Walk(
            tables=(
                Table("First octant side by side (y for each x)", columns, rows, stepped=True),
                *_theory("circle", theory),
            )
        ),
        plot=Plot(
            figures=_disagreement_figure({m: _plotted(sols[m]) for m in methods}),
            ideal=(IdealCircle(0, 0, ir),),
        ),
        data={"methods": list(methods), "columns_differing": len(differing)},
    )


def _takes(name: str, r: int) -> bool:
    """Whether circle method ``name`` takes radius ``r`` (its record's row estimate refuses
    a radius beyond the method's limit, as the symmetric DDA's)."""
    try:
        method("circle", name).load("rows")(asked.CircleQuestion(name, r))
    except InputError:
        return False
    return True


def _circle_reasons(x: int, cells: dict[str, list[int]], last: dict[str, int]) -> list[str]:
    """The reason tags of one octant column, each method measured against the midpoint's;
    ``last`` is each method's last column in the octant."""
    ref = cells[REFERENCE]
    out = []
    for m, ys in cells.items():
        if m == REFERENCE or ys == ref:
            continue
        if not ys:
            kind = "stops" if x > last[m] else "skips"
        elif not ref:
            kind = "beyond"
        else:
            kind = "twice" if len(ys) > 1 else "off"
        out.append(f"{SHORT[m]} {kind}")
    return out


def _circle_notes(
    sols: dict[str, Solution],
    cols: dict[str, dict[int, list[int]]],
    differing: list[tuple[Any, ...]],
    exact: Callable[[int], Number],
) -> Iterator[str]:
    """One note per reason tag that occurs, with its first example's numbers."""
    by_short = {v: k for k, v in SHORT.items()}
    for tag, row in _first_rows(differing):
        x = row[0]
        short, kind = tag.rsplit(" ", 1)
        m = by_short[short]
        head = f"{tag} (rows marked '{tag}'): at x = {x} the circle is at y = {fmt(exact(x), 3)}"
        ref = _cell(cols[REFERENCE].get(x, []))
        if kind == "stops":
            a = max(cols[m])
            b = cols[m][a][-1]
            gap = (
                f"; the circle has a gap between ({a}, {b}) and its mirror image ({b}, {a})"
                if b - a > 1
                else ""
            )
            yield (
                f"{head}; the {NAMES[m]} method's last point in the octant is ({a}, {b}) "
                f"(it stops at the 45 degree diagonal), so it plots nothing in this column, "
                f"where the midpoint method plots ({x}, {ref}){gap}."
            )
            continue
        if m in _DECIDED_AT_THE_POINT:  # its points are pixels: no samples between them
            samples = ", ".join(f"({x}, {y})" for y in cols[m].get(x, []))
        else:
            samples = ", ".join(
                f"({fmt(px, 3)}, {fmt(py, 3)})" for px, py in _octant_samples(sols[m], x)
            )
        what = {
            "off": f"the {NAMES[m]} method's point in this column, {samples}, is not at the "
            f"pixel centre and rounds to y = {_cell(cols[m][x])}, the midpoint method's "
            f"to y = {ref}",
            "twice": f"the {NAMES[m]} method's points {samples} both round into this column",
            "decides": f"the {NAMES[m]} method tests p = x^2 + y^2 - r^2 at its point, not at "
            f"the midpoint between the two candidate pixels, and plots {samples}, where the "
            f"midpoint method plots ({x}, {ref})",
            "skips": f"none of the {NAMES[m]} method's points rounds into this column",
            "beyond": f"the {NAMES[m]} method's point {samples} lies past the midpoint "
            "method's last column",
        }["decides" if kind == "off" and m in _DECIDED_AT_THE_POINT else kind]
        yield f"{head}; {what}."


_DECIDED_AT_THE_POINT = ("general",)
"""The methods that step pixel by pixel on a test at the point itself (the notes' general
method): where one differs from the midpoint method, that test is the reason."""


def _octant_samples(sol: Solution, x: int) -> Iterator[tuple[Any, Any]]:
    """The exact or float sample points of a circle method whose pixel lies in column x of
    the octant 0 <= x <= y (a point past the diagonal counts in its mirror column)."""
    for s in sol.steps():
        px, py = s.pixel
        if min(px, py) != x:
            continue
        sx, sy = s.extra[-2:]  # the methods' own (x, y) columns come last
        yield (sx, sy) if px <= py else (sy, sx)


def _theory(kind: str, wanted: bool) -> tuple[Table, ...]:
    """The points the notes' comparison questions expect, as a table (``theory=True``)."""
    if not wanted:
        return ()
    if kind == "line":
        return (
            th.theory_table(
                "Theory: DDA vs Bresenham", ("point", "DDA", "Bresenham"), th.LINE_THEORY
            ),
        )
    return (
        th.theory_table(
            "Theory: general method vs Bresenham (midpoint)",
            ("point", "general method", "Bresenham"),
            th.CIRCLE_THEORY,
        ),
    )
