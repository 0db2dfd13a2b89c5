"""The safe expression evaluator: hostile input is refused quickly, allowed input is right."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from scanconv.core.expr import MAX_BRACKETS, MAX_LENGTH, compile_expr, parse_exact, parse_value

from .helpers import python_calls

#: Each hostile input with a word its refusal message must contain.
HOSTILE = [
    ("__import__('os')", "function '__import__' is not allowed"),
    ("().__class__", "attribute access"),
    ("(1).__class__", "attribute access"),
    ("t.real", "attribute access"),
    ("lambda: 1", "lambda"),
    ("[x for x in ()]", "comprehensions"),
    ("(x for x in t)", "comprehensions"),
    ("9**9**9", "exponent 387420489 is too large"),
    ("t**(9**9)", "exponent"),
    ("2**-1000", "exponent -1000 is too large"),
    ("(" * 100_000 + "1" + ")" * 100_000, "too long"),
    ("(" * 60 + "t" + ")" * 60, "too deeply nested"),
    ("-" * 300 + "t", "too deeply nested"),
    ("1" * 1_000_000, "too long"),
    ("open('f')", "function 'open' is not allowed"),
    ("eval('1')", "function 'eval' is not allowed"),
    ("sin.__call__(1)", "attribute access"),
    ("'abc'", "strings"),
    ("f'{t}'", "strings"),
    ("t[0]", "subscripts"),
    ("t^2", "use ** for powers"),
    ("t % 2", "operator '%'"),
    ("t // 2", "operator '//'"),
    ("x + 1", "unknown name 'x'"),
    ("sin", "must be called"),
    ("sin(t, t)", "exactly one argument"),
    ("sin(x=t)", "exactly one argument"),
    ("t if t else 1", "conditional"),
    ("t == 1", "comparisons"),
    ("(t := 1)", "assignment"),
    ("1j", "complex"),
    ("1e400", "number too large"),
    ("1" * 400, "number too large"),
    ("1e300 * 1e300", "constant part"),
    ("True", "True"),
    ("t +", "not a valid formula"),
    ("import os", "not a valid formula"),
    ("1\x00", "not a valid formula"),
    ("", "empty"),
]


@pytest.mark.parametrize(("text", "word"), HOSTILE, ids=[repr(h[0][:20]) for h in HOSTILE])
def test_hostile_input_is_refused_quickly(text: str, word: str) -> None:
    refusal, calls = python_calls(_refusal, text)
    message = str(refusal)
    assert word in message
    assert "\n" not in message and len(message) < 200
    assert calls < REFUSAL_CALLS, f"{calls} Python calls before the refusal"


REFUSAL_CALLS = 10_000
"""A refusal is quick: about 2,000 Python calls at most today. Counted, not timed, so that a
busy machine cannot fail the test; a parser that walked a long hostile input node by node
would make far more."""


def _refusal(text: str) -> ValueError:
    with pytest.raises(ValueError) as info:
        compile_expr(text, ("t",))
    return info.value


def test_limits_are_checked_before_parsing() -> None:
    # Exactly at the limits is fine; one past them is refused.
    ok = "(" * MAX_BRACKETS + "t" + ")" * MAX_BRACKETS
    assert compile_expr(ok, ("t",))(t=2.0) == 2.0
    with pytest.raises(ValueError, match="too deeply nested"):
        compile_expr("(" + ok + ")", ("t",))
    terms = (MAX_LENGTH - 1) // 4
    long_ok = "t" + "+111" * terms
    assert MAX_LENGTH - 4 < len(long_ok) <= MAX_LENGTH
    assert compile_expr(long_ok, ("t",))(t=0.0) == 111 * terms
    with pytest.raises(ValueError, match="too long"):
        compile_expr(long_ok + "+111", ("t",))


def test_overflow_at_run_time_is_an_error() -> None:
    f = compile_expr("(t**100)**100", ("t",))
    assert f(t=1.0) == 1.0
    with pytest.raises(ValueError, match="undefined or infinite at t = 2"):
        f(t=2.0)
    g = compile_expr("t**t", ("t",))
    with pytest.raises(ValueError, match="undefined or infinite"):
        g(t=1000.0)


@pytest.mark.parametrize(
    ("text", "value"), [("log(t)", -1.0), ("sqrt(t)", -4.0), ("1/t", 0.0), ("log(t)", 0.0)]
)
def test_domain_errors_are_value_errors(text: str, value: float) -> None:
    with pytest.raises(ValueError, match="undefined or infinite"):
        compile_expr(text, ("t",))(t=value)


def test_domain_error_in_an_array_names_the_first_bad_sample() -> None:
    f = compile_expr("sqrt(t)", ("t",))
    with pytest.raises(ValueError, match="at t = -3"):
        f(t=np.array([1.0, 4.0, -3.0, -5.0]))


ALLOWED = [
    ("3*cos(t)", lambda t: 3 * math.cos(t)),
    ("2*sin(t) - tan(t/4)", lambda t: 2 * math.sin(t) - math.tan(t / 4)),
    (
        "sqrt(t*t + 1) + exp(-t) + log(t + 10)",
        lambda t: math.sqrt(t * t + 1) + math.exp(-t) + math.log(t + 10),
    ),
    ("abs(t - 1)**3 / (1 + t**2)", lambda t: abs(t - 1) ** 3 / (1 + t**2)),
    ("-t**2", lambda t: -(t**2)),
    ("+t - -t", lambda t: t + t),
    ("2**3**2", lambda t: 2.0 ** (3**2)),
    ("pi*e + t", lambda t: math.pi * math.e + t),
    ("1e-3*t + 0.5 + 1_000", lambda t: 1e-3 * t + 0.5 + 1000),
]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize(("text", "ref"), ALLOWED, ids=[a[0] for a in ALLOWED])
@given(t=st.floats(min_value=-5, max_value=5, allow_nan=False))
def test_allowed_input_matches_math(text, ref, t: float) -> None:
    assert compile_expr(text, ("t",))(t=t) == pytest.approx(ref(t), rel=1e-12, abs=1e-12)


def test_arrays_evaluate_elementwise_and_broadcast() -> None:
    f = compile_expr("x*y + 1", ("x", "y"))
    xs = np.array([[0.0, 1.0], [2.0, 3.0]])
    assert np.array_equal(f(x=xs, y=2.0), xs * 2 + 1)
    const = compile_expr("2*pi", ("t",))(t=np.zeros(3))
    assert const.shape == (3,) and np.allclose(const, 2 * math.pi)
    assert isinstance(compile_expr("t", ("t",))(t=1), float)


def test_missing_or_unexpected_variables_are_type_errors() -> None:
    f = compile_expr("x + y", ("x", "y"))
    with pytest.raises(TypeError, match="missing: y"):
        f(x=1.0)
    with pytest.raises(TypeError, match="unexpected: z"):
        f(x=1.0, y=1.0, z=1.0)


def test_exact_evaluation_of_rational_expressions() -> None:
    f = compile_expr("(t**2 - 1/3) / (t + 1) + abs(-t)", ("t",))
    assert f.rational
    t = Fraction(1, 7)
    assert f.exact(t=t) == (t**2 - Fraction(1, 3)) / (t + 1) + t
    assert compile_expr("0.1 + 0.2", ()).exact() == Fraction(3, 10)
    assert not compile_expr("cos(t)", ("t",)).rational
    assert not compile_expr("t**0.5", ("t",)).rational
    with pytest.raises(ValueError, match="cannot be evaluated exactly"):
        compile_expr("pi*t", ("t",)).exact(t=1)
    with pytest.raises(ValueError, match="divides by zero at t = 0"):
        compile_expr("1/t", ("t",)).exact(t=0)
    with pytest.raises(ValueError, match="too large"):
        compile_expr("((t**100)**100)**100", ("t",)).exact(t=3)


def test_parse_value_and_parse_exact() -> None:
    assert parse_value("2*pi") == 2 * math.pi
    assert parse_value("-3") == -3.0
    assert parse_exact("1/3") == Fraction(1, 3)
    assert parse_exact("-3/4") == Fraction(-3, 4)
    assert parse_exact("pi/2") == math.pi / 2
    with pytest.raises(ValueError, match="unknown name 't'"):
        parse_value("t")
    with pytest.raises(ValueError, match="undefined"):
        parse_value("log(0) * 0 + 1/(1-1)")


def test_text_is_kept() -> None:
    assert compile_expr(" 3*cos(t) ", ("t",)).text == " 3*cos(t) "
