"""The entry point: run the command line, and turn whatever goes wrong into an exit status.

Bad input is one line on stderr and exit status 2 (click's usage errors here; the library's
``ValueError`` in :func:`scanconv.cli.command.answers`), a failure to write is 1, Ctrl-C is 130
and SIGTERM 143; no traceback reaches the user.
"""

from __future__ import annotations

import copy
import functools
import gc
import signal
import sys
from typing import Any

import typer
from typer._click import exceptions as click_exc  # typer vendors click

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
    anything else (``--help``, ``--version``, an unknown name) gets the whole group. Only the
    command's name picks it (a group's and its command's: groups nest one deep), so a
    process that calls :func:`main` again (a notebook, the tests) reuses the command built
    for that name (click keeps no state in a command between runs).

    >>> _command_for(["line", "2", "2", "10", "6"]) is _command_for(["line", "0", "0", "1", "1"])
    True
    """
    group = bool(argv) and any(g.name == argv[0] for g in register(argv[:1]).registered_groups)
    return _built(tuple(argv[: 2 if group else 1]))


@functools.lru_cache(maxsize=128)
def _built(words: tuple[str, ...]) -> Any:
    """The click command for a command line starting with ``words``, its command's name
    (:func:`_command_for`)."""
    argv = list(words)
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
    SIGTERM into a one-line exit 130 or 143 (:func:`scanconv.cli.output.catch_signals`),
    and freezes the objects of its start-up (:func:`gc.freeze`: the modules, typer's and its
    own, and the command live until exit, so no collection walks them again, the last one at
    exit included; about a fifth of scanconv's own start-up), then turns the collector back
    on (:func:`scanconv.__main__.run` turns it off for the imports and the command's build,
    which make only such objects: a quarter of scanconv's own start-up more). Called
    in-process with ``argv``
    it leaves the caller's signal handlers and collector alone, so that a SIGTERM to a test
    runner still ends it."""
    as_program = argv is None
    if as_program and signal.getsignal(signal.SIGINT) is signal.SIG_IGN:  # a shell's background
        signal.signal(signal.SIGINT, signal.default_int_handler)
    if argv is None:
        argv = sys.argv[1:]
    # "-inf"/"-nan" would be read as bundled short options (-i -n -f ...); keep them arguments
    # so the number parser names them.
    argv = [_MINUS + a[1:] if a.lower() in _NONFINITE else a for a in students(argv)]
    command = _command_for(argv)
    if as_program:  # what start-up made lives until exit: the collector (at exit too) skips it
        gc.freeze()
        gc.enable()  # run() turned it off for the start-up
    restore_signals = output.catch_signals() if as_program else _nothing
    try:
        return _run(command, argv)
    finally:
        restore_signals()


def _run(command: Any, argv: list[str]) -> int:
    """Run one command; its exit status, with bad input, signals and write failures turned
    into one line on stderr (:func:`_status`). A closed pipe is quiet, the help too."""
    try:
        try:
            result = command.main(args=argv, prog_name=PROG, standalone_mode=False)
        except click_exc.NoArgsIsHelpError as err:  # ``scanconv``, ``scanconv parametric``
            print(err.ctx.get_help() if err.ctx is not None else err.format_message())
            result = 0
        sys.stdout.flush()
        return result if isinstance(result, int) else 0
    except BrokenPipeError:  # ``scanconv | head``: the reader has gone
        return output._quiet_pipe()
    except BaseException as err:  # each kind is mapped to a status; the rest re-raised
        return _status(err)


def _status(err: BaseException) -> int:
    """The exit status of an exception a command raised, its one line written to stderr."""
    if isinstance(err, click_exc.UsageError):
        note(f"error: {_usage_message(err)}")
        return 2
    if isinstance(err, click_exc.ClickException):
        note(f"error: {' '.join(err.format_message().split())}")
        return err.exit_code
    if isinstance(err, typer.Abort | KeyboardInterrupt):
        return 130
    if isinstance(err, typer.Exit):
        return err.exit_code
    if isinstance(err, output.Interrupted):  # SIGINT, SIGTERM: one line, 130 or 143
        note(str(err))
        return int(err.code or 1)
    if isinstance(err, SystemExit):
        return err.code if isinstance(err.code, int) else 1
    return _failure(err)


def _failure(err: BaseException) -> int:
    """Bad input found while the answer was streaming, a failed write, running out."""
    if isinstance(err, OSError):
        note(f"error: cannot write output: {err.strerror or err}")
        return 1
    if isinstance(err, RecursionError):
        note("error: input too deeply nested")
        return 2
    if isinstance(err, ValueError):  # bad input found while the answer was already streaming
        note(f"error: {' '.join(str(err).split())}")
        return 2
    if isinstance(err, MemoryError):
        note("error: out of memory (see docs/limits.md for the input limits)")
        return 1
    raise err


def _nothing() -> None:
    """Nothing to restore: an in-process run installs no signal handler."""


_terminate = output.on_signal
"""The handler of SIGINT and SIGTERM during a run (:func:`scanconv.cli.output.on_signal`)."""
