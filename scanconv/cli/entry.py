"""The entry point: run the command line, and turn whatever goes wrong into an exit status.

Bad input is one line on stderr and exit status 2 (click's usage errors here; the library's
``ValueError`` in :func:`scanconv.cli.command.answers`), a failure to write is 1, Ctrl-C is 130
and SIGTERM 143; no traceback reaches the user.
"""

from __future__ import annotations

import copy
import re
import signal
import sys
from typing import Any, NoReturn

import typer

from . import output
from .application import app
from .output import PROG, note

_MINUS = "\u2212"
_NEG_NONFINITE = re.compile(r"-(inf|infinity|nan)$", re.IGNORECASE)


def _command_for(argv: list[str]) -> Any:
    """The click command for ``argv``, building only the subcommand it names.

    typer turns the signature of every command into click parameters each time the CLI
    starts, a cost that grows with each command added. A run that names its subcommand
    (``scanconv line ...``, ``scanconv parametric circle ...``) gets groups holding just that
    one, with the same callbacks and settings, so its parsing, help and errors are unchanged;
    anything else (``--help``, ``--version``, an unknown name) gets the whole group.
    """
    return typer.main.get_command(_only(app, argv))


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


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; return (and exit with) its status. Never shows a traceback for bad input."""
    from typer._click import exceptions as click_exc  # typer vendors click

    if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:  # started in the background by a shell
        signal.signal(signal.SIGINT, signal.default_int_handler)
    if argv is None:
        argv = sys.argv[1:]
    # "-inf"/"-nan" would be read as bundled short options (-i -n -f ...); keep them arguments
    # so the number parser names them.
    argv = [_MINUS + a[1:] if _NEG_NONFINITE.match(a) else a for a in argv]
    command = _command_for(argv)
    code = 0
    previous_term = _catch_sigterm()
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
        _restore_sigterm(previous_term)
    return code


def _catch_sigterm() -> Any:
    """Turn SIGTERM into ``SystemExit(143)`` so a file being written is cleaned up (its
    temporary is removed; the target is untouched). Returns the handler to restore."""
    try:
        return signal.signal(signal.SIGTERM, _terminate)
    except ValueError:  # not the main thread: leave signals alone
        return None


def _terminate(signum: int, frame: Any) -> NoReturn:
    raise SystemExit(128 + signum)


def _restore_sigterm(handler: Any) -> None:
    if handler is not None:
        signal.signal(signal.SIGTERM, handler)
