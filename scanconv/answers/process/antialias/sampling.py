"""The worked answers of anti-aliasing: Xiaolin Wu's line (a step table of the two pixels and
their intensities) and area sampling or supersampling of a line, a circle or a polygon (an
intensity table and a shaded picture)."""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
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
    from . import subpixel
else:
    subpixel = lazy.module("scanconv.answers.process.antialias.subpixel")

__all__ = ["antialias_solution", "wu_solution"]


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


def _coverage(
    pts: Sequence[tuple[Number, Number]], method: str, n: int, rule_name: str
) -> tuple[dict[Pixel, Any], Number | None]:
    if method == "area":
        return dict(cov.area_coverage(pts, rule_name)), cov.region_area(pts, rule_name)
    return dict(cov.supersample_coverage(pts, n, rule_name)), None


def _line_region(
    params: Sequence[Number], method: str, n: int, rule_name: str, width: Number, across: str
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
    values, exact = _coverage(pts, method, n, rule_name)
    if not exact_length and method == "area":  # samples are counted exactly either way
        values, exact = {p: float(v) for p, v in values.items()}, None
    return _Region(
        title, values, exact, strip, [f"{named}: {note[0].lower()}{note[1:]}"],
        (IdealLine(x1, y1, x2, y2),),
    )  # fmt: skip


def _polygon_region(params: Sequence[Number], method: str, n: int, rule_name: str) -> _Region:
    pts, _ = check_polygon(vertices_from_coords(params))
    ideal = (Polyline([(float(x), float(y)) for x, y in (*pts, pts[0])], "polygon"),)
    values, exact = _coverage(pts, method, n, rule_name)
    title = f"polygon of {len(pts)} vertices ({rule_name} rule)"
    return _Region(title, values, exact, [], [], ideal)


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
    return _Region(title, values, None, [ring], notes, (IdealCircle(xc, yc, r),))


_REGIONS = {"polygon": _polygon_region, "circle": _circle_region}


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


def _line_method(
    shape: str, params: Sequence[Number], method: str, samples: int | None, L: int,
    ends: str | None, width: Number, across: str, subgrid: str | None, divide: str | None,
) -> Solution | None:  # fmt: skip
    """The answer of a line-only method (``subpixel``, ``wu``), else ``None``; a convention
    given to a method it is not of is refused by name."""
    if method == "subpixel":
        if shape != "line":
            raise InputError(f"subpixel supersamples lines only, not a {shape}", "method")
        if ends is not None or (width, across) != (1, "minor"):
            raise InputError(
                "the sub-pixel line is Bresenham's: no ends, width or across", "method"
            )
        return subpixel.subpixel_solution(
            *_line_params(params),
            n=3 if samples is None else samples,
            levels=L,
            subgrid=subgrid or "span",
            divide=divide or "n",
        )
    for name, value in (("divide", divide), ("subgrid", subgrid)):
        if value is not None:
            raise InputError(
                f"the {name} convention is the subpixel method's, not {method}'s", name
            )
    if method == "wu":
        if shape != "line":
            raise InputError(f"wu draws lines only, not a {shape}", "method")
        if (width, across) != (1, "minor"):
            raise InputError("Wu's line is one pixel wide: no width or across convention", "width")
        return wu_solution(*_line_params(params), levels=L, ends=ends or "full")
    if ends is not None:
        raise InputError(f"the ends convention is Wu's line's, not {method}'s", "ends")
    if across not in cov.ACROSS:
        raise InputError(
            f"unknown across {across!r} (choose from {', '.join(cov.ACROSS)})", "across"
        )
    return None  # fmt: skip


def _region(
    shape: str, params: Sequence[Number], method: str, n: int, rule_name: str, width: Number,
    across: str,
) -> _Region:  # fmt: skip
    """The shape to sample; a width and its convention only for a line."""
    if shape not in ("line", *_REGIONS):
        raise InputError(f"unknown shape {shape!r} (choose from line, circle, polygon)", "shape")
    if shape == "line":
        return _line_region(params, method, n, rule_name, width, across)
    if (width, across) != (1, "minor"):
        raise InputError(
            f"a width and its across convention are a line's, not a {shape}'s", "width"
        )
    return _REGIONS[shape](params, method, n, rule_name)


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
    defaults to 4 for ``supersample``.

    >>> sol = antialias_solution("polygon", [0, 0, 2, 0, 2, 1, 0, 1])
    >>> [q.text for q in sol.derived][-2]
    'sum of I = 2 = the exact area of the shape'
    """
    L = check_levels(levels)
    line_only = _line_method(
        shape, params, method, samples, L, ends, width, across, subgrid, divide
    )
    if line_only is not None:
        return line_only
    samples = 4 if samples is None else samples
    if method not in ("area", "supersample"):
        raise InputError(
            f"unknown method {method!r} (choose from area, supersample, wu, subpixel)", "method"
        )
    n = cov.check_samples(samples) if method == "supersample" else 1
    check_rule(rule_name)
    region = _region(shape, params, method, n, rule_name, width, across)
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
        sol.data = {**sol.data, "conventions": {"across": across}, "width": width}
    return sol
