"""Start-up stays lean: heavy modules load only on the paths that use them, and the CLI
builds only the subcommand it runs, with the same behaviour as the whole group.

(The timings themselves are in ``benchmarks/bench.py``; nothing here is timed.)
"""

from __future__ import annotations

import contextlib
import io
import subprocess
import sys

import pytest
import typer

from scanconv.cli import commands as cli

PROBE = """
import sys
from scanconv.cli import main
code = main({args!r})
heavy = {{"numpy", "rich", "tabulate", "pydantic"}}
loaded = sorted({{m.split(".")[0] for m in sys.modules}} & heavy)
print("LOADED", ",".join(loaded), code, file=sys.stderr)
"""


def loaded_after(*args: str) -> set[str]:
    proc = subprocess.run(
        [sys.executable, "-c", PROBE.format(args=list(args))],
        capture_output=True,
        text=True,
        timeout=120,
    )
    line = next(x for x in proc.stderr.splitlines() if x.startswith("LOADED"))
    _, names, code = line.split(" ")
    assert code == "0", proc.stderr
    return set(filter(None, names.split(",")))


@pytest.mark.parametrize("fmt", ["plain", "markdown", "csv", "json", "latex"])
def test_text_formats_load_no_numpy_rich_tabulate_or_pydantic(fmt):
    """pydantic would come with typer 0.29, which pyproject.toml excludes for its start-up."""
    assert (
        loaded_after("line", "2", "2", "10", "6", "--algo", "bresenham", "--format", fmt) == set()
    )


def test_rich_format_loads_rich():
    """The probe can see a heavy import when one happens."""
    assert "rich" in loaded_after("line", "2", "2", "10", "6", "--format", "rich")


def test_only_the_named_command_is_built():
    every = typer.main.get_command(cli.app).commands  # type: ignore[attr-defined]
    assert len(every) > 1
    assert list(cli._command_for(["line", "2", "2", "10", "6"]).commands) == ["line"]
    assert set(cli._command_for(["--version"]).commands) == set(every)
    assert set(cli._command_for(["no-such-command"]).commands) == set(every)
    assert set(cli._command_for([]).commands) == set(every)


def _help(command: object, args: list[str]) -> str:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.suppress(SystemExit):
        command.main(args=args, prog_name="scanconv", standalone_mode=False)  # type: ignore[attr-defined]
    return out.getvalue()


@pytest.mark.parametrize("name", sorted(typer.main.get_command(cli.app).commands))  # type: ignore[attr-defined]
def test_help_is_the_same_as_with_the_whole_group(name):
    whole = typer.main.get_command(cli.app)
    alone = cli._command_for([name, "--help"])
    assert list(alone.commands) == [name]
    assert _help(alone, [name, "--help"]) == _help(whole, [name, "--help"]) != ""
