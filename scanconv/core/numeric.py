"""Exact numbers: parsing, the one rounding rule, and display.

Every step table in scanconv is computed with ``int`` and :class:`fractions.Fraction`.
Floats appear only where an algorithm is genuinely transcendental (square roots,
trigonometry), and even there the rounding goes through :func:`round_half_up`.

Python's built-in ``round()`` rounds halves to even (``round(2.5) == 2``), which gives the
wrong pixels for the notes' own DDA example; it is never used here.
"""

from __future__ import annotations

from fractions import Fraction

from . import lazy

Number = int | Fraction
"""An exact value: what every step record holds."""

#: Largest accepted magnitude of a coordinate or size given on the command line.
#: Beyond it even a streamed table would take hours, and the bulk rasterizers use int64.
COORD_LIMIT = 10**9

_NUMBER = lazy.pattern(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d{1,3})?|[+-]?\d+/\d+")
_MAX_LITERAL = 40


def round_half_up(v: Number | float) -> int:
    """Round to the nearest integer, halves upward: ``floor(v + 1/2)``, exactly.

    Parameters
    ----------
    v : int, Fraction or float
        The value; a float is read exactly (its binary value, not the decimal it prints as).

    Returns
    -------
    int
        ``floor(v + 1/2)``: the notes' rounding of a coordinate to a pixel (the DDA's and the
        basic method's default, ``rounding="half-up"``).

    Notes
    -----
    Python's :func:`round` rounds halves to even (``round(4.5) == 4``), and ``int(v + 0.5)``
    in floats both truncates negative values and can round up a float just below 1/2.

    Examples
    --------
    >>> [round_half_up(Fraction(n, 2)) for n in (1, 3, 5, 7, -1, -3)]
    [1, 2, 3, 4, 0, -1]
    >>> round_half_up(Fraction(9, 2)), round(4.5)   # Python's round() gives 4
    (5, 4)
    >>> round_half_up(0.49999999999999994)   # floor(v + 0.5) in floats would give 1
    0
    """
    if isinstance(v, int):
        return v
    if not isinstance(v, Fraction):
        v = Fraction(v)  # exact: float v + 0.5 would round 0.49999999999999994 up to 1
    return (2 * v.numerator + v.denominator) // (2 * v.denominator)


def round_trunc(v: Number | float) -> int:
    """Truncate toward zero (the other convention some textbooks use).

    >>> round_trunc(Fraction(-7, 2)), round_trunc(3.9)
    (-3, 3)
    """
    return int(v)


def round_half_even(v: Number | float) -> int:
    """Round to the nearest integer, halves to the even neighbour: Python's ``round()``.

    >>> [round_half_even(Fraction(n, 2)) for n in (1, 3, 5, -1, -3)]
    [0, 2, 2, 0, -2]
    """
    return round(Fraction(v))


def round_c_cast(v: Number | float) -> int:
    """C's ``(int)(a + 0.5)``: add a half, truncate toward zero (wrong below -1/2).

    >>> [round_c_cast(Fraction(n, 2)) for n in (1, 3, -1, -3, -4)]
    [1, 2, 0, -1, -1]
    """
    return int(Fraction(v) + Fraction(1, 2))


def round_half_away(v: Number | float) -> int:
    """Round to the nearest integer, halves away from zero: C's ``round()``.

    >>> [round_half_away(Fraction(n, 2)) for n in (1, 3, -1, -3)]
    [1, 2, -1, -2]
    """
    f = Fraction(v)
    return round_half_up(f) if f >= 0 else -round_half_up(-f)


def parse_number(text: str, limit: int = COORD_LIMIT) -> Fraction:
    """Parse a decimal, integer or ``a/b`` literal exactly.

    NaN, infinities, empty strings, overlong literals and magnitudes beyond ``limit``
    (:data:`COORD_LIMIT`: coordinates) are refused with a :class:`ValueError` that names the
    problem.

    >>> parse_number("2.5"), parse_number("-3/4"), parse_number("1e2")
    (Fraction(5, 2), Fraction(-3, 4), Fraction(100, 1))
    >>> parse_number("nan")
    Traceback (most recent call last):
    ...
    ValueError: 'nan' is not a finite number
    """
    s = text.strip().replace("\u2212", "-")
    if not s:
        raise ValueError("empty value where a number is expected")
    if len(s) > _MAX_LITERAL:
        raise ValueError(f"number literal longer than {_MAX_LITERAL} characters")
    whole = s[1:] if s[0] in "+-" else s  # an integer ([+-]?\d+) needs no pattern
    if not whole.isdecimal() and not _NUMBER.fullmatch(s):
        low = s.lower().lstrip("+-")
        if low in ("nan", "inf", "infinity"):
            raise ValueError(f"{s!r} is not a finite number")
        raise ValueError(f"{text!r} is not a number")
    if "/" in s and int(s.split("/")[1]) == 0:
        raise ValueError(f"{text!r} divides by zero")
    value = Fraction(s)
    if abs(value) > limit:
        raise ValueError(f"{text!r} is out of range (|value| <= {limit:.0e})")
    return value


def as_int(value: Number, what: str) -> int:
    """Return ``value`` as an ``int``, or raise ``ValueError`` naming ``what``.

    >>> as_int(Fraction(4), "x1")
    4
    """
    if isinstance(value, Fraction):
        if value.denominator != 1:
            raise ValueError(f"{what} must be an integer, got {fmt(value)}")
        return value.numerator
    return value


def normalize(value: Number) -> Number:
    """Integral fractions become ``int`` so they print and serialize as integers."""
    if isinstance(value, Fraction) and value.denominator == 1:
        return value.numerator
    return value


def fmt(value: Number | float, places: int | None = None) -> str:
    """Display a number: integers as they are, anything else to 3 decimals.

    With ``places`` every value gets exactly that many decimals (the DDA columns of the notes
    print ``2.000``). The last decimal is rounded half up, exactly.

    >>> fmt(8), fmt(Fraction(1, 2)), fmt(Fraction(1, 3)), fmt(2, places=3), fmt(Fraction(-5, 2000))
    ('8', '0.500', '0.333', '2.000', '-0.002')
    """
    if places is None:
        if isinstance(value, int) or (isinstance(value, Fraction) and value.denominator == 1):
            return str(int(value))
        places = 3
    scaled = round_half_up(Fraction(value) * 10**places)
    sign = "-" if scaled < 0 else ""
    digits = str(abs(scaled)).rjust(places + 1, "0")
    if places == 0:
        return sign + digits
    return f"{sign}{digits[:-places]}.{digits[-places:]}"


def fmt_short(value: Number) -> str:
    """Display a given or worked value briefly and exactly: ``1.5``, ``-3``, ``1/3``.

    Terminating decimals of up to 6 places print as decimals, anything else as a fraction.

    >>> fmt_short(Fraction(3, 2)), fmt_short(Fraction(-6, 2)), fmt_short(Fraction(1, 3))
    ('1.5', '-3', '1/3')
    """
    value = normalize(value)
    if isinstance(value, int):
        return str(value)
    for places in range(1, 7):
        scaled = value * 10**places
        if scaled.denominator == 1:
            return fmt(value, places)
    return str(value)


def paren(text: str) -> str:
    """Bracket a negative number's text where it is substituted into working: ``10 - (-2)``.

    >>> paren("-2"), paren("3/4")
    ('(-2)', '3/4')
    """
    return f"({text})" if text.startswith("-") else text


def fmt_paren(value: Number) -> str:
    """:func:`fmt_short`, bracketed when negative.

    >>> fmt_paren(Fraction(-3, 2)), fmt_paren(4)
    ('(-1.5)', '4')
    """
    return paren(fmt_short(value))


def fmt_exact(value: Number) -> str:
    """Display a number exactly: ``3/8`` rather than ``0.375``.

    >>> fmt_exact(Fraction(3, 8)), fmt_exact(Fraction(4, 2))
    ('3/8', '2')
    """
    value = normalize(value)
    return str(value)


def fmt_value(value: Number) -> str:
    """Exact and decimal together where they differ: ``1/3 = 0.333``; ``1/2`` stays ``0.5``.

    >>> fmt_value(Fraction(1, 3)), fmt_value(Fraction(1, 2)), fmt_value(4)
    ('1/3 ≈ 0.333', '0.5', '4')
    """
    value = normalize(value)
    if isinstance(value, int):
        return str(value)
    den = value.denominator
    while den % 2 == 0:
        den //= 2
    while den % 5 == 0:
        den //= 5
    if den == 1 and len(str(float(value))) <= 8:
        return str(float(value))
    return f"{value} ≈ {fmt(value)}"


def fmt_pixel(pixel: tuple[int, int]) -> str:
    """``(3, 3)``.

    >>> fmt_pixel((3, -4))
    '(3, -4)'
    """
    return f"({pixel[0]}, {pixel[1]})"


def json_number(value: Number | float) -> int | float:
    """Integers stay JSON integers; other exact values become JSON numbers."""
    value = normalize(value) if not isinstance(value, float) else value
    if isinstance(value, int):
        return value
    return float(value)
