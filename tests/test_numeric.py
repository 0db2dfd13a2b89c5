"""The display and rounding rules of :mod:`scanconv.core.numeric`, at their edges, against
values worked by hand."""

from __future__ import annotations

from fractions import Fraction

import pytest

from scanconv.core.numeric import fmt_value


@pytest.mark.parametrize(
    ("value", "shown"),
    [
        (Fraction(1, 64), "0.015625"),  # a terminating decimal of 8 characters: as it is
        (Fraction(25, 4), "6.25"),
        (Fraction(1, 128), "1/128 ≈ 0.008"),  # 0.0078125 is 9 characters: the fraction
        (Fraction(1, 3), "1/3 ≈ 0.333"),  # not a terminating decimal
        (Fraction(-6, 3), "-2"),
    ],
)
def test_fmt_value_shows_a_short_decimal_and_else_the_fraction(value, shown):
    assert fmt_value(value) == shown


def test_a_number_literal_at_its_length_limit():
    # a literal of exactly _MAX_LITERAL characters is read; one more is refused
    from scanconv.core.numeric import _MAX_LITERAL, parse_number

    at = "0." + "0" * (_MAX_LITERAL - 3) + "5"
    assert len(at) == _MAX_LITERAL
    assert parse_number(at) == Fraction(5, 10 ** (_MAX_LITERAL - 2))
    with pytest.raises(ValueError, match=f"longer than {_MAX_LITERAL} characters"):
        parse_number(at + "0")


def test_a_fraction_over_zero_is_refused_and_over_one_read():
    from scanconv.core.numeric import parse_number

    with pytest.raises(ValueError, match="divides by zero"):
        parse_number("3/0")
    assert parse_number("3/1") == 3
    assert parse_number("-6/4") == Fraction(-3, 2)
