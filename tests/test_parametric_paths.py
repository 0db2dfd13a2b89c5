"""The float pre-check of a parametric curve's length gives the same verdict with numpy
(vectorised) and without it (the browser's Python): the same refusal at the same t_k."""

from __future__ import annotations

import pytest

from scanconv.algorithms import parametric as P
from scanconv.core.checks import InputError
from scanconv.core.expr import compile_expr


def _verdict(check, x: str, y: str, t0, t1, samples: int) -> str:
    fx, fy = compile_expr(x, ("t",)), compile_expr(y, ("t",))
    try:
        check(fx, fy, t0, t1, samples)
    except InputError as e:
        return str(e)
    return "accepted"


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize(
    ("x", "y", "t0", "t1", "samples", "refused_at"),
    [
        ("t*10000000", "t", 0, 1, 100_000, "t_10205"),  # refused part-way
        ("t", "0", 0, 10**7, 10, "t_2"),
        ("t", "0", 0, 10**6, 10, None),  # within the margin: left to the exact pass
        ("sin(t)*100 + cos(3*t)*t", "t**2", 0, 1, 20_000, None),  # a short curve
        ("1/t", "t", 0, 1, 1_000, None),  # undefined at t_0: left to the exact pass
        ("t**3*1000", "-t*2000000", -1, 1, 50_000, "t_"),
    ],
)
def test_numpy_and_scalar_pre_checks_agree(x, y, t0, t1, samples, refused_at):
    def scalar(fx, fy, a, b, n):
        P._check_float_path_scalar(fx, fy, float(a), float(b), n)

    vectorised = _verdict(P.check_float_path, x, y, t0, t1, samples)
    assert vectorised == _verdict(scalar, x, y, t0, t1, samples)
    if refused_at is None:
        assert vectorised == "accepted"
    else:
        assert (
            "more than 1,000,000 pixels long" in vectorised
            and f"(reached by {refused_at}" in vectorised
        )
