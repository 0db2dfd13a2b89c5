"""The worked answers of anti-aliasing: Xiaolin Wu's line (a step table of the two pixels and
their intensities) and area sampling or supersampling of a line, a circle or a polygon (an
intensity table and a shaded picture)."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any, NamedTuple

from ....algorithms import coverage as cov
from ....algorithms.image_limits import check_levels
from ....algorithms.polygon import check_polygon, check_rule, vertices_from_coords
from ....core import lazy
from ....core.checks import InputError, check_integer
from ....core.ideal import Ideal, IdealCircle, IdealLine, Polyline
from ....core.numeric import Number, fmt_exact, fmt_short, normalize
from ....core.records import (
    Pixel,
    Plot,
    Quantity,
    Solution,
    Table,
    Walk,
    heading,
    rule,
    worked,
)
from ._shared import SHADING
from ._shared import level_rule as _level_rule
from ._shared import picture as _picture
from ._shared import pixel_box as _bbox
from .wu import wu_solution

if TYPE_CHECKING:
    from ... import methods
    from . import subpixel
else:
    methods = lazy.module("scanconv.answers.methods")
    subpixel = lazy.module("scanconv.answers.process.antialias.subpixel")

__all__ = ["Antialiased", "antialias_solution", "wu_solution"]


class Antialiased(NamedTuple):
    """An anti-aliasing question, as each method's answer (its record's ``answer``) takes it:
    the shape and its numbers, the levels (checked), and the conventions, ``None`` where not
    given."""

    shape: str
    params: Sequence[Number]
    levels: int
    samples: int | None = None
    rule_name: str = "even-odd"
    ends: str | None = None
    width: Number = 1
    across: str = "minor"
    subgrid: str | None = None
    divide: str | None = None


class _Sampler(NamedTuple):
    """How area sampling or supersampling finds a pixel's intensity: its name in the answer,
    the samples a side (1: the area itself), whether the values are counts of samples (exact
    whatever the shape) or areas, and the coverage of a polygon and of a circle's ring."""

    method: str
    name: str
    n: int
    counts: bool
    coverage: Callable[
        [Sequence[tuple[Number, Number]], str], tuple[dict[Pixel, Any], Number | None]
    ]
    ring: Callable[[int, int, int], dict[Pixel, Any]]
    ring_notes: tuple[str, ...]
    rules: tuple[Quantity, ...]


def _area() -> _Sampler:
    def coverage(
        pts: Sequence[tuple[Number, Number]], rule_name: str
    ) -> tuple[dict[Pixel, Any], Number | None]:
        return dict(cov.area_coverage(pts, rule_name)), cov.region_area(pts, rule_name)

    intensity = rule(
        "intensity",
        r"I(i, j) = \text{area of the shape inside } [i - 1/2, i + 1/2] \times [j - 1/2, j + 1/2]",
    )
    ring_note = (
        "A circle's covered areas involve arcsin: they are computed in floating point "
        "from the closed form (the ring's total is π((r + 1/2)² - (r - 1/2)²) = 2π·r)."
    )
    return _Sampler(
        "area", "Unweighted area sampling", 1, False, coverage,
        lambda r, xc, yc: dict(cov.ring_area(r, xc, yc)), (ring_note,), (intensity,),
    )  # fmt: skip


def _supersample(n: int) -> _Sampler:
    def coverage(
        pts: Sequence[tuple[Number, Number]], rule_name: str
    ) -> tuple[dict[Pixel, Any], Number | None]:
        return dict(cov.supersample_coverage(pts, n, rule_name)), None

    rules = (
        rule(
            "samples",
            f"{n} \\times {n} = {n * n} \\text{{ samples per pixel, at }} (i - 1/2 + (2a + 1)/{2 * n},\\ "
            f"j - 1/2 + (2b + 1)/{2 * n}),\\ a, b = 0 \\ldots {n - 1}",
        ),
        rule("intensity", f"I = \\text{{samples inside}} / {n * n}"),
    )
    return _Sampler(
        "supersample", f"Supersampling {n} x {n}", n, True, coverage,
        lambda r, xc, yc: dict(cov.ring_supersample(r, n, xc, yc)), (), rules,
    )  # fmt: skip


class _Region(NamedTuple):
    """A shape to sample: its title, pixel values, exact area (if known) and its working."""

    title: str
    values: dict[Pixel, Any]
    exact_total: Number | None
    derived: list[Quantity]
    notes: list[str]
    ideal: tuple[Ideal, ...]


def _line_params(params: Sequence[Number]) -> tuple[Number, Number, Number, Number]:
    if len(params) != 4:
        raise InputError(f"a line needs x1 y1 x2 y2, got {len(params)} numbers", "line")
    x1, y1, x2, y2 = (normalize(v) for v in params)
    return x1, y1, x2, y2


def _line_region(
    params: Sequence[Number], sampler: _Sampler, rule_name: str, width: Number, across: str
) -> _Region:
    x1, y1, x2, y2 = _line_params(params)
    pts = cov.line_strip(x1, y1, x2, y2, width, across)
    dx, dy = Fraction(x2 - x1), Fraction(y2 - y1)
    minor = "y" if abs(dy) <= abs(dx) else "x"
    corners = ", ".join(f"({fmt_short(x)}, {fmt_short(y)})" for x, y in pts)
    wide = "one pixel" if width == 1 else f"{fmt_short(width)} pixels"
    exact_length = across == "minor" or cov.exact_sqrt(dx * dx + dy * dy) is not None
    if across == "minor":
        strip = [worked("strip", pts, f"\\text{{line {wide} wide along }} {minor}: {corners}")]
        note = (
            f"The line is the parallelogram {wide} thick along {minor}, from end point to "
            f"end point: exact, and each column along the line is covered by "
            f"{fmt_short(width)} in total."
        )
    else:
        length = cov.exact_sqrt(dx * dx + dy * dy)
        shown = (
            fmt_short(length)
            if length is not None
            else f"{math.sqrt(float(dx * dx + dy * dy)):.4f}"
        )
        at = [
            f"({fmt_short(x)}, {fmt_short(y)})" if exact_length else f"({float(x):.4f}, {float(y):.4f})"
            for x, y in pts
        ]  # fmt: skip
        strip = [  # one line per end: four points with decimals overrun a printed line
            worked(
                "length",
                length if length is not None else math.sqrt(float(dx * dx + dy * dy)),
                f"L = \\sqrt{{{fmt_short(dx)}^2 + {fmt_short(dy)}^2}} "
                + ("= " if exact_length else "\\approx ")
                + f"{shown},\\ n = (-\\Delta y, \\Delta x)/L",
            ),
            worked(
                "strip",
                pts if exact_length else tuple((float(x), float(y)) for x, y in pts),
                f"\\text{{corners }} P_1 \\pm (w/2) n: {at[0]}, {at[3]}",
            ),
            worked("strip_end", (), f"\\text{{corners }} P_2 \\pm (w/2) n: {at[1]}, {at[2]}"),
        ]
        note = (
            f"The line is the rectangle {wide} wide measured perpendicular to it, its ends cut "
            "square at the end points: its area is w·L"
            + (
                ", exact."
                if exact_length
                else "; L is irrational, so the corners are the nearest doubles and the "
                "intensities floats."
            )
        )
    named = (
        f"Width (across = {across}"
        + (", the default; across = perpendicular measures it square to the line)"
           if across == "minor" else "; the default is across = minor, along the minor axis)")
    )  # fmt: skip
    title = f"line ({fmt_short(x1)}, {fmt_short(y1)}) to ({fmt_short(x2)}, {fmt_short(y2)})"
    if width != 1:
        title += f", width {fmt_short(width)}"
    values, exact = sampler.coverage(pts, rule_name)
    if not exact_length and not sampler.counts:  # samples are counted exactly either way
        values, exact = {p: float(v) for p, v in values.items()}, None
    return _Region(
        title, values, exact, strip, [f"{named}: {note[0].lower()}{note[1:]}"],
        (IdealLine(x1, y1, x2, y2),),
    )  # fmt: skip


def _polygon_region(params: Sequence[Number], sampler: _Sampler, rule_name: str) -> _Region:
    pts, _ = check_polygon(vertices_from_coords(params))
    ideal = (Polyline([(float(x), float(y)) for x, y in (*pts, pts[0])], "polygon"),)
    values, exact = sampler.coverage(pts, rule_name)
    title = f"polygon of {len(pts)} vertices ({rule_name} rule)"
    return _Region(title, values, exact, [], [], ideal)


def _circle_region(params: Sequence[Number], sampler: _Sampler, rule_name: str) -> _Region:
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
    values = sampler.ring(r, xc, yc)
    notes = list(sampler.ring_notes)
    title = f"circle r = {r}, centre ({xc}, {yc}), one pixel wide"
    return _Region(title, values, None, [ring], notes, (IdealCircle(xc, yc, r),))


_REGIONS = {"polygon": _polygon_region, "circle": _circle_region}


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


def _no_subpixel_conventions(q: Antialiased, method: str) -> None:
    for name, value in (("divide", q.divide), ("subgrid", q.subgrid)):
        if value is not None:
            raise InputError(
                f"the {name} convention is the subpixel method's, not {method}'s", name
            )


def subpixel_answer(q: Antialiased) -> Solution:
    """Hearn & Baker's supersampling of a line: Bresenham on the sub-pixel grid."""
    if q.shape != "line":
        raise InputError(f"subpixel supersamples lines only, not a {q.shape}", "method")
    if q.ends is not None or (q.width, q.across) != (1, "minor"):
        raise InputError("the sub-pixel line is Bresenham's: no ends, width or across", "method")
    return subpixel.subpixel_solution(
        *_line_params(q.params),
        n=3 if q.samples is None else q.samples,
        levels=q.levels,
        subgrid=q.subgrid or "span",
        divide=q.divide or "n",
    )


def wu_answer(q: Antialiased) -> Solution:
    """Xiaolin Wu's line (:func:`wu_solution`, with its ``ends`` convention)."""
    _no_subpixel_conventions(q, "wu")
    if q.shape != "line":
        raise InputError(f"wu draws lines only, not a {q.shape}", "method")
    if (q.width, q.across) != (1, "minor"):
        raise InputError("Wu's line is one pixel wide: no width or across convention", "width")
    return wu_solution(*_line_params(q.params), levels=q.levels, ends=q.ends or "full")


def area_answer(q: Antialiased) -> Solution:
    """Unweighted area sampling: each pixel's intensity the area of the shape in it."""
    _sampling_conventions(q, "area")
    return _sampled(q, _area())


def supersample_answer(q: Antialiased) -> Solution:
    """``samples x samples`` supersampling (4 by default): the samples inside, counted."""
    _sampling_conventions(q, "supersample")
    return _sampled(q, _supersample(cov.check_samples(4 if q.samples is None else q.samples)))


def _sampling_conventions(q: Antialiased, method: str) -> None:
    """Refuse the line-only methods' conventions and an unknown ``across``."""
    _no_subpixel_conventions(q, method)
    if q.ends is not None:
        raise InputError(f"the ends convention is Wu's line's, not {method}'s", "ends")
    if q.across not in cov.ACROSS:
        raise InputError(
            f"unknown across {q.across!r} (choose from {', '.join(cov.ACROSS)})", "across"
        )


def _region(q: Antialiased, sampler: _Sampler) -> _Region:
    """The shape to sample; a width and its convention only for a line."""
    shape = q.shape
    if shape not in ("line", *_REGIONS):
        raise InputError(f"unknown shape {shape!r} (choose from line, circle, polygon)", "shape")
    if shape == "line":
        return _line_region(q.params, sampler, q.rule_name, q.width, q.across)
    if (q.width, q.across) != (1, "minor"):
        raise InputError(
            f"a width and its across convention are a line's, not a {shape}'s", "width"
        )
    return _REGIONS[shape](q.params, sampler, q.rule_name)


def antialias_solution(
    shape: str,
    params: Sequence[Number],
    *,
    method: str = "area",
    samples: int | None = None,
    levels: int = 8,
    rule_name: str = "even-odd",
    ends: str | None = None,
    width: Number = 1,
    across: str = "minor",
    subgrid: str | None = None,
    divide: str | None = None,
) -> Solution:
    """Area sampling (``method="area"``) or ``samples x samples`` supersampling of a
    ``line`` (``x1 y1 x2 y2``), a ``circle`` (``r [xc yc]``) or a ``polygon`` (``x1 y1 ...``);
    ``method="wu"``: Wu's line (:func:`wu_solution`, with its ``ends`` convention);
    ``method="subpixel"``: Hearn & Baker's supersampling of a line, Bresenham on the
    ``samples x samples`` sub-pixel grid (3 by default; ``subgrid`` convention). ``samples``
    defaults to 4 for ``supersample``. Each method's answer is its record's.

    >>> sol = antialias_solution("polygon", [0, 0, 2, 0, 2, 1, 0, 1])
    >>> [q.text for q in sol.derived][-2]
    'sum of I = 2 = the exact area of the shape'
    """
    L = check_levels(levels)
    names = methods.methods_of("antialias")
    if method not in names:
        raise InputError(f"unknown method {method!r} (choose from {', '.join(names)})", "method")
    q = Antialiased(shape, params, L, samples, rule_name, ends, width, across, subgrid, divide)
    return methods.method("antialias", method).load("answer")(q)  # type: ignore[no-any-return]


def _sampled(q: Antialiased, sampler: _Sampler) -> Solution:
    """The answer of area sampling or supersampling: the intensity table and the picture."""
    shape, L, width = q.shape, q.levels, q.width
    check_rule(q.rule_name)
    region = _region(q, sampler)
    values, title = region.values, region.title
    derived = [*region.derived, *sampler.rules]
    notes = list(region.notes)
    if sampler.counts and shape != "circle":
        notes.append(
            "A sample is inside by the scan-line fill's rules (half-open spans and edges)."
        )
    derived += [_total(values, region.exact_total), _level_rule(L)]
    notes.append(SHADING)
    levels_of = {p: cov.quantize(v, L) for p, v in values.items()}
    order = list(values)
    picture = _picture({p: lv for p, lv in levels_of.items() if lv}, L)
    name, method = sampler.name, sampler.method
    drawn = title.split(", width ")[0]  # the width is given on its own (a line of print)
    sol = Solution(
        primitive=shape,
        algorithm=method,
        title=f"{name}: {title}, L = {L}",
        given=(
            Quantity("shape", shape, f"shape: {drawn}", f"\\text{{shape: {drawn}}}"),
            Quantity(
                "method", method, f"method: {name.lower()}", f"\\text{{method: {name.lower()}}}"
            ),
            worked("L", L, f"L = {L} \\text{{ levels}}"),
            *((worked("w", width, f"w = {fmt_short(width)}"),) if width != 1 else ()),
        ),
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(tables=(_intensity_table(order, values, levels_of),)),
        plot=Plot(
            pixels=lambda: iter(order),
            bbox=_bbox(order),
            figures=(picture,) if picture else (),
            ideal=region.ideal,
            shades=levels_of,
            levels=L,
            numbering="none",
        ),
    )
    if shape == "line":
        sol.data = {**sol.data, "conventions": {"across": q.across}, "width": width}
    return sol
