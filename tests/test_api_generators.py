"""The exported step generators read their arguments as the API does (attack report D16, D18):
numpy integers exactly (no int64 overflow), NaN and Decimal NaN refused by parameter, a radius
checked before the first step; and the API's errors name their parameter."""

from __future__ import annotations

from decimal import Decimal

import numpy as np
import pytest

import scanconv
from scanconv.algorithms import circles, lines


def test_numpy_integers_give_the_same_steps_as_python_integers() -> None:
    ours = [(s.p, s.pixel) for s in scanconv.bresenham_line(np.int64(2), np.int32(2), 10, 6)]
    assert ours == [(s.p, s.pixel) for s in lines.bresenham(2, 2, 10, 6)]
    assert [s.p for s in scanconv.midpoint_circle(np.int64(8))] == [
        s.p for s in circles.midpoint(8)
    ]


@pytest.mark.parametrize(
    ("call", "param"),
    [
        (lambda: scanconv.bresenham_line(Decimal("NaN"), 0, 1, 1), "x1"),
        (lambda: scanconv.dda_line(0, 0, float("inf"), 1), "x2"),
        (lambda: scanconv.midpoint_circle(np.int64(2**62)), "r"),
        (lambda: scanconv.midpoint_circle(-3), "r"),
        (lambda: scanconv.bresenham_circle(Decimal("NaN")), "r"),
        (lambda: scanconv.midpoint_ellipse(4, -1), "ry"),
        (lambda: scanconv.circle(-1), "r"),
        (lambda: scanconv.ellipse(-1, 3), "rx"),
    ],
)
def test_bad_numbers_are_input_errors_naming_their_parameter(call, param) -> None:
    with pytest.raises(scanconv.InputError) as info:
        next(iter(call()))
    assert info.value.param == param
