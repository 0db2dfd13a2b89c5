"""The README and CI agree, and every command is documented."""

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


def test_readme_python_examples_are_true():
    """Every ```python block of the README runs as a doctest and prints what it shows."""
    import doctest

    blocks = re.findall(r"```python\n(.*?)```", README, flags=re.S)
    assert blocks, "the README shows the Python API"
    parser = doctest.DocTestParser()
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    namespace: dict[str, object] = {}  # the blocks read as one session
    for i, block in enumerate(blocks):
        test = parser.get_doctest(block, namespace, f"README block {i + 1}", "README.md", 0)
        test.globs = namespace
        runner.run(test, clear_globs=False)
    result = runner.summarize(verbose=False)
    assert result.failed == 0 and result.attempted > 0


EXAMPLES = re.findall(r"```text\n\$ scanconv (.*?)\n(.*?)```", README, flags=re.S)


@pytest.mark.parametrize("command,shown", EXAMPLES, ids=[c for c, _ in EXAMPLES])
def test_readme_outputs_are_true(command, shown):
    """Every ``$ scanconv ...`` block of the README shows what the command prints today."""
    import shlex

    from .helpers import run

    result = run(*shlex.split(command))
    assert result.code == 0, result.err
    assert result.out.rstrip() == shown.rstrip(), f"README: rerun `scanconv {command}`"


def test_readme_has_a_cheat_sheet_of_exam_questions():
    sheet = README.split("## Cheat sheet", 1)[1].split("\n## ", 1)[0]
    rows = [r for r in sheet.splitlines() if r.startswith("| ") and "`scanconv" in r]
    assert len(rows) >= 20


def test_the_readme_counts_the_theory_topics_it_lists():
    """A count the README states is the program's: ``theory --list`` has one line a topic."""
    import re

    from .helpers import run

    said = re.search(r"`scanconv theory --list` names the (\d+) topics", README)
    assert said is not None
    listed = [ln for ln in run("theory", "--list").out.splitlines() if ln.strip()]
    assert int(said[1]) == len(listed)


def test_teaching_says_what_a_batch_does_with_an_unreadable_file(tmp_path):
    from .helpers import run

    folder = tmp_path / "class"
    folder.mkdir()
    (folder / "a.csv").write_bytes(b"\x00\x01")
    r = run("check", "--batch", str(folder), "--", "line", "2", "2", "10", "6")
    assert r.code == 0 and "not marked" in r.out
    teaching = (ROOT / "docs" / "teaching.md").read_text(encoding="utf-8")
    assert "`not marked: ...`" in teaching and "stops the batch" not in teaching
