"""The work budget of a command, checked before the command does any work.

:func:`check` estimates, from the command's arguments alone, how many rows (step tables) or
cells (matrices) its answer prints, and refuses the request at once when that is beyond the
budget of the output format (:mod:`scanconv.render.budget`): one line naming the size, the
format's limit and the formats that would print it, as options of this command line
(``use --format plain, csv or json``). The estimates only need to be close (an ellipse's rows
are counted from its region boundary); an argument the estimate cannot read is left to the
command's own validation.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from fractions import Fraction
from typing import Any

from ..core.numeric import COORD_LIMIT
from ..render import Format
from .output import Output, format_for_file, resolve

Work = tuple[str, int, int | None]
"""``("rows", rows, None)`` for a step table, ``("matrix", m, n)`` for a matrix."""


def _num(v: Any) -> Fraction:
    return Fraction(v)


def _line_rows(a: Mapping[str, Any], names: tuple[str, str, str, str]) -> int:
    x1, y1, x2, y2 = (_num(a[k]) for k in names)
    return math.ceil(max(abs(x2 - x1), abs(y2 - y1))) + 1


def _line(a: Mapping[str, Any]) -> Work:
    return ("rows", _line_rows(a, ("x1", "y1", "x2", "y2")), None)


def _circle(a: Mapping[str, Any]) -> Work:
    # one octant: x runs from 0 to r/sqrt(2)
    return ("rows", math.ceil(abs(_num(a["r"])) / math.sqrt(2)) + 1, None)


def _ellipse(a: Mapping[str, Any]) -> Work:
    # region 1 ends where the slope is -1, at x = rx^2 / sqrt(rx^2 + ry^2); region 2 has about
    # ry^2 / sqrt(rx^2 + ry^2) steps (ellipse 20000 20000: 28,285 rows)
    rx, ry = abs(float(_num(a["rx"]))), abs(float(_num(a["ry"])))
    h = math.hypot(rx, ry) or 1.0
    return ("rows", math.ceil((rx * rx + ry * ry) / h) + 2, None)


def _samples(default: int = 16) -> Callable[[Mapping[str, Any]], Work]:
    def rows(a: Mapping[str, Any]) -> Work:
        n = a.get("samples")
        return ("rows", (default if n is None else int(n)) + 1, None)

    return rows


def _parametric_line(a: Mapping[str, Any]) -> Work:
    n = a.get("samples")
    if n is None:
        return ("rows", _line_rows(a, ("x0", "y0", "x1", "y1")), None)
    return ("rows", int(n) + 1, None)


def _polygon(a: Mapping[str, Any]) -> Work:
    # one row per scan line of the vertices' y extent (and a few for the edge table)
    ys = [_num(v) for v in list(a["vertices"])[1::2]]
    return ("rows", math.ceil(max(ys) - min(ys)) + 1, None)


def _quantize(a: Mapping[str, Any]) -> Work:
    bits = int(_num(a["bits"]))
    return ("rows", 1 << bits if 0 < bits <= 64 else 0, None)


def _matrix(default: str | None = None) -> Callable[[Mapping[str, Any]], Work]:
    def cells(a: Mapping[str, Any]) -> Work:
        from ..algorithms.image_limits import parse_size

        m, n = parse_size(a.get("size") or default or "")
        return ("matrix", m, n)

    return cells


ESTIMATES: dict[str, Callable[[Mapping[str, Any]], Work]] = {
    "line": _line,
    "circle": _circle,
    "ellipse": _ellipse,
    "compare_line": _line,
    "quantize": _quantize,
    "polygon": _polygon,
    "sample": _matrix(),
    "image_ramp": _matrix("8"),
    "parametric_circle": _samples(),
    "parametric_ellipse": _samples(),
    "parametric_parabola": _samples(),
    "parametric_custom": _samples(),
    "parametric_line": _parametric_line,
    "bezier": _samples(),
    "bspline": _samples(),
    "continuity": _samples(),
    "local_control": _samples(),
}
"""How the size of each command's answer is estimated, by the command function's name."""

#: How a budget refusal's formats are written on this command line.
_FLAGS = {"csv": "csv", "json": "json", "plain": "plain", "markdown": "markdown"}


def estimate(name: str, arguments: Mapping[str, Any]) -> Work | None:
    """The size of the answer of command ``name`` for ``arguments``, or ``None`` if unknown.

    >>> estimate("sample", {"size": "4096"})
    ('matrix', 4096, 4096)
    >>> estimate("ellipse", {"rx": 20000, "ry": 20000})
    ('rows', 28287, None)
    >>> estimate("line", {"x1": "junk"}) is None
    True
    """
    how = ESTIMATES.get(name)
    if how is None:
        return None
    try:
        return how(arguments)
    except (ArithmeticError, KeyError, TypeError, ValueError):  # the command refuses it itself
        return None


LONG_TABLES = {"quantize"}
"""Commands whose table may pass :data:`~scanconv.render.budget.ALL_ROWS` (in csv and json):
``quantize --bits 24`` is 2^24 rows, and those rows are the answer. With ``--range`` each row
carries exact fractions, three times slower: that table keeps the budget of every format."""


def _bare(arguments: Mapping[str, Any]) -> bool:
    """True for a quantizer's table without ``--range`` (integers and names only)."""
    return not arguments.get("value_range")


def check(name: str, arguments: Mapping[str, Any], out: Output) -> None:
    """Refuse (``ValueError``, one line) a request beyond its output format's budget.

    >>> check("sample", {"size": "4096"}, Output(fmt=Format.latex))
    Traceback (most recent call last):
    ...
    ValueError: a 4096 x 4096 matrix is 16,777,216 cells; the rich, latex and markdown formats print at most 65,536: use --format csv or json
    >>> check("sample", {"size": "4096"}, Output(fmt=Format.csv))
    """
    if name not in ESTIMATES:
        return
    fmt = resolve(format_for_file(out.fmt, out.output), out.output is not None)
    work = estimate(name, arguments)
    if work is None:
        return
    if fmt in (Format.csv, Format.json, Format.html) and work[0] != "rows":
        return  # matrices: streamed, or cut by the page itself
    from ..render.budget import BudgetError, check_matrix, check_rows

    kind, a, b = work
    if kind == "matrix" and b is not None:
        from ..algorithms.image_limits import MAX_CELLS

        if a * b > MAX_CELLS:
            return  # beyond the input limit: the command refuses it, naming that limit
    if kind == "rows" and a > 2 * COORD_LIMIT + 1:
        return
    try:
        if kind == "matrix" and b is not None:
            check_matrix(a, b, fmt)
        elif name in LONG_TABLES and fmt in (Format.csv, Format.json) and _bare(arguments):
            return  # a quantizer's 2^24 rows are what was asked for (docs/limits.md)
        else:
            check_rows(a, fmt, every_format=not (name in LONG_TABLES and _bare(arguments)))
    except BudgetError as err:
        if err.ways == ("raster",):
            hint = (
                "; for the pixels alone use scanconv.raster in Python (docs/library-numpy.md)"
                if name in ("line", "circle")
                else ""
            )
            raise ValueError(f"{err}{hint}") from None
        ways = [_FLAGS.get(w, w) for w in err.ways]
        words = ways[0] if len(ways) == 1 else ", ".join(ways[:-1]) + " or " + ways[-1]
        raise ValueError(f"{err}: use --format {words}") from None
