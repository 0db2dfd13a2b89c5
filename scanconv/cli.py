"""The ``scanconv`` command line: parse, pick the renderer, print.

This is the only module that writes to stdout or stderr. The algorithms and renderers never
print; they return generators, and :func:`emit` writes what they yield. Errors in the input
become one line on stderr and exit status 2; a failure to write is exit status 1.
"""

from __future__ import annotations

import os
import re
import sys
import tempfile
from collections.abc import Iterable
from enum import Enum
from fractions import Fraction
from pathlib import Path
from typing import Annotated, Any, NoReturn

import typer

from . import __version__
from .numeric import parse_number
from .records import Solution
from .render import Format, Notice, Options, render

PROG = "scanconv"

app = typer.Typer(
    name=PROG,
    help="Scan-conversion algorithms as exam-style worked solutions: the derivation, the step "
    "table, the pixels and a pixel grid. Coordinates are (x, y) with y up.",
    add_completion=False,
    rich_markup_mode=None,
    pretty_exceptions_enable=False,
    no_args_is_help=True,
    context_settings={"help_option_names": ["-h", "--help"]},
)

#: Commands that take numbers as positional arguments accept negative ones (``-3``) too.
NUMERIC_ARGS: dict[str, Any] = {"ignore_unknown_options": True}


class Origin(str, Enum):
    """Where the grid's origin is drawn."""

    bottom_left = "bottom-left"
    top_left = "top-left"


class LineAlgo(str, Enum):
    """Line algorithms."""

    bresenham = "bresenham"
    dda = "dda"
    basic = "basic"


def number(text: str) -> Fraction:
    """typer parser for an exact number (integer, decimal or a/b)."""
    try:
        return parse_number(text)
    except ValueError as err:
        raise typer.BadParameter(str(err)) from None


# Shared options, declared once.
FormatOpt = Annotated[
    Format,
    typer.Option(
        "--format",
        "-f",
        case_sensitive=False,
        help="Output format. auto: rich on a terminal, markdown otherwise.",
    ),
]
GridOpt = Annotated[bool, typer.Option("--grid/--no-grid", help="Draw the text pixel grid.")]
OriginOpt = Annotated[
    Origin,
    typer.Option(
        "--origin",
        case_sensitive=False,
        help="Grid orientation: bottom-left (y up, as in the notes) or top-left (screen, y down).",
    ),
]
OutputOpt = Annotated[
    Path | None,
    typer.Option(
        "--output",
        "-o",
        help="Write to this file (atomically: complete or not at all) instead of stdout.",
        dir_okay=False,
    ),
]


Num = Annotated[Fraction, typer.Argument(parser=number, show_default=False)]
"""A positional exact number (integer, decimal or a/b); negative values are accepted."""


# --- output -----------------------------------------------------------------------------------


def resolve(fmt: Format, to_file: bool) -> Format:
    """Resolve ``auto`` once, at the edge: rich on a terminal, markdown otherwise."""
    if fmt is not Format.auto:
        return fmt
    return Format.rich if (not to_file and sys.stdout.isatty()) else Format.markdown


def note(message: str) -> None:
    """A one-line message on stderr."""
    print(f"{PROG}: {message}", file=sys.stderr)


def fail(message: str, code: int = 2) -> NoReturn:
    """One line on stderr, then exit."""
    note(f"error: {message}")
    raise typer.Exit(code)


def _write(chunks: Iterable[Any], out: Any, fmt: Format) -> None:
    console = None
    for chunk in chunks:
        if isinstance(chunk, str):
            out.write(chunk)
        elif isinstance(chunk, Notice):
            out.flush()
            note(chunk.message)
        else:
            if console is None:
                from rich.console import Console

                console = Console(file=out, highlight=False, emoji=False, markup=False)
            console.print(chunk)


def emit(
    solution: Solution,
    fmt: Format,
    *,
    grid: bool = True,
    origin: Origin = Origin.bottom_left,
    output: Path | None = None,
) -> None:
    """Render ``solution`` and write it to stdout or, atomically, to ``output``."""
    fmt = resolve(fmt, output is not None)
    chunks = render(solution, fmt, Options(grid=grid, origin=origin.value))
    if output is None:
        try:
            _write(chunks, sys.stdout, fmt)
            sys.stdout.flush()
        except BrokenPipeError:
            _quiet_pipe()
        return
    write_atomic(output, lambda f: _write(chunks, f, fmt))


def write_atomic(path: Path, fill: Any) -> None:
    """Create ``path`` through a temporary file in its directory and a rename.

    A failure leaves any existing file untouched and no partial file behind (exit 1).
    """
    directory = path.parent if str(path.parent) else Path(".")
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=directory)
    except OSError as err:
        fail(f"cannot write {path}: {err.strerror or err}", 1)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as f:
            fill(f)
        os.replace(tmp, path)
    except OSError as err:
        _unlink(tmp)
        fail(f"cannot write {path}: {err.strerror or err}", 1)
    except BaseException:
        _unlink(tmp)
        raise


def _unlink(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass


def library_call(fn: Any, *args: Any, **kwargs: Any) -> Any:
    """Call into the library; its ``ValueError`` is a bad-input error (exit 2)."""
    try:
        return fn(*args, **kwargs)
    except ValueError as err:
        fail(str(err))


# --- commands ---------------------------------------------------------------------------------


@app.command(context_settings=NUMERIC_ARGS)
def line(
    x1: Num,
    y1: Num,
    x2: Num,
    y2: Num,
    algo: Annotated[
        LineAlgo,
        typer.Option("--algo", "-a", case_sensitive=False, help="Line algorithm."),
    ] = LineAlgo.bresenham,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
) -> None:
    """Draw the line from (X1, Y1) to (X2, Y2), with the step table of the chosen algorithm.

    Example: scanconv line 2 2 10 6 --algo bresenham
    """
    from .lines import line_solution

    solution = library_call(line_solution, algo.value, x1, y1, x2, y2)
    emit(solution, fmt, grid=grid, origin=origin, output=output)


def _version(value: bool) -> None:
    if value:
        print(f"{PROG} {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: Annotated[
        bool,
        typer.Option("--version", callback=_version, is_eager=True, help="Show the version."),
    ] = False,
) -> None:
    """Scan-conversion algorithms as exam-style worked solutions."""


# --- entry point ------------------------------------------------------------------------------


_MINUS = "\u2212"
_NEG_NONFINITE = re.compile(r"-(inf|infinity|nan)$", re.IGNORECASE)


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; return (and exit with) its status. Never shows a traceback for bad input."""
    from typer._click import exceptions as click_exc  # typer vendors click

    command = typer.main.get_command(app)
    if argv is None:
        argv = sys.argv[1:]
    # "-inf"/"-nan" would be read as bundled short options (-i -n -f ...); keep them arguments
    # so the number parser names them.
    argv = [_MINUS + a[1:] if _NEG_NONFINITE.match(a) else a for a in argv]
    code = 0
    try:
        result = command.main(args=argv, prog_name=PROG, standalone_mode=False)
        code = result if isinstance(result, int) else 0
        sys.stdout.flush()
    except click_exc.UsageError as err:
        message = " ".join(err.format_message().split()).replace("Value error, ", "")
        note(f"error: {message}")
        code = 2
    except click_exc.ClickException as err:
        note(f"error: {' '.join(err.format_message().split())}")
        code = err.exit_code
    except typer.Abort:
        code = 130
    except typer.Exit as err:
        code = err.exit_code
    except SystemExit as err:
        code = err.code if isinstance(err.code, int) else 1
    except KeyboardInterrupt:
        code = 130
    except BrokenPipeError:
        code = _quiet_pipe()
    except OSError as err:
        note(f"error: cannot write output: {err.strerror or err}")
        code = 1
    except RecursionError:
        note("error: input too deeply nested")
        code = 2
    return code


def _quiet_pipe() -> int:
    """The reader went away (``| head``): stop quietly with status 0.

    What was wanted was read; later writes (and the interpreter's final flush) go to
    ``/dev/null`` so no ``BrokenPipeError`` text reaches the terminal.
    """
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass
    return 0
