"""The terminal output as a person sees it: every line fits the terminal, at 60, 80 and 120
columns, and no coordinate pair is split across lines or cells.

One question per command (its first golden case), printed in the ``rich`` format at each
width through ``COLUMNS``, which rich reads as the terminal's width.
"""

from __future__ import annotations

import re

import pytest

from .cli_vocabulary import DOCUMENTS
from .helpers import run
from .test_golden import FILES, read_case

WIDTHS = (60, 80, 120)
_FORMAT_OPTIONS = {"-f", "--format", "-o", "--output", "--svg", "--png"}
_SPLIT_PAIR = re.compile(r"\(-?[\d.]+,\s*$|^\s*-?[\d.]+\)|\(-?[\d.]+,\s{2,}|\(\S+,\s+│")


def _as_rich(args: list[str]) -> list[str]:
    out: list[str] = []
    skip = False
    for a in args:
        if skip:
            skip = False
        elif a in _FORMAT_OPTIONS:
            skip = True
        elif a.split("=", 1)[0] in _FORMAT_OPTIONS:
            pass
        else:
            out.append(a)
    return [*out, "--format", "rich"]


def _one_per_command() -> dict[str, list[str]]:
    cases: dict[str, list[str]] = {}
    for path in FILES:
        args = read_case(path)[0]
        words = [a for a in args if not a.startswith("-")][:2]
        name = " ".join(words[:2] if words[0] in ("parametric", "clip", "pipeline") else words[:1])
        if (words[0],) in DOCUMENTS:  # documents have no terminal layout (cli_vocabulary)
            continue
        cases.setdefault(name, _as_rich(args))
    # the widest cases: a radius-12 grid, a quadratic B-spline's basis columns
    cases["circle 12"] = ["circle", "12", "--format", "rich"]
    cases["bspline p2"] = ["bspline", *"0 0 1 2 3 3 4 0 5 2".split(), "--degree", "2", "-f", "rich"]
    cases["circle 20"] = ["circle", "20", "--format", "rich"]
    return cases


CASES = _one_per_command()


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("width", WIDTHS)
@pytest.mark.parametrize("name", sorted(CASES))
def test_rich_output_fits_the_terminal(
    name: str, width: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("COLUMNS", str(width))
    result = run(*CASES[name])
    assert result.code == 0, result.err
    for line in result.out.splitlines():
        assert len(line) <= width, f"{len(line)} > {width}: {line!r}"
        assert not _SPLIT_PAIR.search(line), f"a pair split at {width} columns: {line!r}"
    assert "_{" not in result.out and "\\" not in result.out, "TeX source in the terminal"


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_wide_table_is_split_repeating_its_first_column(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("COLUMNS", "80")
    out = run("circle", "5", "--method", "bresenham", "--format", "rich").out
    assert "(part 1 of 2)" in out and "(part 2 of 2)" in out
    assert out.count("(x, y)") >= 2


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_grid_too_wide_says_how_to_see_it(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("COLUMNS", "60")
    result = run("circle", "20", "--format", "rich")
    assert "--svg" in result.err and "--no-grid" in result.err
    assert " | " not in result.out  # no grid rows


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_radius_12_grid_shrinks_its_cells_to_fit_80(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("COLUMNS", "80")
    out = run("circle", "12", "--format", "rich").out
    assert "12 | " in out and "o = centre" in out and "marked point" not in out


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_terminal_shows_the_working_unless_brief(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("COLUMNS", "80")
    full = run("line", "2", "2", "10", "6", "--algo", "bresenham", "--format", "rich").out
    brief = run("line", "2", "2", "10", "6", "--algo", "bresenham", "-f", "rich", "--brief").out
    for text in ("Δx = x₂ - x₁ = 10 - 2 = 8", "p₀ = 2Δy - Δx", "Notes:"):
        assert text in full and text not in brief
    assert "Pixels plotted (9):" in brief
    pixels = full.index("Pixels plotted")
    grid = full.index("7 | ")
    assert full[pixels:grid].endswith("\n\n"), "a blank line between the pixels and the grid"


@pytest.mark.parametrize("columns", [60, 80, 120])
def test_a_wrapped_note_keeps_its_indent(columns: int, monkeypatch: pytest.MonkeyPatch) -> None:
    """The "Conventions" note holds a bracket group longer than the line;
    it ran past the screen's edge and rich broke it at column 0. Each of the note's lines
    now fits the width and every line after its first keeps the note's indent; its words are
    the note's words, in order (none lost to the wrapping)."""
    from scanconv import _api

    monkeypatch.setenv("COLUMNS", str(columns))
    out = run("line", "2", "2", "10", "6", "--format", "rich").out.splitlines()
    start = next(i for i, ln in enumerate(out) if ln.startswith("  - Conventions"))
    end = next(i for i in range(start + 1, len(out)) if not out[i].startswith("    "))
    lines = out[start:end]
    assert len(lines) > 1 and all(len(ln) <= columns for ln in out), [len(ln) for ln in out]
    note = next(n for n in _api.line(2, 2, 10, 6, "bresenham").notes if n.startswith("Conv"))
    shown = " ".join(ln.strip() for ln in lines).removeprefix("- ")
    assert shown.split() == note.replace("$", "").split()
