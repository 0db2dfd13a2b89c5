"""The README and CI agree, every command is documented, and the docs' Python examples run
(the other claims of the README and docs/: tests/test_docs_claims.py)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import typer

from scanconv.cli import app

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text(encoding="utf-8")
COMMANDS = sorted(typer.main.get_command(app).commands)  # type: ignore[attr-defined]


def test_readme_opens_with_install_and_test_commands():
    blocks = re.findall(r"```sh\n(.*?)\n```", README, flags=re.S)
    assert (
        "pip install -e ." in blocks[0] and "scanconv line 2 2 10 6 --algo bresenham" in blocks[0]
    )
    assert "pip install -e '.[test]'" in blocks[1]


def test_ci_runs_the_readme_test_command():
    test_command = re.findall(r"```sh\n(.*?)\n```", README, flags=re.S)[1]
    test_part = test_command.split("pip install -e '.[test]' && ", 1)[1]
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert test_part in ci.splitlines()
    assert "pip install --quiet -e '.[test]'" in ci and "python3 -m venv" in ci


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("name", COMMANDS)
def test_every_command_has_help_and_a_readme_mention(name):
    command = typer.main.get_command(app).commands[name]  # type: ignore[attr-defined]
    assert command.help, f"{name} has no help"
    assert f"scanconv {name}" in README, f"README does not show `scanconv {name}`"


#: The pages whose ```python blocks are doctests (the README sends programmers to docs/api.md).
DOCTEST_PAGES = ["docs/api.md", "docs/library-numpy.md"]


@pytest.mark.parametrize(
    "page",
    [
        "docs/api.md",
        pytest.param("docs/library-numpy.md", marks=pytest.mark.slow),  # a circle of r = 10**6
    ],
)
def test_the_python_examples_of_the_docs_are_true(page):
    """Every ```python block of the page runs as a doctest and prints what it shows."""
    import doctest

    text = (ROOT / page).read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert blocks, f"{page} shows the Python API"
    parser = doctest.DocTestParser()
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    namespace: dict[str, object] = {}  # the blocks read as one session
    for i, block in enumerate(blocks):
        test = parser.get_doctest(block, namespace, f"{page} block {i + 1}", page, 0)
        test.globs = namespace
        runner.run(test, clear_globs=False)
    result = runner.summarize(verbose=False)
    assert result.failed == 0 and result.attempted > 0


def test_every_python_example_with_a_prompt_is_a_checked_doctest():
    """A page that shows ``>>>`` in a ```python block is one of :data:`DOCTEST_PAGES`."""
    pages = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
    shown = [
        str(p.relative_to(ROOT))
        for p in pages
        if any(">>>" in b for b in re.findall(r"```python\n(.*?)```", p.read_text("utf-8"), re.S))
    ]
    assert sorted(shown) == sorted(DOCTEST_PAGES)


def test_readme_has_a_cheat_sheet_of_exam_questions():
    sheet = README.split("## Cheat sheet", 1)[1].split("\n## ", 1)[0]
    rows = [r for r in sheet.splitlines() if r.startswith("| ") and "`scanconv" in r]
    assert len(rows) >= 20


def test_teaching_says_what_a_batch_does_with_an_unreadable_file(tmp_path):
    from .helpers import run

    folder = tmp_path / "class"
    folder.mkdir()
    (folder / "a.csv").write_bytes(b"\x00\x01")
    r = run("check", "--batch", str(folder), "--", "line", "2", "2", "10", "6")
    assert r.code == 0 and "not marked" in r.out
    teaching = (ROOT / "docs" / "teaching.md").read_text(encoding="utf-8")
    assert "`not marked: ...`" in teaching and "stops the batch" not in teaching
