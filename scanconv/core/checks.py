"""Input checks shared by every layer above, and the error they raise.

A library error names the *parameter* (``radius``, ``rounding``), never a command-line flag:
the CLI maps :attr:`InputError.param` to its own option names.
"""

from __future__ import annotations

from .numeric import COORD_LIMIT, Number, as_int, normalize


class InputError(ValueError):
    """Bad input to a library function: the message, and the parameter it is about."""

    def __init__(self, message: str, param: str | None = None) -> None:
        super().__init__(message)
        self.param = param
        """The parameter's name in the library's signature (``None``: no single one)."""


def looks_like_option(text: str) -> bool:
    """``-x``, ``--bogus``: an option name where a number was expected (``-3``, ``-.5`` and
    ``-inf`` are values, the last refused as not finite)."""
    s = text.strip()
    return (
        s.startswith("-")
        and not s[1:2].isdigit()
        and s[1:2] != "."
        and s.lstrip("-").lower() not in ("nan", "inf", "infinity")
    )


def check_integer(
    value: Number, what: str, *, negative: bool = True, param: str | None = None
) -> int:
    """``value`` as an int within :data:`~scanconv.core.numeric.COORD_LIMIT`, or
    :class:`InputError` naming ``what`` (about ``param``).

    >>> from fractions import Fraction
    >>> check_integer(Fraction(-3), "xc")
    -3
    >>> check_integer(-1, "radius", negative=False, param="r")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: radius must be a non-negative integer, got -1
    """
    try:
        v = as_int(normalize(value), what)
    except ValueError as err:
        raise InputError(str(err), param) from None
    if not negative and v < 0:
        raise InputError(f"{what} must be a non-negative integer, got {v}", param)
    if abs(v) > COORD_LIMIT:
        raise InputError(f"{what} = {v} is out of range (|value| <= {COORD_LIMIT:.0e})", param)
    return v


def check_positive(value: Number, what: str, *, param: str | None = None) -> int:
    """``value`` as an ``int`` >= 1, or :class:`InputError` naming ``what`` (about ``param``).

    >>> from fractions import Fraction
    >>> check_positive(Fraction(8), "M")
    8
    >>> check_positive(0, "M (rows)", param="m")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: M (rows) must be a positive integer, got 0
    """
    n = check_whole(value, what, param=param)
    if n < 1:
        raise InputError(f"{what} must be a positive integer, got {n}", param)
    return n


def check_whole(value: Number, what: str, *, param: str | None = None) -> int:
    """``value`` as an ``int``, or :class:`InputError` naming ``what`` (no range check).

    >>> from fractions import Fraction
    >>> check_whole(Fraction(5, 2), "L", param="levels")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: L must be an integer, got 2.500
    """
    try:
        return as_int(value, what)
    except ValueError as err:
        raise InputError(str(err), param) from None


def check_count(value: int, what: str, lo: int, hi: int, *, param: str | None = None) -> int:
    """``value`` if ``lo <= value <= hi``, else :class:`InputError` naming the bound it passes.

    >>> check_count(25, "bits per pixel", 1, 24, param="bits")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: bits per pixel must be at most 24, got 25
    """
    if value < lo:
        raise InputError(f"{what} must be at least {lo}, got {value}", param)
    if value > hi:
        raise InputError(f"{what} must be at most {hi}, got {value}", param)
    return value
