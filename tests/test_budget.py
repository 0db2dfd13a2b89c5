"""Work budgets: decided from the arguments before any work, and the fast paths they protect.

* Every command whose answer can outgrow a format's budget is refused at once in that format
  (exit 2, one line naming the size, the limit and the formats that would print it), and the
  same request is accepted in csv.
* The estimates are close to the real sizes (the refusal is about the answer it refuses).
* ``sample`` evaluates f in float64 with numpy but gives exactly the levels exact arithmetic
  gives, on random rational formulas and sizes (cells near a level boundary are recomputed).
* A parametric curve beyond the exact budget is computed in float64 (and says so); a curve
  whose pixel path is certainly too long is refused from its float samples, at once.
"""

from __future__ import annotations

import json
import math
import random
from fractions import Fraction

import numpy as np
import pytest

from scanconv.algorithms import curve_limits
from scanconv.algorithms.parametric import check_float_path, exact_values, parametric
from scanconv.algorithms.sample import sample_levels
from scanconv.cli.budget import estimate
from scanconv.core.checks import InputError
from scanconv.core.expr import compile_expr
from scanconv.render import Format
from scanconv.render.budget import (
    ALL_ROWS,
    MATRIX_CELLS,
    TABLE_ROWS,
    BudgetError,
    check_matrix,
    check_rows,
)
from scanconv.render.work import ESTIMATES

from .helpers import assert_refused, python_calls, run


def _ring_point(i: int) -> tuple[float, float]:
    t = 2 * math.pi * i / 400
    return math.cos(t), math.sin(t)


#: A polygon of 400 vertices on a circle, and 100 points: 40,000 edge rows.
_RING = [str(round(1000 * v)) for i in range(400) for v in _ring_point(i)]

#: A request beyond a budget, per estimated command, with the words its refusal must contain.
BEYOND = [
    (["linestyle", "0", "0", "100000", "1", "--mask", "10", "-f", "rich"], "100,001 rows", "rich"),
    (["thickline", "0", "0", "100000", "1", "--width", "3", "-f", "rich"], "100,001 rows", "rich"),
    (["inside", *_RING, "--points", *(["1", "1"] * 100), "-f", "rich"], "rows", "rich"),
    (
        ["char", "bitmap", "X", "--rows", "/".join(["1" * 64] * 64), "--scale", "16", "-f", "rich"],
        "rows",
        "rich",
    ),
    (["line", "0", "0", "100000", "1", "-f", "rich"], "100,001 rows", "at most 10,000"),
    (["circle", "100000", "-f", "rich"], "rows", "--format plain, markdown, csv or json"),
    (["ellipse", "1000000", "1000000", "-f", "rich"], "1,414,216 rows", "rich"),
    (["compare", "line", "0", "0", "10000", "3", "-f", "rich"], "10,001 rows", "rich"),
    (["quantize", "--bits", "24", "-f", "rich"], "16,777,216 rows", "rich"),
    (
        ["polygon", "0", "0", "1", "0", "1", "499999", "0", "499999", "-f", "rich"],
        "500,000 rows",
        "rich",
    ),
    (
        ["sample", "x*y", "--size", "4096", "--levels", "256", "-f", "rich"],
        "16,777,216 cells",
        "65,536",
    ),
    (
        ["sample", "x*y", "--size", "2048", "--levels", "256", "-f", "latex"],
        "4,194,304 cells",
        "csv or json",
    ),
    (
        ["sample", "x*y", "--size", "257x256", "-L", "4", "-f", "markdown"],
        "65,792 cells",
        "plain, csv or json",
    ),
    (
        ["sample", "x*y", "--size", "1025x1024", "-L", "4", "-f", "plain"],
        "plain format prints",
        "csv or json",
    ),
    (["image", "ramp", "--size", "300", "-f", "latex"], "90,000 cells", "65,536"),
    (
        ["parametric", "custom", "--x", "t", "--y", "t", "-n", "100000", "-f", "rich"],
        "100,001 rows",
        "rich",
    ),
    (["parametric", "circle", "--radius", "5", "-n", "20000", "-f", "rich"], "20,001 rows", "rich"),
    (
        ["parametric", "ellipse", "--a", "5", "--b", "3", "-n", "20000", "-f", "rich"],
        "rows",
        "rich",
    ),
    (["parametric", "parabola", "--a", "1", "-n", "20000", "-f", "rich"], "rows", "rich"),
    (["parametric", "line", "0", "0", "50000", "0", "-f", "rich"], "50,001 rows", "rich"),
    (["bezier", "0", "0", "5", "5", "10", "0", "-n", "20000", "-f", "rich"], "rows", "rich"),
    (
        ["bspline", "0", "0", "5", "5", "10", "0", "--degree", "2", "-n", "20000", "-f", "rich"],
        "rows",
        "rich",
    ),
    (
        ["continuity", "0", "0", "1", "1", ":", "1", "1", "2", "0", "-n", "20000", "-f", "rich"],
        "rows",
        "rich",
    ),
    (
        [
            "local-control",
            "0",
            "0",
            "1",
            "1",
            "2",
            "0",
            "3",
            "1",
            "--move",
            "1",
            "1",
            "2",
            "-n",
            "20000",
            "-f",
            "rich",
        ],
        "rows",
        "rich",
    ),
]


def _warm(args: list[str]) -> None:
    run(*args[: 2 if args[0] in ("parametric", "image", "compare") else 1], "--help")


@pytest.mark.parametrize(
    ("args", "size", "limit"),
    BEYOND,
    ids=lambda a: " ".join(a)[:50] if isinstance(a, list) else None,
)
def test_beyond_the_budget_of_its_format_is_refused_at_once(args, size, limit):
    _warm(args)
    r, calls = python_calls(run, *args)
    assert_refused(r, size, limit, "use --format")
    assert calls < REFUSAL_CALLS, f"{calls} Python calls before the refusal"


REFUSAL_CALLS = 50_000
""""At once" is before any work: a refusal makes at most about 4,000 Python calls (parsing the
arguments, the estimate), where rows cost several calls each. Counted, not timed, so that a busy
machine cannot fail the test."""


def test_every_estimated_command_has_a_refusal_case():
    names = {
        "line": "line",
        "circle": "circle",
        "ellipse": "ellipse",
        "quantize": "quantize",
        "polygon": "polygon",
        "sample": "sample",
        "ramp": "ramp",
        "compare line": "compare_lines",
        "bezier": "bezier",
        "bspline": "bspline",
        "continuity": "continuity",
        "local-control": "local_control",
        "linestyle": "line_style",
        "thickline": "thick_line",
        "inside": "inside",
        "char": "char_bitmap",
    }
    covered = set()
    for args, _, _ in BEYOND:
        key = (
            " ".join(args[:2])
            if args[0] in ("compare",)
            else args[1]
            if args[0] == "image"
            else args[0]
        )
        if args[0] == "parametric":
            covered.add(f"parametric_{args[1]}")
        else:
            covered.add(names[key])
    # the antialias and pipeline budgets: their refusal cases are in
    # tests/test_budget_entry_points.py
    unified = {"antialias_line", "antialias_circle", "antialias_polygon", "pipeline_line"}
    unified |= {"pipeline_polygon", "bspline_basis"}
    assert covered | unified == set(ESTIMATES)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_same_request_is_accepted_in_csv_and_starts_at_once():
    r = run("sample", "x*y", "--size", "300", "-L", "4", "-f", "csv")
    assert r.code == 0 and r.out.count("\n") == 301
    r = run("image", "ramp", "--size", "300", "-f", "json")
    assert r.code == 0 and r.out.startswith("{")


@pytest.mark.slow  # about a second of CPU
def test_at_the_budget_is_accepted():
    check_matrix(256, 256, Format.rich)
    check_matrix(1024, 1024, Format.plain)
    check_rows(TABLE_ROWS[Format.rich], Format.rich)
    with pytest.raises(BudgetError):
        check_matrix(256, 257, Format.latex)
    with pytest.raises(BudgetError):
        check_rows(TABLE_ROWS[Format.rich] + 1, Format.rich)
    for fmt in (Format.csv, Format.json):  # no budget of their own but ALL_ROWS
        check_matrix(4096, 4096, fmt)
        check_rows(ALL_ROWS, fmt)
        check_rows(2**24, fmt, every_format=False)  # quantize's table
        with pytest.raises(BudgetError, match="no format prints more than 2,000,000"):
            check_rows(ALL_ROWS + 1, fmt)
    for args in (["line", "0", "0", "2000000", "0"], ["circle", "2828500"]):
        r = run(*args, "-f", "csv")
        assert r.code == 2 and "scanconv.raster" in r.err and r.out == ""
    assert set(MATRIX_CELLS) == {Format.rich, Format.latex, Format.markdown, Format.plain}
    r = run("sample", "x", "--size", "256", "-L", "4", "-f", "latex")
    assert r.code == 0 and r.err == ""


def test_a_library_message_names_no_flag():
    with pytest.raises(BudgetError) as info:
        check_matrix(4096, 4096, Format.rich)
    assert "--" not in str(info.value) and info.value.ways == ("csv", "json")


def _rows(*args: str) -> int:
    """The longest table of the answer: its steps, or its longest secondary table."""
    r = run(*args, "-f", "json")
    assert r.code == 0, r.err
    answer = json.loads(r.out)
    return max([len(answer["steps"]), *(len(t["rows"]) for t in answer.get("tables", []))])


@pytest.mark.parametrize(
    ("name", "arguments", "args"),
    [
        ("line", {"x1": 0, "y1": 0, "x2": 37, "y2": -90}, ("line", "0", "0", "37", "-90")),
        ("circle", {"r": 500}, ("circle", "500")),
        ("ellipse", {"rx": 300, "ry": 40}, ("ellipse", "300", "40")),
        ("ellipse", {"rx": 7, "ry": 900}, ("ellipse", "7", "900")),
        ("quantize", {"bits": 6}, ("quantize", "--bits", "6")),
        (
            "polygon",
            {"vertices": [0, 0, 9, 2, 4, 300]},
            ("polygon", "0", "0", "9", "2", "4", "300"),
        ),
        (
            "parametric_custom",
            {"samples": 77},
            ("parametric", "custom", "--x", "t", "--y", "t", "-n", "77"),
        ),
        (
            "parametric_line",
            {"x0": 0, "y0": 0, "x1": 12, "y1": 5},
            ("parametric", "line", "0", "0", "12", "5"),
        ),
        ("bezier", {}, ("bezier", "0", "0", "5", "5", "10", "0")),
    ],
)
def test_the_estimate_is_close_to_the_rows_printed(name, arguments, args):
    work = estimate(name, arguments)
    assert work is not None and work.kind == "rows"
    rows = _rows(*args)
    assert rows <= work.rows <= rows * 1.01 + 3, (work, rows)


# --- sample: float64 levels equal the exact levels --------------------------------------------


def _random_formula(rng: random.Random, depth: int = 0) -> str:
    if depth > 2 or rng.random() < 0.3:
        return rng.choice(
            ["x", "y", str(rng.randint(1, 9)), f"{rng.randint(1, 9)}/{rng.randint(1, 9)}"]
        )
    op = rng.choice(["+", "-", "*", "/", "**"])
    if op == "**":
        return f"({_random_formula(rng, depth + 1)})**{rng.randint(2, 3)}"
    return f"({_random_formula(rng, depth + 1)}){op}({_random_formula(rng, depth + 1)})"


def _exact_levels(text: str, m: int, n: int, levels: int, domain, origin: str) -> np.ndarray:
    f = compile_expr(text, ("x", "y"))
    x0, x1, y0, y1 = (Fraction(v) for v in domain)
    dx = (x1 - x0) / (n - 1) if n > 1 else 0
    dy = (y1 - y0) / (m - 1) if m > 1 else 0
    ys = (
        [y0 + i * dy for i in range(m)] if origin == "top-left" else [y1 - i * dy for i in range(m)]
    )
    values = [[f.exact(x=x0 + j * dx, y=y) for j in range(n)] for y in ys]
    lo, hi = min(map(min, values)), max(map(max, values))
    if lo == hi:
        return np.zeros((m, n), dtype=int)
    return np.array(
        [
            [min(max(math.floor((v - lo) * levels / (hi - lo)), 0), levels - 1) for v in row]
            for row in values
        ]
    )


@pytest.mark.slow  # about a second of CPU
def test_float_levels_equal_exact_levels_on_random_formulas():
    """Before the boundary check, 8 of these 320 formulas had a level off by one."""
    rng = random.Random(19)
    compared = 0
    for _ in range(600):
        text = _random_formula(rng)
        m, n = rng.randint(1, 12), rng.randint(1, 12)
        levels = rng.choice([2, 3, 4, 7, 8, 10, 16, 256])
        origin = rng.choice(["top-left", "bottom-left"])
        domain = rng.choice([(0, n - 1, 0, m - 1), (Fraction(-1, 3), 2, 1, Fraction(7, 2))])
        if (m == 1) != (domain[2] == domain[3]) or (n == 1) != (domain[0] == domain[1]):
            domain = (0, n - 1, 0, m - 1)
        try:
            s = sample_levels(text, m, n, levels, domain=domain, origin=origin)
            want = _exact_levels(text, m, n, levels, domain, origin)
        except ValueError:  # a division by zero somewhere on the grid
            continue
        compared += 1
        assert s.unchecked == 0
        assert (s.levels == want).all(), (text, m, n, levels, domain, origin)
    assert compared > 300


def test_a_boundary_that_float64_gets_wrong_is_exact():
    # 1/3 + x*4/8 at x = 0..2: f = 1/3, 5/6, 4/3; (f - 1/3) * 8 / 1 = 0, 4, 8: level 4 exactly
    s = sample_levels("1/3 + x*4/8", 2, 3, 8, origin="top-left")
    assert s.levels.tolist() == [[0, 4, 7], [0, 4, 7]]
    assert s.f_min == Fraction(1, 3) and s.checked > 0


@pytest.mark.slow  # about a second of CPU
def test_too_many_boundary_cells_keep_float_levels_and_say_so():
    from scanconv.answers.image.sample import sample_solution

    s = sample_levels("x", 4096, 4096, 4095)
    assert s.unchecked > 0 and s.levels[0].tolist() == [*range(4095), 4094]
    assert any("float64 level" in n for n in sample_solution(s).notes)


# --- parametric: the float path and the early path check ---------------------------------------

LONG_POLYNOMIAL = "+".join(f"{i + 1}*t**{i}" for i in range(40))


#: The fewest samples of LONG_POLYNOMIAL (size 239) and ``t`` (size 1) whose exact work,
#: (samples + 1) x 240 evaluations, is beyond EXACT_WORK: one more than 4,165 (999,840 is within
#: it). Just past the edge, not 10,000 or 20,000: the float64 values cost as many scalar
#: evaluations as the exact work they replace, so every sample beyond the edge is CPU spent
#: proving nothing more (this test took half a minute of CPU with 10**4 and 2 x 10**4).
FLOAT_SAMPLES = 4_200


@pytest.mark.slow  # about a second of CPU
def test_beyond_the_exact_budget_the_curve_is_computed_in_float64():
    fx, fy = compile_expr(LONG_POLYNOMIAL, ("t",)), compile_expr("t", ("t",))
    assert exact_values(fx, fy, 0, 1, 4_165)  # the largest within the budget...
    assert not exact_values(fx, fy, 0, 1, 4_166)  # ...and the next one beyond it
    steps = list(parametric(fx, fy, 0, 1, FLOAT_SAMPLES))
    assert all(isinstance(s.extra[1], float) for s in steps[:5])
    exact = list(parametric(fx, fy, 0, 1, 100))  # within the budget: fractions
    assert isinstance(exact[1].extra[1], Fraction)
    # the same points either way (t = k/100 is t = 42k/4200)
    assert [s.pixel for s in steps[:: FLOAT_SAMPLES // 100]] == [s.pixel for s in exact]
    samples = str(FLOAT_SAMPLES)
    r = run("parametric", "custom", "--x", LONG_POLYNOMIAL, "--y", "t", "-n", samples, "-f", "json")
    assert r.code == 0 and "would take 1,008,240 evaluations" in r.out
    assert "floating point" in r.out


def test_a_path_certainly_too_long_is_refused_from_float_samples_at_once():
    _warm(["parametric", "custom"])
    args = ("parametric", "custom", "--x", "t*10000000", "--y", "t", "-n", "100000", "-f", "csv")
    r, calls = python_calls(run, *args)
    assert calls < REFUSAL_CALLS, f"{calls} Python calls before the refusal"
    assert_refused(r, "more than 1,000,000 pixels")
    with pytest.raises(InputError):
        check_float_path(compile_expr("t", ("t",)), compile_expr("t", ("t",)), 0, 3 * 10**6, 10)
    # within the margin the exact pass decides (no refusal here)
    check_float_path(
        compile_expr("t", ("t",)), compile_expr("0", ("t",)), 0, curve_limits.MAX_CURVE_PIXELS, 10
    )
