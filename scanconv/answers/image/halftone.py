"""The worked answer of a printer's halftone arithmetic: a printer of ``dpi`` dots per inch
printing a halftone screen of ``lpi`` lines (cells) per inch has cells of ``n = dpi / lpi`` dots
a side, and an n x n cell of bilevel dots gives ``n² + 1`` grey levels; and back, from the cell
or the levels wanted to the screen, or from the screen and the cell to the printer.

Conventions, named and settable (:data:`PRINTER_KNOBS`):

- ``count``: the levels of an n x n cell counted ``n2+1`` (0 to n² dots on: "(dpi / lpi)² + 1",
  as T. Autiokari's "Printing halftones" (aim-dtp.net) and Stanford CS248's 1996 midterm answer
  write it) or ``n2`` (the shades printed, PCMag's encyclopedia, "halftone": an 8 x 8 cell
  gives 64 shades);
- ``dots``: the cell ``whole`` (``n = floor(dpi / lpi)``: a cell holds whole dots) or
  ``exact`` (the ratio itself, as the formula is often applied).

Exact arithmetic throughout (Fractions), with every number substituted.
"""

from __future__ import annotations

from fractions import Fraction
from math import isqrt

from ...core.checks import InputError
from ...core.numeric import Number, fmt_short, normalize
from ...core.records import Quantity, Solution, Table, Walk, heading, worked

PRINTER_KNOBS: dict[str, tuple[str, ...]] = {
    "count": ("n2+1", "n2"),
    "dots": ("whole", "exact"),
}
"""Each convention of the printer arithmetic and its values, the default first."""

MAX_DPI = 10**6
"""The largest resolution (dots or lines per inch) worked."""

MAX_CELL = 4096
"""The largest halftone cell side worked (4096² + 1 levels)."""


def _knob(name: str, value: str) -> str:
    values = PRINTER_KNOBS[name]
    if value not in values:
        raise InputError(f"unknown {name} {value!r} (choose from {', '.join(values)})", name)
    return value


def _per_inch(v: Number | None, what: str, param: str) -> Fraction | None:
    if v is None:
        return None
    f = Fraction(v)
    if not 0 < f <= MAX_DPI:
        raise InputError(f"{what} must be in (0, {MAX_DPI:,}], got {fmt_short(v)}", param)
    return f


def _levels_of(n: Number, count: str) -> Number:
    return normalize(Fraction(n) ** 2 + (1 if count == "n2+1" else 0))


def _levels_text(n: Number, count: str) -> str:
    plus = " + 1" if count == "n2+1" else ""
    side = fmt_short(n) if n == int(n) else f"({fmt_short(n)})"
    return f"\\text{{levels}} = n^2{plus} = {side}^2{plus} = {fmt_short(_levels_of(n, count))}"


def _cell_for(levels: int, count: str) -> int:
    """The smallest whole cell giving at least ``levels`` levels."""
    need = levels - (1 if count == "n2+1" else 0)
    n = isqrt(need)
    return n if n * n >= need else n + 1


def _given(
    dpi: Fraction | None, lpi: Fraction | None, cell: int | None, levels: int | None
) -> tuple[Quantity, ...]:
    out = []
    if dpi is not None:
        out.append(
            worked("dpi", normalize(dpi), f"\\text{{printer: }} {fmt_short(dpi)} \\text{{ dpi}}")
        )
    if lpi is not None:
        out.append(
            worked("lpi", normalize(lpi), f"\\text{{screen: }} {fmt_short(lpi)} \\text{{ lpi}}")
        )
    if cell is not None:
        out.append(worked("n", cell, f"\\text{{cell: }} {cell} \\times {cell} \\text{{ dots}}"))
    if levels is not None:
        out.append(worked("L", levels, f"\\text{{levels wanted: }} {levels}"))
    return tuple(out)


def _check_given(
    dpi: Fraction | None, lpi: Fraction | None, cell: int | None, levels: int | None
) -> None:
    if cell is not None and levels is not None:
        raise InputError("give the cell or the levels, not both", "cell")
    if cell is not None and not 1 <= cell <= MAX_CELL:
        raise InputError(f"a cell is 1 .. {MAX_CELL} dots wide, got {cell}", "cell")
    if levels is not None and not 2 <= levels <= MAX_CELL**2:
        raise InputError(f"the levels must be 2 .. {MAX_CELL**2:,}, got {levels}", "levels")
    known = sum(v is not None for v in (dpi, lpi)) + (cell is not None or levels is not None)
    if known != 2:
        raise InputError(
            "give two of: the printer's dpi, the screen's lpi, the cell (or the levels)", "dpi"
        )


def _side(
    d: Fraction | None,
    ll: Fraction | None,
    cell: int | None,
    levels: int | None,
    count: str,
    dots: str,
) -> tuple[Number, list[Quantity]]:
    """The cell's side n (given, the smallest for the levels, or dpi / lpi) and its working."""
    derived: list[Quantity] = []
    n: Number
    if levels is not None:
        n = _cell_for(levels, count)
        plus = " - 1" if count == "n2+1" else ""
        derived.append(
            worked(
                "n",
                n,
                f"n = \\lceil \\sqrt{{L{plus}}} \\rceil = \\lceil \\sqrt{{{levels}{plus}}} "
                f"\\rceil = {n} \\text{{ dots (the smallest cell giving {levels} levels)}}",
            )
        )
    elif cell is not None:
        n = cell
    else:
        assert d is not None and ll is not None
        ratio = normalize(d / ll)
        n = ratio if dots == "exact" else int(d // ll)
        whole = (
            ""
            if dots == "exact" or n == ratio
            else f" \\to \\lfloor {fmt_short(ratio)} \\rfloor = {n}"
        )
        derived.append(
            worked(
                "n",
                n,
                f"n = \\text{{dpi}} / \\text{{lpi}} = {fmt_short(d)} / {fmt_short(ll)} = "
                f"{fmt_short(ratio)}{whole} \\text{{ dots}}",
            )
        )
        if n == 0:
            raise InputError(
                f"the screen ({fmt_short(ll)} lpi) is finer than the printer's dots", "lpi"
            )
    return n, derived


def printer_solution(
    dpi: Number | None = None,
    lpi: Number | None = None,
    *,
    cell: int | None = None,
    levels: int | None = None,
    count: str = "n2+1",
    dots: str = "whole",
) -> Solution:
    """A printer's halftone arithmetic from any two of the printer's ``dpi``, the screen's
    ``lpi`` and the cell's side ``cell`` (or the ``levels`` wanted).

    >>> sol = printer_solution(300, 60)
    >>> for q in sol.derived:
    ...     print(q.text)
    n = dpi / lpi = 300 / 60 = 5 dots
    levels = n² + 1 = 5² + 1 = 26
    cell size = 1 / lpi = 1/60 inch
    >>> printer_solution(300, levels=64, count="n2").data["lpi"]
    Fraction(75, 2)
    """
    _knob("count", count)
    _knob("dots", dots)
    d, ll = _per_inch(dpi, "the printer's dpi", "dpi"), _per_inch(lpi, "the screen's lpi", "lpi")
    _check_given(d, ll, cell, levels)
    n, derived = _side(d, ll, cell, levels, count, dots)
    derived.append(worked("levels", _levels_of(n, count), _levels_text(n, count)))
    if d is None:
        assert ll is not None
        d = ll * Fraction(n)
        derived.append(
            worked(
                "dpi",
                normalize(d),
                f"\\text{{dpi}} = \\text{{lpi}} \\times n = {fmt_short(ll)} \\times {fmt_short(n)} = "
                f"{fmt_short(d)}",
            )
        )
    elif ll is None:
        ll = d / Fraction(n)
        derived.append(
            worked(
                "lpi",
                normalize(ll),
                f"\\text{{lpi}} = \\text{{dpi}} / n = {fmt_short(d)} / {fmt_short(n)} = "
                f"{fmt_short(normalize(ll))}",
            )
        )
    derived.append(
        worked(
            "cell_inches",
            normalize(1 / ll),
            f"\\text{{cell size}} = 1 / \\text{{lpi}} = {fmt_short(normalize(1 / ll))} \\text{{ inch}}",
        )
    )
    notes = (
        f"Conventions: levels counted {count} ("
        + ("0 to n^2 dots on" if count == "n2+1" else "the n^2 shades with a dot on")
        + f"), the cell {dots} ("
        + ("floor(dpi / lpi): a cell holds whole dots" if dots == "whole" else "dpi / lpi itself")
        + ").",
        "A finer screen (more lpi) has smaller cells and fewer levels: spatial resolution is "
        "traded for intensity levels.",
    )
    data = {q.key: q.value for q in derived}
    data |= {"n": n, "dpi": normalize(d), "lpi": normalize(ll), "count": count, "dots": dots}
    rows = tuple((k, data[k]) for k in ("dpi", "lpi", "n", "levels"))
    table = Table(
        "Printer and screen",
        (heading("quantity", r"\text{quantity}"), heading("value", r"\text{value}")),
        lambda: rows,
    )
    return Solution(
        primitive="printer",
        algorithm="halftone",
        title="Halftone printing: printer, screen and cell",
        given=_given(_per_inch(dpi, "", "dpi"), _per_inch(lpi, "", "lpi"), cell, levels),
        derived=tuple(derived),
        notes=notes,
        walk=Walk(tables=(table,)),
        data=data,
    )
