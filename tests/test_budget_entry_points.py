"""One work budget at every entry point: every command, the Python API, ``scanconv.raster``,
each question of a sheet and a sheet's total, and ``check --batch``.

Each hole the attack report found is reproduced here: before the one budget, each of these
commands or calls was accepted and ran for minutes or hours (or needed gigabytes).
"""

from __future__ import annotations

import inspect
import re
import shlex
from pathlib import Path

import numpy as np
import pytest
import typer

import scanconv
from scanconv import raster
from scanconv.answers.methods import methods_of
from scanconv.cli.application import register
from scanconv.cli.budget import DOCUMENT_COMMANDS
from scanconv.cli.command import Command
from scanconv.core.checks import InputError
from scanconv.questions.budget import library_call
from scanconv.render import FORMATS, Format, formats
from scanconv.render.budget import (
    ALL_ROWS,
    BATCH_FILES,
    DOCUMENT,
    ROWS_IN_MEMORY,
    SECONDS,
    SHEET_ROWS,
    BudgetError,
    check_question,
    check_work,
    document,
    row_cost,
    row_limit,
)
from scanconv.render.work import BASE_COSTS, BOUNDED, COSTS, ESTIMATES, estimate

from .helpers import assert_refused, run

# --- the command line -------------------------------------------------------------------------

HOLES = [
    # (the command that streamed 10^9 rows, words of its refusal)
    (["antialias", "line", "0", "1000000000", "8", "0", "--method", "wu"], "2,000,000"),
    (
        [
            *("pipeline", "line", "0", "0", "1000000000", "1"),
            *("--window", "0", "0", "1000000000", "10"),
            *("--viewport", "0", "0", "1000000000", "10"),
        ],
        "1,000,000,002 rows",
    ),
    # Wu's line costs about ten times Bresenham's: a million rows is beyond a minute in csv
    (["line", "0", "0", "1000000", "1", "--algo", "wu", "-f", "csv"], "line/wu in csv costs"),
    (["line", "0", "0", "1000000", "1", "--algo", "wu", "-f", "json"], "json prints at most"),
]


@pytest.mark.parametrize(("args", "words"), HOLES, ids=lambda a: " ".join(a)[:40])
def test_a_command_beyond_the_budget_is_refused_with_one_line(args, words):
    assert_refused(run(*args), words)


def test_the_same_line_with_bresenham_is_within_the_budget():
    line = {"x1": 0, "y1": 0, "x2": 10**6, "y2": 1}
    assert check_work("line", line, Format.csv) is not None
    with pytest.raises(BudgetError) as info:
        check_work("line", {**line, "algo": "wu"}, Format.csv)
    assert info.value.param == "x2"


def _commands(group: typer.Typer, path: tuple[str, ...] = ()):
    for info in group.registered_commands:
        name = info.name or typer.main.get_command_name(info.callback.__name__)
        yield (*path, name), info.callback
    for sub in group.registered_groups:
        yield from _commands(sub.typer_instance, (*path, sub.name))


def _example(callback) -> list[str]:
    """The command line of the ``Example:`` in a command's help."""
    doc = inspect.getdoc(callback) or ""
    line = next(x for x in doc.splitlines() if "Example: scanconv " in x)
    return shlex.split(line.split("Example: scanconv ", 1)[1].split("  (", 1)[0])


def _parsed(path: tuple[str, ...], argv: list[str]) -> dict:
    """The keyword arguments click gives the command ``path`` for ``argv`` (its words after
    the path)."""
    command = typer.main.get_command(register(list(path)))
    for name in path:
        command = command.commands[name]
    return command.make_context(" ".join(path), argv[len(path) :]).params


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_every_command_has_an_estimate_or_a_reason():
    """Walk every registered command: it is estimated (and its example estimates), bounded by
    construction with a reason, or runs other commands as questions (each budgeted)."""
    seen = set()
    for path, callback in _commands(register(None)):
        seen.add(path)
        if not isinstance(callback, Command):
            assert path[0] in DOCUMENT_COMMANDS, f"{path}: how is its work bounded?"
            continue
        if library_call(callback.__name__, {})[0] in BOUNDED:
            continue
        example = _example(callback)
        assert tuple(example[: len(path)]) == path, (path, example)
        function, arguments = library_call(callback.__name__, _parsed(path, example))
        assert function in ESTIMATES, f"scanconv {' '.join(path)}: no estimate of its work"
        assert estimate(function, arguments) is not None, (path, example, arguments)
    assert len(seen) >= 35 and ("antialias", "line") in seen and ("pipeline", "line") in seen


def test_every_library_function_has_an_estimate_or_a_reason():
    names = [n for n in scanconv._api.__all__ if n[0].islower()]
    assert names and all(n in ESTIMATES or n in BOUNDED for n in names), sorted(
        set(names) - set(ESTIMATES) - set(BOUNDED)
    )
    assert not set(ESTIMATES) & set(BOUNDED) and all(BOUNDED.values())


def _keys() -> set[str]:
    """Every costs key an estimate can name."""
    keys = {f"line/{m}" for m in methods_of("line")}
    keys |= {f"circle/{m}" for m in methods_of("circle")}
    keys |= {f"pipeline_line/{m}" for m in ("basic", "dda", "bresenham")}
    for shape in ("line", "circle", "polygon"):
        keys |= {f"antialias_{shape}/area", f"antialias_{shape}/supersample"}
    keys |= {"antialias_line/wu", "ellipse/midpoint", "polygon/scan-line", "quantize"}
    return keys | {"quantize/range", "parametric", "curve", "compare_lines", "matrix"}


@pytest.mark.parametrize("key", sorted(_keys()))
def test_every_cost_key_has_a_base_cost_that_every_format_scales(key):
    """Every costs key has a base (csv) cost, which every single-answer format scales by its
    one row factor where the key does not measure it; what it measures is in csv and in
    formats that exist."""
    formats = {f.value for f in Format if f is not Format.auto}
    assert BASE_COSTS[key] > 0, f"benchmarks/bench_budget.py --only {key}"
    assert all(FORMATS[f].row_factor >= 1 for f in formats)
    measured = COSTS.get(key, {})
    assert not measured or (measured["csv"] == BASE_COSTS[key] and set(measured) <= formats)


def test_a_new_format_needs_one_number_for_every_cost(monkeypatch):
    """A format with a row factor and nothing else (no cost in any table) costs every key its
    base cost times that factor; a second new format with twice the factor, twice as much."""
    from scanconv.render import Spec
    from scanconv.render.budget import MIN_COST, unit_cost

    monkeypatch.setitem(FORMATS, "typst", Spec("typst:render_typst", (".typ",), row_factor=12))
    monkeypatch.setitem(FORMATS, "wider", Spec("wider:render_wider", (".w",), row_factor=24))
    assert not any("typst" in costs or "wider" in costs for costs in COSTS.values())
    for key in sorted(_keys()):
        typst = unit_cost(key, "typst")
        assert typst == max(BASE_COSTS[key] * 12, MIN_COST), key
        assert unit_cost(key, "wider") == max(BASE_COSTS[key] * 24, MIN_COST), key


@pytest.mark.parametrize("fmt", [f for f in Format if f is not Format.auto])
def test_an_accepted_table_is_within_the_seconds_of_the_budget(fmt):
    for key in sorted(_keys()):
        work = estimate("line", {"x1": 0, "y1": 0, "x2": 1, "y2": 0})._replace(key=key)
        limit = row_limit(work, fmt)
        assert limit * row_cost(work, fmt) <= SECONDS * 1e6
        assert limit <= ALL_ROWS or key == "quantize"


# --- the Python API ----------------------------------------------------------------------------


def test_the_api_refuses_a_line_no_format_prints_at_once():
    with pytest.raises(InputError) as info:
        scanconv.line(0, 0, 10**9, 1)
    assert info.value.param == "x2" and "2,000,000" in str(info.value)
    with pytest.raises(InputError) as info:
        scanconv.antialias_line(0, 0, 10**9, 1, method="wu")
    assert info.value.param == "x2"


def test_the_api_refuses_a_number_beyond_the_magnitude_limit():
    with pytest.raises(InputError, match="out of range") as info:
        scanconv.line(0, 0, 10**12, 1)
    assert info.value.param == "x2"
    with pytest.raises(InputError, match="out of range") as info:
        scanconv.line(2**63, 0, 0, 1)
    assert info.value.param == "x1"


def test_showing_an_answer_beyond_its_format_is_refused_before_any_row():
    wu = estimate("line", {"x1": 0, "y1": 0, "x2": 1, "y2": 0, "algo": "wu"})
    n = row_limit(wu, Format.csv)  # csv is the cheapest: the answer itself is accepted
    assert all(row_limit(wu, f) < n for f in (Format.html, Format.markdown, Format.json))
    answer = scanconv.line(0, 0, n - 1, 1, algo="wu")  # lazy: nothing computed yet
    for show in (answer._repr_html_, answer._repr_markdown_, lambda: answer.to("json")):
        with pytest.raises(InputError) as info:
            show()
        assert info.value.param == "x2" and "at most" in str(info.value)
    big = scanconv.line(0, 0, ROWS_IN_MEMORY, 1)
    with pytest.raises(InputError, match=f"at most {ROWS_IN_MEMORY:,}") as info:
        big.rows()
    assert info.value.param == "x2"
    small = scanconv.line(0, 0, 3, 1)
    assert small.to("csv").count("\n") == 5 and len(small.rows()) == 4


def test_raster_has_a_pixel_budget(monkeypatch):
    def allocation(*a, **k):
        raise AssertionError("numpy allocated before the refusal")

    for name in ("arange", "empty", "zeros"):
        monkeypatch.setattr(np, name, allocation)
    for call, param in (
        (lambda: raster.line(0, 0, 10**9, 1), "x2"),
        (lambda: raster.line(0, 0, 1, 10**9, algo="dda"), "y2"),
        (lambda: raster.circle(10**9), "r"),
        (lambda: raster.ellipse(5, 10**9), "ry"),
        (lambda: raster.line_aa(0, 0, 10**9, 1), "x2"),
    ):
        with pytest.raises(InputError, match="at most 20,000,000") as info:
            call()
        assert info.value.param == param
    monkeypatch.undo()
    with pytest.raises(InputError, match="pixels") as info:
        raster.polygon([0, 10**8, 10**8], [0, 0, 10**8])
    assert info.value.param == "vertices"


# --- documents ---------------------------------------------------------------------------------


def _questions(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "q.txt"
    path.write_text(text, encoding="utf-8")
    return path


def test_a_sheet_question_beyond_the_budget_is_refused_with_its_line(tmp_path):
    path = _questions(tmp_path, "line 2 2 10 6\nsample 'x+y' --size 1024 -L 8\n")
    target = tmp_path / "k.md"
    r = run("sheet", str(path), "-o", str(target))
    assert_refused(r, f"{path}:2: ", "1,048,576 cells", "at most 65,536")
    assert not target.exists()
    path = _questions(tmp_path, "antialias line 0 0 999999 1 --method wu\n")
    assert_refused(run("sheet", str(path)), f"{path}:1: ", "table rows")


def test_a_sheet_total_beyond_the_budget_is_refused_before_writing(tmp_path):
    per = 9_999  # each question alone is far within the budget
    count = SHEET_ROWS // (per + 1) + 1
    path = _questions(tmp_path, f"line 0 0 {per} 1 --no-grid\n" * count)
    target = tmp_path / "k.json"
    r = run("sheet", str(path), "-o", str(target))
    assert_refused(r, f"{path}:{count}: ", "with the questions before it", f"{SHEET_ROWS:,}")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["q.txt"]


def test_the_document_total_counts_each_question_in_its_costliest_format():
    line = {"x1": 0, "y1": 0, "x2": 9_999, "y2": 1}
    with document():
        for _ in range(SHEET_ROWS // 10_000):
            check_question("line", line)
        with pytest.raises(BudgetError, match="with the questions before it"):
            check_question("line", line)
    with document():  # a new document starts from nothing
        check_question("line", line)
    wu = {**line, "algo": "wu"}
    with document(), pytest.raises(BudgetError, match="s of work"):
        for _ in range(SHEET_ROWS // 10_000):
            check_question("line", wu)
    # every format that writes both single answers and documents (a quiz file's feedback is plain)
    assert set(DOCUMENT) == {Format(f) for f in formats("answer") if f in formats("document")}


def test_check_refuses_a_question_beyond_the_budget(tmp_path):
    answer = tmp_path / "a.csv"
    answer.write_text("k,x,y\n0,0,0\n", encoding="utf-8")
    r = run("check", str(answer), "--", "line", "0", "0", "999999", "1", "--algo", "wu")
    assert_refused(r, "question:", "table rows")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_check_batch_is_bounded_in_files_and_work(tmp_path):
    folder = tmp_path / "class"
    folder.mkdir()
    for i in range(BATCH_FILES + 1):
        (folder / f"s{i:04}.csv").write_text("k,x,y\n0,2,2\n", encoding="utf-8")
    r = run("check", "--batch", str(folder), "--", "line", "2", "2", "10", "6")
    assert_refused(r, f"{BATCH_FILES + 1:,} files", f"at most {BATCH_FILES:,}")
    big = tmp_path / "big"
    big.mkdir()
    rows = "".join(f"{k},{k},{k % 7}\n" for k in range(5_000))
    for i in range(40):  # each within the file limits; 82 s of marking before the budget
        (big / f"s{i:02}.csv").write_text("k,x,y\n" + rows, encoding="utf-8")
    r = run("check", "--batch", str(big), "--", "line", "0", "0", "9998", "1")
    assert_refused(r, "40 files", "s of marking", "mark the folder in parts")


# --- the documentation ---------------------------------------------------------------------------

BUDGET_ROW = re.compile(r"^\| [^|]+ \| `((?:render|algorithms)\.\w+)\.(\w+)` \| `([^`]+)` \|", re.M)


def test_the_documented_budgets_are_the_constants():
    import importlib

    from scanconv.core.expr import parse_exact

    doc = (Path(__file__).parent.parent / "docs" / "limits.md").read_text(encoding="utf-8")
    rows = {(m, n): v for m, n, v in BUDGET_ROW.findall(doc)}
    names = {"SECONDS", "ALL_ROWS", "SHEET_ROWS", "SHEET_SECONDS", "BATCH_FILES"}
    names |= {"BATCH_SECONDS", "ROWS_IN_MEMORY", "PIXEL_BUDGET", "MEMORY", "PDF_ROWS"}
    assert {n for _, n in rows} == names
    for (module, name), value in rows.items():
        constant = getattr(importlib.import_module(f"scanconv.{module}"), name)
        assert parse_exact(value.replace("_", "")) == constant, name
