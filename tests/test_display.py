"""The Python API's answers show themselves: repr, to(fmt), rows(), grid(), Jupyter, pickle."""

from __future__ import annotations

import pickle
import subprocess
import sys

import pytest

import scanconv
from scanconv.display import Answer

from .helpers import run


def test_every_api_function_returns_an_answer_that_prints_what_the_cli_prints():
    sol = scanconv.circle(5, method="bresenham", center=(10, 10))
    assert isinstance(sol, Answer) and isinstance(sol, scanconv.Solution)
    cli = run("circle", "5", "--method", "bresenham", "--center", "10", "10", "-f", "markdown")
    assert sol.to("markdown") == cli.out
    cli = run("circle", "5", "--method", "bresenham", "--center", "10", "10", "-f", "plain")
    assert sol.to("plain") == cli.out


def test_the_repr_is_short_and_names_the_question():
    sol = scanconv.line(2, 2, 10, 6, algo="dda")
    assert repr(sol) == "<Answer line/dda: Simple DDA line algorithm: (2, 2) to (10, 6)>"
    assert len(repr(scanconv.bezier([(0, 0), (1, 2), (3, 3), (4, 0)]))) < 120


def test_jupyter_shows_the_markdown_answer():
    sol = scanconv.line(2, 2, 10, 6)
    shown = sol._repr_markdown_()
    assert shown == sol.to("markdown")
    assert shown.startswith("## Bresenham's line algorithm: (2, 2) to (10, 6)")
    assert "$k$ |" in shown and "$p_0 = 2\\Delta y - \\Delta x" in shown


def test_rows_are_the_step_table_with_exact_values():
    rows = scanconv.line(0, 0, 5, 2, algo="dda").rows()
    assert [r["pixel"] for r in rows] == [s.pixel for s in scanconv.dda_line(0, 0, 5, 2)]
    assert {type(v).__name__ for r in rows for k, v in r.items() if k not in ("pixel",)} <= {
        "int",
        "Fraction",
        "str",
        "NoneType",
    }


def test_grid_is_the_text_grid_and_empty_when_too_large():
    sol = scanconv.line(0, 0, 3, 1)
    assert sol.grid().splitlines()[-1] == "# = plotted pixel; x to the right, y up"
    assert "(3, 1)" not in sol.grid() and sol.grid().count("#") == 4 + 1  # 4 pixels + legend
    assert scanconv.line(0, 0, 500, 1).grid() == ""


def test_answers_pickle_by_asking_again():
    sol = scanconv.ellipse(8, 6, center=(1, 2))
    back = pickle.loads(pickle.dumps(sol))
    assert back.to("json") == sol.to("json")
    assert list(back.pixels()) == list(sol.pixels())


def test_a_solution_built_by_hand_does_not_pretend_to_pickle():
    from scanconv.answers.primitives.line import line_solution

    bare = Answer.of(line_solution("bresenham", 0, 0, 2, 1))
    with pytest.raises(TypeError, match="only answers made by the scanconv API"):
        pickle.dumps(bare)


def test_to_refuses_unknown_and_terminal_formats():
    sol = scanconv.line(0, 0, 2, 1)
    with pytest.raises(ValueError, match="unknown format 'docx'"):
        sol.to("docx")
    with pytest.raises(ValueError, match="for a terminal"):
        sol.to("rich")


def test_bad_input_names_the_keyword():
    with pytest.raises(scanconv.InputError) as err:
        scanconv.circle(5, method="midpoint", rounding="trunc")
    assert err.value.param == "rounding"
    assert "--" not in str(err.value)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_import_scanconv_is_lazy():
    code = (
        "import sys, scanconv; "
        "print(sorted(m for m in sys.modules if m.startswith('scanconv') or m in "
        "('numpy', 'rich', 'typer', 'fractions')))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    # scanconv.core.lazy: the lazy-loading mechanism that loads every other name
    assert out.stdout.strip() == "['scanconv', 'scanconv.core', 'scanconv.core.lazy']"
