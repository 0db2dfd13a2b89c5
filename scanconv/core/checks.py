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


def check_integer(value: Number, what: str, *, negative: bool = True) -> int:
    """``value`` as an int within :data:`~scanconv.core.numeric.COORD_LIMIT`, or ``ValueError``.

    >>> from fractions import Fraction
    >>> check_integer(Fraction(-3), "xc")
    -3
    >>> check_integer(-1, "radius", negative=False)
    Traceback (most recent call last):
    ...
    ValueError: radius must be a non-negative integer, got -1
    """
    v = as_int(normalize(value), what)
    if not negative and v < 0:
        raise ValueError(f"{what} must be a non-negative integer, got {v}")
    if abs(v) > COORD_LIMIT:
        raise ValueError(f"{what} = {v} is out of range (|value| <= {COORD_LIMIT:.0e})")
    return v
