"""The Python API: what the functions take (the number, point and choice types) and how they read it. See :mod:`scanconv._api`."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from enum import Enum
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..core import lazy
from ..core.checks import InputError
from ..core.numeric import COORD_LIMIT, Number, fmt_short, parse_number

if TYPE_CHECKING:
    from ..algorithms import bspline, curve_limits, image_limits
    from ..core import expr
else:
    bspline = lazy.module("scanconv.algorithms.bspline")
    curve_limits = lazy.module("scanconv.algorithms.curve_limits")
    image_limits = lazy.module("scanconv.algorithms.image_limits")
    expr = lazy.module("scanconv.core.expr")

if TYPE_CHECKING:
    from decimal import Decimal

    import numpy as np


if TYPE_CHECKING:
    NumberLike = int | Fraction | float | Decimal | str | np.integer[Any] | np.floating[Any]
else:  # decimal is imported only by callers that pass a Decimal (start-up time)
    NumberLike = int | Fraction | float | str
"""What a number parameter takes: an int, Fraction, float, decimal.Decimal, numpy scalar or
string."""

PointLike = tuple[NumberLike, NumberLike]
"""A point ``(x, y)``."""

PointsLike = Sequence[PointLike] | Sequence[NumberLike]
"""Control points: ``[(x0, y0), (x1, y1), ...]`` or flat, ``[x0, y0, x1, y1, ...]``."""

FormulaLike = NumberLike
"""A number, or a constant expression in a string (``"2*pi"``, ``"1/3"``)."""

TRangeLike = tuple[FormulaLike, FormulaLike]
"""The range of a curve's parameter t: two formulas (``(0, "2*pi")``)."""


def _number(value: NumberLike, param: str) -> Number:
    """An exact number within :data:`~scanconv.core.numeric.COORD_LIMIT`, as the command line
    reads one: an ``int``, a numpy integer or a ``Fraction`` as given; a ``float`` (numpy's
    too) as the decimal it prints as; a ``Decimal`` or a string through
    :func:`~scanconv.core.numeric.parse_number`. NaN and infinities are refused.

    >>> _number(Fraction(5, 2), "x"), _number(2.5, "x"), _number("-3", "x")
    (Fraction(5, 2), Fraction(5, 2), Fraction(-3, 1))
    """
    import numbers

    if isinstance(value, bool):
        raise InputError(f"{param} must be a number, got {value!r}", param)
    if isinstance(value, int | Fraction):
        if not -COORD_LIMIT <= value <= COORD_LIMIT:
            raise InputError(
                f"{param} = {value} is out of range (|value| <= {COORD_LIMIT:.0e})", param
            )
        return value
    decimal = sys.modules.get("decimal")  # a Decimal exists only if its module is loaded
    if isinstance(value, numbers.Integral):  # numpy's integers
        return _number(int(value), param)
    if isinstance(value, float) or (
        isinstance(value, numbers.Real) and not isinstance(value, numbers.Rational)
    ):  # numpy's floats too, whose repr is np.float64(2.5)
        text = repr(float(value))
    elif decimal is not None and isinstance(value, decimal.Decimal):
        text = str(value)
    elif isinstance(value, str):
        text = value
    else:
        raise InputError(f"{param} must be a number, got {value!r}", param)
    try:
        return parse_number(text)
    except ValueError as err:
        raise InputError(str(err), param) from None


def _numbers(**values: NumberLike) -> tuple[Number, ...]:
    return tuple(_number(v, name) for name, v in values.items())


def _optional(value: NumberLike | None, param: str) -> Number | None:
    return None if value is None else _number(value, param)


def _whole(value: NumberLike, param: str) -> int:
    v = _number(value, param)
    if isinstance(v, Fraction):
        if v.denominator != 1:
            raise InputError(f"{param} must be an integer, got {fmt_short(v)}", param)
        return v.numerator
    return v


def _pair(values: Sequence[NumberLike], param: str) -> tuple[Number, Number]:
    """A point or a range: two numbers."""
    if isinstance(values, str) or len(values) != 2:
        raise InputError(f"{param} takes 2 numbers, got {values!r}", param)
    return _number(values[0], param), _number(values[1], param)


def _formula(value: FormulaLike, param: str) -> Any:
    """A value of a parameter such as ``t``: a number, or a constant expression (exact when it
    is rational; ``"pi/4"`` is a float)."""
    if isinstance(value, str):
        try:
            parsed: Any = expr.parse_exact(value)
        except ValueError as err:
            raise InputError(str(err), param) from None
    else:
        parsed = _number(value, param)
    if isinstance(parsed, Fraction) and parsed.denominator == 1:
        return parsed.numerator
    return parsed


def _formulas(values: Sequence[FormulaLike], param: str, count: int) -> tuple[Any, ...]:
    """``domain`` and ``value_range`` of :func:`sample`: numbers or constant expressions."""
    if isinstance(values, str) or len(values) != count:
        raise InputError(f"{param} takes {count} values, got {values!r}", param)
    out = []
    for v in values:
        try:
            out.append(expr.parse_exact(v) if isinstance(v, str) else _number(v, param))
        except ValueError as err:
            raise InputError(str(err), param) from None
    return tuple(out)


def _bounds(values: TRangeLike) -> tuple[Any, Any]:
    """``t_range``: formulas stay text, for the answer to show them as given (``2π``)."""
    if isinstance(values, str) or len(values) != 2:
        raise InputError(f"t_range takes 2 values, got {values!r}", "t_range")
    lo, hi = (v if isinstance(v, str) else _number(v, "t_range") for v in values)
    return lo, hi


def _points(values: PointsLike, param: str = "points") -> list[Any]:
    """Control points, as pairs or flat, as the library's exact pairs."""
    flat: list[Any] = []
    for v in values:
        if not isinstance(v, tuple | list):
            flat.append(v)
        elif len(v) == 2:
            flat.extend(v)
        else:
            raise InputError(f"a point is a pair (x, y), got {v!r}", param)
    try:
        return curve_limits.pairs([_number(v, param) for v in flat])
    except InputError:
        raise
    except ValueError as err:
        raise InputError(str(err), param) from None


def _knots(value: str | Sequence[NumberLike]) -> str | tuple[Number, ...]:
    if not isinstance(value, str):
        return tuple(_number(v, "knots") for v in value)
    try:
        return bspline.parse_knots(value)
    except ValueError as err:
        raise InputError(str(err), "knots") from None


def _size(value: str | int | tuple[int, int]) -> tuple[int, int]:
    if isinstance(value, str):
        try:
            return image_limits.parse_size(value)
        except ValueError as err:
            raise InputError(str(err), "size") from None
    if isinstance(value, tuple):
        m, n = value
        return _whole(m, "size"), _whole(n, "size")
    side = _whole(value, "size")
    return side, side


def _maybe(value: Enum | str | None, param: str) -> str | None:
    """:func:`_choice`, or ``None`` for a convention left to the preset or default."""
    return None if value is None else _choice(value, param)


def _choice(value: Enum | str, param: str) -> str:
    """A choice as the library's string (an enum member's value)."""
    if isinstance(value, Enum):
        return str(value.value)
    if isinstance(value, str):
        return value
    raise InputError(f"{param} must be a string, got {value!r}", param)


def _rect(values: Sequence[NumberLike], param: str) -> tuple[Number, ...]:
    """A window or viewport: four numbers ``(xmin, ymin, xmax, ymax)``."""
    if isinstance(values, str) or len(values) != 4:
        raise InputError(f"{param} takes 4 numbers (xmin ymin xmax ymax), got {values!r}", param)
    return tuple(_number(v, param) for v in values)


def _flat(values: PointsLike, param: str) -> list[Number]:
    """Points as pairs or flat, as a flat list of exact numbers (the library pairs them)."""
    flat: list[Any] = []
    for v in values:
        if not isinstance(v, tuple | list):
            flat.append(v)
        elif len(v) == 2:
            flat.extend(v)
        else:
            raise InputError(f"a point is a pair (x, y), got {v!r}", param)
    return [_number(v, param) for v in flat]
