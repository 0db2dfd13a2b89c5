"""The entry point: run the command line, and turn whatever goes wrong into an exit status.

Bad input is one line on stderr and exit status 2 (click's usage errors here; the library's
``ValueError`` in :func:`scanconv.cli.command.answers`), a failure to write is 1, Ctrl-C is 130
and SIGTERM 143; no traceback reaches the user.
"""

from __future__ import annotations

import copy
import signal
import sys
from typing import Any

import typer

from ..questions.words import MINUS, NONFINITE, students, usage_message
from . import output
from .application import register
from .output import PROG, note

__all__ = ["main", "students"]

_MINUS, _NONFINITE = MINUS, NONFINITE  # the question language's (scanconv.questions.words)


def _command_for(argv: list[str]) -> Any:
    """The click command for ``argv``, building only the subcommand it names.

    typer turns the signature of every command into click parameters each time the CLI
    starts, a cost that grows with each command added. A run that names its subcommand
    (``scanconv line ...``, ``scanconv parametric circle ...``) gets groups holding just that
    one, with the same callbacks and settings, so its parsing, help and errors are unchanged;
    anything else (``--help``, ``--version``, an unknown name) gets the whole group.
    """
    return typer.main.get_command(_only(register(argv), argv))


def _only(group: typer.Typer, argv: list[str]) -> typer.Typer:
    """``group`` with only the command or sub-group ``argv[0]`` names (itself if none)."""
    if not argv or argv[0].startswith("-"):
        return group
    commands = [
        c
        for c in group.registered_commands
        if c.callback is not None
        and (c.name or typer.main.get_command_name(c.callback.__name__)) == argv[0]
    ]
    groups = [copy.copy(g) for g in group.registered_groups if g.name == argv[0]]
    if not commands and not groups:
        return group
    for g in groups:
        if g.typer_instance is not None:
            g.typer_instance = _only(g.typer_instance, argv[1:])
    one = copy.copy(group)
    one.registered_commands, one.registered_groups = commands, groups
    return one


def _usage_message(err: Exception) -> str:
    """click's message, in the words a student expects (:func:`usage_message`)."""
    return usage_message(err.format_message())  # type: ignore[attr-defined]


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; return (and exit with) its status. Never shows a traceback for bad input.

    Run as the program (``argv`` None: the arguments are ``sys.argv``), it turns SIGINT and
    SIGTERM into a one-line exit 130 or 143 (:func:`scanconv.cli.output.catch_signals`);
    called in-process with ``argv`` it leaves the caller's signal handlers alone, so that a
    SIGTERM to a test runner still ends it."""
    from typer._click import exceptions as click_exc  # typer vendors click

    as_program = argv is None
    if as_program and signal.getsignal(signal.SIGINT) is signal.SIG_IGN:  # a shell's background
        signal.signal(signal.SIGINT, signal.default_int_handler)
    if argv is None:
        argv = sys.argv[1:]
    # "-inf"/"-nan" would be read as bundled short options (-i -n -f ...); keep them arguments
    # so the number parser names them.
    argv = [_MINUS + a[1:] if a.lower() in _NONFINITE else a for a in students(argv)]
    command = _command_for(argv)
    code = 0
    restore_signals = output.catch_signals() if as_program else _nothing
    try:
        result = command.main(args=argv, prog_name=PROG, standalone_mode=False)
        code = result if isinstance(result, int) else 0
        sys.stdout.flush()
    except click_exc.NoArgsIsHelpError as err:  # ``scanconv``, ``scanconv parametric``
        print(err.ctx.get_help() if err.ctx is not None else err.format_message())
        code = 0
    except click_exc.UsageError as err:
        note(f"error: {_usage_message(err)}")
        code = 2
    except click_exc.ClickException as err:
        note(f"error: {' '.join(err.format_message().split())}")
        code = err.exit_code
    except typer.Abort:
        code = 130
    except typer.Exit as err:
        code = err.exit_code
    except output.Interrupted as err:  # SIGINT, SIGTERM: one line, 130 or 143
        note(str(err))
        code = int(err.code or 1)
    except SystemExit as err:
        code = err.code if isinstance(err.code, int) else 1
    except KeyboardInterrupt:
        code = 130
    except BrokenPipeError:
        code = output._quiet_pipe()
    except OSError as err:
        note(f"error: cannot write output: {err.strerror or err}")
        code = 1
    except RecursionError:
        note("error: input too deeply nested")
        code = 2
    except ValueError as err:  # bad input found while the answer was already streaming
        note(f"error: {' '.join(str(err).split())}")
        code = 2
    except MemoryError:
        note("error: out of memory (see docs/limits.md for the input limits)")
        code = 1
    finally:
        restore_signals()
    return code


def _nothing() -> None:
    """Nothing to restore: an in-process run installs no signal handler."""


_terminate = output.on_signal
"""The handler of SIGINT and SIGTERM during a run (:func:`scanconv.cli.output.on_signal`)."""
