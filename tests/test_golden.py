"""Golden files: one worked example per file under ``golden/<topic>/``.

Line 1 of each file is the exact command (``$ scanconv ...``); everything after it is the exact
stdout. Terminal answers (``*.rich.txt``) are printed at 80 columns (``COLUMNS=80``), the
width a person's terminal usually has; ``tests/test_terminal_width.py`` checks other widths. ``pytest --update-golden`` rewrites the files from the current output and then fails,
so every change to expected output is reviewed in the diff.

Besides byte equality, every case checks one invariant (black's habit of checking more than
the bytes): the pixels its format shows are the pixels of the same question's JSON answer, so
a renderer that drops or reorders rows in one format fails even if its golden file was
rewritten with the mistake.
"""

from __future__ import annotations

import json
import os
import re
import shlex
from pathlib import Path

import pytest

from .cli_vocabulary import NOT_WALKED
from .helpers import run

GOLDEN = Path(
    os.environ.get("SCANCONV_GOLDEN_DIR") or Path(__file__).resolve().parent.parent / "golden"
)
FILES = sorted(p for p in GOLDEN.rglob("*") if p.is_file() and not p.name.startswith("."))
#: Question files of the sheet cases (golden/teach/*.questions) are inputs, not cases; a case
#: names them from the repository's root, where every case runs.
FILES = [p for p in FILES if p.suffix != ".questions"]
IDS = [p.relative_to(GOLDEN).as_posix() for p in FILES]

#: Options that take a value and do not change the answer's content (dropped for the JSON run).
_OUTPUT_OPTIONS = {"-f", "--format", "-o", "--output", "--origin", "--svg", "--png"}
#: Flags that change only how the answer is shown (dropped for the JSON run).
_FLAGS = ("--explain", "--brief", "--exact", "--no-grid")
_PAIR = re.compile(r"\((-?\d+), (-?\d+)\)")


def read_case(path: Path) -> tuple[list[str], str]:
    first, _, expected = path.read_text(encoding="utf-8").partition("\n")
    assert first.startswith("$ scanconv "), f"{path.name}: first line must be '$ scanconv ...'"
    return shlex.split(first[2:])[1:], expected


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_golden(
    path: Path, request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch
) -> None:
    args, expected = read_case(path)
    if path.name.endswith(".rich.txt") or ".rich-" in path.name:
        monkeypatch.setenv("COLUMNS", "80")
    monkeypatch.chdir(GOLDEN.parent)
    result = run(*args)
    assert result.code == 0, result.err
    if request.config.getoption("--update-golden"):
        if result.out != expected:
            first = path.read_text(encoding="utf-8").partition("\n")[0]
            path.write_text(f"{first}\n{result.out}", encoding="utf-8")
            pytest.fail(f"{path.name} rewritten; review the diff and commit it")
        return
    assert result.out == expected


def _as_json(args: list[str]) -> list[str]:
    out: list[str] = []
    skip = False
    for a in args:
        if skip:
            skip = False
        elif a in _OUTPUT_OPTIONS:
            skip = True
        elif a.split("=", 1)[0] in _OUTPUT_OPTIONS or a in _FLAGS:
            pass
        else:
            out.append(a)
    return [*out, "--format", "json"]


def shown_pixels(text: str) -> list[tuple[int, int]] | None:
    """The pixel list a text answer shows under its "Pixels plotted (N)" heading, or ``None``
    if it shows none. The list runs until the first line without a pair.

    >>> shown_pixels("Pixels plotted (2):\\n  (1, 2), (3, -4)\\n\\n1 | #")
    [(1, 2), (3, -4)]
    """
    lines = text.splitlines()
    for i, line in enumerate(lines):
        m = re.search(r"Pixels plotted \((\d+)\)", line)
        if not m:
            continue
        pixels: list[tuple[int, int]] = []
        for follow in lines[i + 1 :]:
            if not follow.strip() or follow.strip() in (r"{\raggedright", r"\par}"):
                if pixels:
                    break
                continue
            found = _PAIR.findall(follow)
            if not found or "|" in follow:
                break
            pixels.extend((int(x), int(y)) for x, y in found)
        assert len(pixels) == int(m.group(1)), "the heading's count is the list's length"
        return pixels
    return None


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_golden_shows_the_json_answers_pixels(path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    args, expected = read_case(path)
    monkeypatch.chdir(GOLDEN.parent)
    answer = json.loads(run(*_as_json(args)).out)
    if path.suffix != ".json" and "questions" in answer:  # a sheet: its first answer, if any
        answer = answer["questions"][0].get("answer", {})  # (tests/test_sheet.py: every one)
    pixels = [tuple(p) for p in answer.get("pixels") or []]
    steps = [tuple(s["pixel"]) for s in answer.get("steps", []) if "pixel" in s]
    if path.suffix == ".json":
        assert json.loads(expected) == answer
    elif path.suffix == ".csv":
        header, *rows = [r.split(",") for r in expected.splitlines()]
        px, py = ("plot_x", "plot_y") if "plot_x" in header else ("x", "y")
        if px in header and py in header and "k" in header:
            ix, iy = header.index(px), header.index(py)
            assert [(int(r[ix]), int(r[iy])) for r in rows] == steps
    else:
        shown = shown_pixels(expected)
        assert (shown or []) == pixels


def _commands() -> set[str]:
    import typer

    from scanconv.cli import app

    def walk(group: object, prefix: str) -> set[str]:
        names = set()
        for name, cmd in getattr(group, "commands", {}).items():
            if getattr(cmd, "commands", None):
                names |= walk(cmd, f"{prefix}{name} ")
            else:
                names.add(f"{prefix}{name}")
        return names

    return walk(typer.main.get_command(app), "")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_every_command_and_format_has_a_golden_case() -> None:
    if os.environ.get("SCANCONV_GOLDEN_DIR"):
        pytest.skip("a custom golden directory: the coverage rule is for the project's own")
    cases = [read_case(p)[0] for p in FILES]
    joined = [" ".join(a) for a in cases]
    walked = _commands() - {" ".join(path) for path in NOT_WALKED}  # tested where it says
    missing = sorted(c for c in walked if not any(j.startswith(c + " ") for j in joined))
    assert not missing, f"commands without a golden case: {missing}"
    suffixes = {p.name.split(".", 1)[1] for p in FILES}
    assert {"txt", "rich.txt", "md", "tex", "csv", "json"} <= suffixes
    for algo in ("bresenham", "dda", "basic"):
        assert any(j.startswith("line ") and f"--algo {algo}" in j for j in joined), algo
    for method in ("midpoint", "bresenham", "polynomial", "trig", "symmetric-dda", "general"):
        assert any(j.startswith("circle ") and f"--method {method}" in j for j in joined), method
