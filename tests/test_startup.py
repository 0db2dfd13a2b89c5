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

from scanconv.cli import app
from scanconv.cli.entry import _command_for

PROBE = """
import sys
from scanconv.cli import main
code = main({args!r})
heavy = {{"numpy", "rich", "tabulate", "pydantic", "latex2mathml"}}
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


#: Each probe is a fresh interpreter (about 0.3 s of CPU): one stays in the inner loop, the
#: others run in the whole suite.
SLOW = pytest.mark.slow


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize(
    "fmt", ["plain", *(pytest.param(f, marks=SLOW) for f in ("csv", "json", "latex"))]
)
def test_text_formats_load_no_numpy_rich_tabulate_or_pydantic(fmt):
    """pydantic would come with typer 0.29, which pyproject.toml excludes for its start-up."""
    assert (
        loaded_after("line", "2", "2", "10", "6", "--algo", "bresenham", "--format", fmt) == set()
    )


@SLOW
def test_only_markdown_loads_tabulate():
    """tabulate pads the Markdown tables; its import (importlib.metadata) is paid there only."""
    assert loaded_after("line", "2", "2", "10", "6", "--format", "markdown") == {"tabulate"}


@SLOW
def test_only_html_loads_latex2mathml():
    """latex2mathml (about 55 ms: importlib.metadata) is imported by the html format only."""
    assert loaded_after("line", "2", "2", "10", "6", "--format", "html") == {"latex2mathml"}


@SLOW
def test_rich_format_loads_rich():
    """The probe can see a heavy import when one happens."""
    assert "rich" in loaded_after("line", "2", "2", "10", "6", "--format", "rich")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_only_the_named_command_is_built():
    every = typer.main.get_command(app).commands  # type: ignore[attr-defined]
    assert len(every) > 1
    assert list(_command_for(["line", "2", "2", "10", "6"]).commands) == ["line"]
    assert set(_command_for(["--version"]).commands) == set(every)
    assert set(_command_for(["no-such-command"]).commands) == set(every)
    assert set(_command_for([]).commands) == set(every)


SIGNATURES = """
from scanconv.cli.application import app
from scanconv.cli.entry import _command_for
_command_for({args!r})
groups = [app, *(g.typer_instance for g in app.registered_groups)]
callbacks = [c.callback for g in groups for c in g.registered_commands]
print(*sorted(c.__name__ for c in callbacks if "parameters" in vars(c)))
"""


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize(
    ("args", "built"),
    [
        (["line", "2", "2", "10", "6"], "line"),
        pytest.param(["parametric", "circle"], "parametric_circle", marks=SLOW),
    ],
)
def test_only_the_named_command_works_out_its_signature(args, built):
    """``@answers`` adds the shared options when typer first reads a command's signature, so
    a run evaluates only its own command's annotations (the others stay as written)."""
    code = SIGNATURES.format(args=args)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.stdout.split() == [built], out.stderr


WHOLE = typer.main.get_command(app)
"""The whole group, built once (building it is most of each help comparison's cost)."""


def _help(command: object, args: list[str]) -> str:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.suppress(SystemExit):
        command.main(args=args, prog_name="scanconv", standalone_mode=False)  # type: ignore[attr-defined]
    return out.getvalue()


@pytest.mark.parametrize("name", sorted(WHOLE.commands))  # type: ignore[attr-defined]
def test_help_is_the_same_as_with_the_whole_group(name):
    alone = _command_for([name, "--help"])
    assert list(alone.commands) == [name]
    assert _help(alone, [name, "--help"]) == _help(WHOLE, [name, "--help"]) != ""


GROUPED = sorted(
    (group, name)
    for group, sub in WHOLE.commands.items()  # type: ignore[attr-defined]
    for name in getattr(sub, "commands", {})
)


@pytest.mark.parametrize(("group", "name"), GROUPED, ids=[" ".join(p) for p in GROUPED])
def test_a_command_of_a_group_is_built_alone_with_the_same_help(group, name):
    alone = _command_for([group, name, "--help"])
    assert list(alone.commands) == [group]
    assert list(alone.commands[group].commands) == [name]
    args = [group, name, "--help"]
    assert _help(alone, args) == _help(WHOLE, args) != ""
