"""The worked answers of anti-aliasing: Xiaolin Wu's line (a step table of the two pixels and
their intensities) and area sampling or supersampling of a line, a circle or a polygon (an
intensity table and a shaded picture)."""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Sequence
from fractions import Fraction
from typing import Any, NamedTuple

from ..algorithms import coverage as cov
from ..algorithms.image_limits import check_levels
from ..algorithms.polygon import check_polygon, check_rule, vertices_from_coords
from ..algorithms.wu import ENDS, end_gaps, wu_line
from ..core.checks import InputError, check_integer
from ..core.numeric import Number, fmt_exact, fmt_short, normalize, round_half_up
from ..core.records import (
    MAX_GRID_CELLS,
    Column,
    Pixel,
    Quantity,
    ShadedMatrix,
    Solution,
    Step,
    Table,
    heading,
    rule,
    worked,
)

SHADING = (
    "The picture draws the intensity as ink on white: shade = L - 1 - level, so a fully "
    "covered pixel is the darkest character."
)


def _level_rule(levels: int) -> Quantity:
    """``level = ⌊I·7 + 1/2⌋ (L = 8)``: round half up of I (L - 1)."""
    return worked(
        "levels",
        levels,
        f"\\text{{level}} = \\lfloor I \\cdot (L - 1) + 1/2 \\rfloor = \\lfloor I \\cdot {levels - 1} "
        f"+ 1/2 \\rfloor \\quad (L = {levels})",
    )


def _picture(values: dict[Pixel, int], levels: int) -> ShadedMatrix | None:
    """The shaded picture of ``pixel -> level`` (ink: shade L - 1 - level), row 0 the top."""
    if not values:
        return None
    xs, ys = [p[0] for p in values], [p[1] for p in values]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    if x1 - x0 + 1 > MAX_GRID_CELLS or y1 - y0 + 1 > MAX_GRID_CELLS:
        return None
    rows = tuple(
        tuple(levels - 1 - values.get((x, y), 0) for x in range(x0, x1 + 1))
        for y in range(y1, y0 - 1, -1)
    )
    return ShadedMatrix(rows, levels, x1 - x0 + 1)


def _bbox(pixels: Sequence[Pixel]) -> tuple[int, int, int, int]:
    if not pixels:
        return (0, 0, 0, 0)
    xs, ys = [p[0] for p in pixels], [p[1] for p in pixels]
    return min(xs), min(ys), max(xs), max(ys)


class _WuWalk(NamedTuple):
    """Wu's walk along the major coordinate ``a`` (the minor one ``b``), from (a1, b1) to
    (a2, b2) with a increasing; ``ends`` is the end-point convention (:data:`ENDS`)."""

    steep: bool
    maj: str
    mnr: str
    lower: str
    upper: str
    a1: Number
    b1: Number
    a2: Number
    b2: Number
    swapped: bool
    ends: str

    @property
    def integer(self) -> bool:
        return all(isinstance(v, int) for v in (self.a1, self.b1, self.a2, self.b2))


def _wu_walk(x1: Number, y1: Number, x2: Number, y2: Number, ends: str) -> _WuWalk:
    steep = abs(Fraction(y2 - y1)) > abs(Fraction(x2 - x1))
    maj, mnr = ("y", "x") if steep else ("x", "y")
    lower, upper = ("left", "right") if steep else ("lower", "upper")
    (a1, b1), (a2, b2) = ((y1, x1), (y2, x2)) if steep else ((x1, y1), (x2, y2))
    swapped = a2 < a1
    if swapped:
        a1, b1, a2, b2 = a2, b2, a1, b1
    return _WuWalk(steep, maj, mnr, lower, upper, a1, b1, a2, b2, swapped, ends)


def _wu_ends(w: _WuWalk) -> tuple[Quantity, ...]:
    """The end columns round(a) and (with ``ends = coverage``) their weights."""
    maj = w.maj
    if w.integer and w.ends == "full":
        return ()
    g1, g2 = end_gaps(w.a1, w.a2, w.ends)
    c1, c2 = round_half_up(w.a1), round_half_up(w.a2)
    out = [
        rule(
            "columns",
            f"{maj}_{{\\text{{end}}}} = \\lfloor {maj} + 1/2 \\rfloor:\\ "
            f"\\lfloor {fmt_short(w.a1)} + 1/2 \\rfloor = {c1},\\ "
            f"\\lfloor {fmt_short(w.a2)} + 1/2 \\rfloor = {c2}",
        )
    ]
    if w.ends == "coverage":
        out += [
            worked(
                "gap1",
                g1,
                f"\\text{{gap}}_1 = 1 - \\operatorname{{frac}}({fmt_short(w.a1)} + 1/2) = {fmt_exact(g1)}",
            ),
            worked(
                "gap2",
                g2,
                f"\\text{{gap}}_2 = \\operatorname{{frac}}({fmt_short(w.a2)} + 1/2) = {fmt_exact(g2)}",
            ),
        ]
    return tuple(out)


def _wu_derived(w: _WuWalk, levels: int) -> tuple[Quantity, ...]:
    """Δ along both coordinates, the gradient, the minor coordinate and the split."""
    maj, mnr, a1, b1 = w.maj, w.mnr, w.a1, w.b1
    da, db = normalize(w.a2 - a1), normalize(w.b2 - b1)
    grad = normalize(Fraction(db) / da) if da else 0
    a2s, b2s = fmt_short(w.a2), fmt_short(w.b2)
    gap = "" if w.ends == "full" else " \\cdot \\text{gap}"
    return (
        worked(f"d{maj}", da, f"\\Delta {maj} = {a2s} - {_p(a1)} = {fmt_exact(da)}"),
        worked(f"d{mnr}", db, f"\\Delta {mnr} = {b2s} - {_p(b1)} = {fmt_exact(db)}"),
        worked(
            "gradient",
            grad,
            f"g = \\frac{{\\Delta {mnr}}}{{\\Delta {maj}}} = \\frac{{{fmt_exact(db)}}}"
            f"{{{fmt_exact(da)}}} = {fmt_exact(grad)}"
            if da
            else r"g = 0 \text{ (a single point)}",
        ),
        *_wu_ends(w),
        rule(
            "minor",
            f"{mnr}_k = {mnr}_1 + g ({maj}_k - {maj}_1) = {fmt_short(b1)} + {fmt_exact(grad)} "
            f"({maj}_k - {_p(a1)})",
        ),
        rule(
            "split",
            f"f = {mnr}_k - \\lfloor {mnr}_k \\rfloor,\\ I(\\text{{{w.lower}}}) = (1 - f){gap},\\ "
            f"I(\\text{{{w.upper}}}) = f{gap}"
            if gap
            else f"f = {mnr}_k - \\lfloor {mnr}_k \\rfloor,\\ I(\\text{{{w.lower}}}) = 1 - f,\\ "
            f"I(\\text{{{w.upper}}}) = f",
        ),
        _level_rule(levels),
    )


def _wu_notes(w: _WuWalk) -> tuple[str, ...]:
    if w.ends == "full":
        ends = (
            "End points (ends = full, the default; ends = coverage weights them): as in Wu "
            "(1991), drawn at full intensity"
            + (
                " (f = 0 there, so the second pixel of the first and last step has intensity 0)."
                if w.integer
                else "; the end columns are round(x) = floor(x + 1/2), the minor coordinate "
                "there read off the line."
            )
        )
        share = (
            f"Each step's two intensities sum to 1: the line's ink is shared between the two "
            f"pixels nearest to it along {w.mnr}, in proportion to its distance from each."
        )
    else:
        ends = (
            "End points (ends = coverage, as Wikipedia's widely copied pseudocode; the default "
            "is ends = full): each end column is weighted by the part of it the line covers "
            f"along {w.maj}, gap = 1 - frac({w.maj}1 + 1/2) and frac({w.maj}2 + 1/2) (1/2 for an "
            "integer end point); the columns between have gap = 1."
        )
        share = (
            f"Each step's two intensities sum to its gap: the line's ink is shared between the "
            f"two pixels nearest to it along {w.mnr}, in proportion to its distance from each."
        )
    return (
        *((f"End points swapped so that {w.maj} increases along the walk.",) if w.swapped else ()),
        ends,
        share,
        "Wu keeps f as an integer error term of n bits and draws from both ends at once; the "
        "table walks one way with f exact, and the levels are the intensities quantized.",
        SHADING,
    )


def _wu_columns(w: _WuWalk) -> tuple[Column, ...]:
    lower, upper = w.lower, w.upper
    gap = (heading("gap", r"\text{gap}", 3),) if w.ends == "coverage" else ()
    return (
        heading("k", "k"),
        heading(w.maj, f"{w.maj}_k"),
        heading(w.mnr, f"{w.mnr}_k \\text{{ (exact)}}", 3),
        *gap,
        heading("pixel_a", f"\\text{{{lower} pixel}}"),
        heading("pixel_b", f"\\text{{{upper} pixel}}"),
        heading("i_a", f"I(\\text{{{lower}}})", 3),
        heading("i_b", f"I(\\text{{{upper}}})", 3),
        heading("levels", f"\\text{{levels ({lower}, {upper})}}"),
    )


def _wu_shades(steps: Iterable[Step]) -> dict[Pixel, int]:
    """Each pixel's level (a pixel both steps share keeps the larger)."""
    values: dict[Pixel, int] = {}
    for s in steps:
        a, b = s.extra[-1]
        values[s.extra[2]] = a
        values[s.extra[3]] = max(values.get(s.extra[3], 0), b)
    return values


def _wu_point(v: Number) -> str:
    return fmt_short(v)


def wu_solution(
    x1: Number, y1: Number, x2: Number, y2: Number, levels: int = 8, ends: str = "full"
) -> Solution:
    """Xiaolin Wu's anti-aliased line as a worked answer; ``ends`` is ``"full"`` (the
    default) or ``"coverage"`` (:data:`~scanconv.algorithms.wu.ENDS`); the end points may be
    fractions.

    >>> sol = wu_solution(0, 0, 8, 3)
    >>> [str(q.value) for q in sol.derived[:3]]
    ['8', '3', '3/8']
    >>> [s.extra[4:] for s in sol.steps()][1]
    (Fraction(5, 8), Fraction(3, 8), (4, 3))
    >>> [str(s.extra[4]) for s in wu_solution(0, 1, 10, 2, ends="coverage").steps()][:2]
    ['1/2', '9/10']
    """
    if ends not in ENDS:
        raise InputError(f"unknown ends {ends!r} (choose from {', '.join(ENDS)})", "ends")
    fx1, fy1, fx2, fy2 = (normalize(v) for v in (x1, y1, x2, y2))
    L = check_levels(levels)
    w = _wu_walk(fx1, fy1, fx2, fy2, ends)
    coverage = ends == "coverage"

    def steps() -> Iterator[Step]:
        for s in wu_line(fx1, fy1, fx2, fy2, ends):
            ia, ib = s.extra[4], s.extra[5]
            levels_ab = (cov.quantize(ia, L), cov.quantize(ib, L))
            extra = (*s.extra[:6], *((s.extra[6],) if coverage else ()), levels_ab)
            yield Step(s.k, None, None, s.pixel, extra)

    def pixels() -> Iterator[Pixel]:
        for s in wu_line(fx1, fy1, fx2, fy2, ends):
            if s.extra[4]:
                yield s.extra[2]
            if s.extra[5]:
                yield s.extra[3]

    c1, c2 = round_half_up(w.a1), round_half_up(w.a2)
    plotted = list(pixels()) if c2 - c1 < 4 * MAX_GRID_CELLS else []
    values = _wu_shades(steps()) if plotted else {}
    picture = _picture({p: v for p, v in values.items() if v}, L) if plotted else None
    box = _wu_box(w)
    p1, p2 = f"({_wu_point(fx1)}, {_wu_point(fy1)})", f"({_wu_point(fx2)}, {_wu_point(fy2)})"
    sol = Solution(
        primitive="line",
        algorithm="wu",
        title=f"Xiaolin Wu's anti-aliased line: {p1} to {p2}, L = {L}"
        + (", ends weighted by coverage" if coverage else ""),
        given=(
            worked("P1", (fx1, fy1), f"P_1 = {p1}"),
            worked("P2", (fx2, fy2), f"P_2 = {p2}"),
            worked("L", L, f"L = {L} \\text{{ levels}}"),
        ),
        derived=_wu_derived(w, L),
        columns=_wu_columns(w),
        extra_keys=(w.maj, w.mnr, "pixel_a", "pixel_b", "i_a", "i_b",
                    *(("gap",) if coverage else ()), "levels"),
        steps=steps,
        pixels=pixels,
        bbox=box,
        notes=_wu_notes(w),
        figures=(picture,) if picture else (),
        geometry={
            "line": (fx1, fy1, fx2, fy2),
            **({"shades": values, "levels": L, "numbering": "none"} if values else {}),
        },
    )  # fmt: skip
    sol.data = {**sol.data, "conventions": {"ends": ends}}
    return sol


def _wu_box(w: _WuWalk) -> tuple[int, int, int, int]:
    """The pixel box of the walk: both end columns' two pixels (the minor coordinate is
    monotonic, so the ends bound it)."""
    da = w.a2 - w.a1
    grad = Fraction(w.b2 - w.b1) / da if da else Fraction(0)
    c1, c2 = round_half_up(w.a1), round_half_up(w.a2)
    lows = [math.floor(w.b1 + grad * (c - Fraction(w.a1))) for c in (c1, c2)]
    lo, hi = min(lows), max(lows) + 1
    return (lo, c1, hi, c2) if w.steep else (c1, lo, c2, hi)


def _p(v: Number) -> str:
    s = fmt_short(v)
    return f"({s})" if s.startswith("-") else s


class _Region(NamedTuple):
    """A shape to sample: its title, pixel values, exact area (if known) and its working."""

    title: str
    values: dict[Pixel, Any]
    exact_total: Number | None
    derived: list[Quantity]
    notes: list[str]
    geometry: dict[str, Any]


def _line_params(params: Sequence[Number]) -> tuple[Number, Number, Number, Number]:
    if len(params) != 4:
        raise InputError(f"a line needs x1 y1 x2 y2, got {len(params)} numbers", "line")
    x1, y1, x2, y2 = (normalize(v) for v in params)
    return x1, y1, x2, y2


def _coverage(
    pts: Sequence[tuple[Number, Number]], method: str, n: int, rule_name: str
) -> tuple[dict[Pixel, Any], Number | None]:
    if method == "area":
        return dict(cov.area_coverage(pts, rule_name)), cov.region_area(pts, rule_name)
    return dict(cov.supersample_coverage(pts, n, rule_name)), None


def _line_region(params: Sequence[Number], method: str, n: int, rule_name: str) -> _Region:
    x1, y1, x2, y2 = _line_params(params)
    pts = cov.line_strip(x1, y1, x2, y2)
    minor = "y" if abs(Fraction(y2 - y1)) <= abs(Fraction(x2 - x1)) else "x"
    strip = worked(
        "strip",
        pts,
        "\\text{line one pixel wide along } "
        + minor
        + ": "
        + ", ".join(f"({fmt_short(x)}, {fmt_short(y)})" for x, y in pts),
    )
    note = (
        f"The line is the parallelogram one pixel thick along {minor}, from end point to "
        "end point: exact, and each column along the line is covered by 1 in total."
    )
    title = f"line ({fmt_short(x1)}, {fmt_short(y1)}) to ({fmt_short(x2)}, {fmt_short(y2)})"
    values, exact = _coverage(pts, method, n, rule_name)
    return _Region(title, values, exact, [strip], [note], {"line": (x1, y1, x2, y2)})


def _polygon_region(params: Sequence[Number], method: str, n: int, rule_name: str) -> _Region:
    pts, _ = check_polygon(vertices_from_coords(params))
    geometry = {
        "polyline": [(float(x), float(y)) for x, y in (*pts, pts[0])],
        "polyline_name": "polygon",
    }
    values, exact = _coverage(pts, method, n, rule_name)
    title = f"polygon of {len(pts)} vertices ({rule_name} rule)"
    return _Region(title, values, exact, [], [], geometry)


def _circle_region(params: Sequence[Number], method: str, n: int, rule_name: str) -> _Region:
    if len(params) not in (1, 3):
        raise InputError(f"a circle needs r [xc yc], got {len(params)} numbers", "circle")
    r = check_integer(params[0], "radius", negative=False)
    xc, yc = (
        (check_integer(v, n_) for v, n_ in zip(params[1:], ("xc", "yc"), strict=False))
        if len(params) == 3
        else (0, 0)
    )
    ring = rule(
        "ring",
        f"\\text{{ring: }} {r} - 1/2 \\le d \\le {r} + 1/2 \\text{{ around }} ({xc}, {yc})",
    )
    notes = []
    values: dict[Pixel, Any]
    if method == "area":
        values = dict(cov.ring_area(r, xc, yc))
        notes.append(
            "A circle's covered areas involve arcsin: they are computed in floating point "
            "from the closed form (the ring's total is π((r + 1/2)² - (r - 1/2)²) = 2π·r)."
        )
    else:
        values = dict(cov.ring_supersample(r, n, xc, yc))
    title = f"circle r = {r}, centre ({xc}, {yc}), one pixel wide"
    return _Region(title, values, None, [ring], notes, {"circle": (xc, yc, r)})


_REGIONS = {"line": _line_region, "polygon": _polygon_region, "circle": _circle_region}


def _sampling_rules(method: str, n: int) -> list[Quantity]:
    if method == "area":
        return [
            rule(
                "intensity",
                r"I(i, j) = \text{area of the shape inside } [i - 1/2, i + 1/2] \times [j - 1/2, j + 1/2]",
            )
        ]
    return [
        rule(
            "samples",
            f"{n} \\times {n} = {n * n} \\text{{ samples per pixel, at }} (i - 1/2 + (2a + 1)/{2 * n},\\ "
            f"j - 1/2 + (2b + 1)/{2 * n}),\\ a, b = 0 \\ldots {n - 1}",
        ),
        rule("intensity", f"I = \\text{{samples inside}} / {n * n}"),
    ]


def _total(values: dict[Pixel, Any], exact_total: Number | None) -> Quantity:
    """The sum of the intensities, against the shape's exact area when that is known."""
    if any(isinstance(v, float) for v in values.values()):
        total = sum(float(v) for v in values.values())
        return worked("total", total, f"\\text{{sum of }} I \\approx {total:.3f}")
    exact_sum = normalize(sum(values.values(), Fraction(0)))
    text = f"\\text{{sum of }} I = {fmt_short(exact_sum)}"
    if exact_total is not None:
        if exact_sum == exact_total:
            text += " = \\text{the exact area of the shape}"
        else:
            text += f" \\ne {fmt_short(exact_total)} = \\text{{the exact area of the shape}}"
    return worked("total", exact_sum, text)


def _intensity_table(
    order: list[Pixel], values: dict[Pixel, Any], levels_of: dict[Pixel, int]
) -> Table:
    def rows() -> Iterator[tuple[Any, ...]]:
        for p in order:
            v = values[p]
            exact = "-" if isinstance(v, float) else fmt_exact(v)
            yield (p, v, exact, levels_of[p])

    return Table(
        "Intensities (pixels with I > 0, bottom row first)",
        (
            heading("pixel", r"\text{pixel } (i, j)"),
            heading("intensity", "I", 3),
            heading("exact", r"I \text{ (exact)}"),
            heading("level", r"\text{level}"),
        ),
        rows,
    )


def antialias_solution(
    shape: str,
    params: Sequence[Number],
    *,
    method: str = "area",
    samples: int = 4,
    levels: int = 8,
    rule_name: str = "even-odd",
    ends: str | None = None,
) -> Solution:
    """Area sampling (``method="area"``) or ``samples x samples`` supersampling of a
    ``line`` (``x1 y1 x2 y2``), a ``circle`` (``r [xc yc]``) or a ``polygon`` (``x1 y1 ...``);
    ``method="wu"``: Wu's line (:func:`wu_solution`, with its ``ends`` convention).

    >>> sol = antialias_solution("polygon", [0, 0, 2, 0, 2, 1, 0, 1])
    >>> [q.text for q in sol.derived][-2]
    'sum of I = 2 = the exact area of the shape'
    """
    L = check_levels(levels)
    if method == "wu":
        if shape != "line":
            raise InputError(f"wu draws lines only, not a {shape}", "method")
        return wu_solution(*_line_params(params), levels=L, ends=ends or "full")
    if ends is not None:
        raise InputError(f"the ends convention is Wu's line's, not {method}'s", "ends")
    if method not in ("area", "supersample"):
        raise InputError(f"unknown method {method!r} (choose from area, supersample, wu)", "method")
    n = cov.check_samples(samples) if method == "supersample" else 1
    check_rule(rule_name)
    if shape not in _REGIONS:
        raise InputError(f"unknown shape {shape!r} (choose from line, circle, polygon)", "shape")
    region = _REGIONS[shape](params, method, n, rule_name)
    values, title = region.values, region.title
    derived = [*region.derived, *_sampling_rules(method, n)]
    notes = list(region.notes)
    if method != "area" and shape != "circle":
        notes.append(
            "A sample is inside by the scan-line fill's rules (half-open spans and edges)."
        )
    derived += [_total(values, region.exact_total), _level_rule(L)]
    notes.append(SHADING)
    levels_of = {p: cov.quantize(v, L) for p, v in values.items()}
    order = list(values)
    picture = _picture({p: lv for p, lv in levels_of.items() if lv}, L)
    name = "Unweighted area sampling" if method == "area" else f"Supersampling {n} x {n}"
    return Solution(
        primitive=shape,
        algorithm=method,
        title=f"{name}: {title}, L = {L}",
        given=(
            Quantity("shape", shape, f"shape: {title}", f"\\text{{shape: {title}}}"),
            Quantity(
                "method", method, f"method: {name.lower()}", f"\\text{{method: {name.lower()}}}"
            ),
            worked("L", L, f"L = {L} \\text{{ levels}}"),
        ),
        derived=tuple(derived),
        notes=tuple(notes),
        tables=(_intensity_table(order, values, levels_of),),
        pixels=lambda: iter(order),
        bbox=_bbox(order),
        figures=(picture,) if picture else (),
        geometry={**region.geometry, "shades": levels_of, "levels": L, "numbering": "none"},
    )
