"""``scanconv check``: mark a student's table against a question, one file or a folder.

The question is another scanconv command line (``line 2 2 10 6 --algo bresenham``), parsed by
that command's own click parameters and run in-process: :func:`solve` swaps each command's
writer (:class:`~scanconv.cli.command.Command`) for one that returns the
:class:`~scanconv.core.records.Solution` instead of writing it, so the question means exactly
what it means on the command line, flags, conventions and error messages included.
"""

from __future__ import annotations

import copy
import inspect
import sys
from pathlib import Path
from typing import Annotated, Any

import typer

from ..core.records import Solution
from ..render import Format
from .application import app
from .budget import check_question
from .command import SHARED, Command, error_message
from .options import BriefOpt, ExactOpt, FormatOpt, OutputOpt
from .output import PROG, Output, emit, fail, format_for_file, write_atomic

#: Commands that are not questions (they would mark, or write sheets, themselves).
NOT_QUESTIONS = ("check", "sheet", "practice")

#: Output options written after the question still belong to ``check`` (the question's own
#: answer is never written): ``check a.csv -- line 2 2 10 6 -f md`` is markdown.
_OWN_VALUED = {"-f": "fmt", "--format": "fmt", "-o": "output", "--output": "output"}
_OWN_FLAGS = {"--brief": "brief", "--exact": "exact"}


class _Capture(Command):
    """A command that returns its Solution instead of writing it."""

    def __call__(self, **kwargs: Any) -> Any:
        own = inspect.signature(self.__wrapped__).parameters
        for name in SHARED:
            if name in kwargs and name not in own:
                del kwargs[name]
        check_question(self.__name__, kwargs)  # the document budget, before any work
        return self.__wrapped__(**kwargs)


def _capturing(group: typer.Typer) -> typer.Typer:
    """A copy of ``group`` whose commands return their Solution (the app is not touched)."""
    one = copy.copy(group)
    one.registered_commands = []
    for info in group.registered_commands:
        info = copy.copy(info)
        cb = info.callback
        if isinstance(cb, Command):
            info.callback = _Capture(cb.__wrapped__, cb._shared)
        one.registered_commands.append(info)
    one.registered_groups = []
    for g in group.registered_groups:
        g = copy.copy(g)
        if g.typer_instance is not None:
            g.typer_instance = _capturing(g.typer_instance)
        one.registered_groups.append(g)
    return one


def solve(question: list[str]) -> Solution:
    """The Solution of a scanconv command line, computed in-process.

    >>> solve(["line", "2", "2", "10", "6"]).title
    "Bresenham's line algorithm: (2, 2) to (10, 6)"
    """
    from typer._click import exceptions as click_exc

    from .application import register
    from .entry import _only, students

    if not question:
        raise ValueError("no question after --: give a scanconv command, e.g. -- line 2 2 10 6")
    argv = students(question)
    if argv[0] in NOT_QUESTIONS or argv[0].startswith("-"):
        raise ValueError(
            f"the question must be a scanconv command with a step table, not {argv[0]!r}"
        )
    if any(a in ("-h", "--help", "--version") for a in argv):
        raise ValueError("the question cannot ask for --help")
    figure = next((a for a in argv if a.split("=")[0] in ("--svg", "--png")), None)
    if figure is not None:
        raise ValueError(
            f"{figure.split('=')[0]}: check draws no figure; leave it out of the question"
        )
    command = typer.main.get_command(_capturing(_only(register(argv), argv)))
    try:
        result = command.main(args=argv, prog_name=PROG, standalone_mode=False)
    except click_exc.NoArgsIsHelpError:
        raise ValueError(
            f"question: {' '.join(question)!r} is incomplete (see scanconv {argv[0]} --help)"
        ) from None
    except click_exc.UsageError as err:
        raise ValueError(f"question: {' '.join(err.format_message().split())}") from None
    except click_exc.ClickException as err:
        raise ValueError(f"question: {' '.join(err.format_message().split())}") from None
    except ValueError as err:
        params = _params_of(command, argv)
        raise ValueError(f"question: {error_message(err, params)}") from None
    if not isinstance(result, Solution):
        raise ValueError(f"the question {' '.join(question[:3])!r} is not a command with an answer")
    if not result.columns:
        raise ValueError(f"the question {' '.join(question[:3])!r} has no step table to mark")
    return result


def _params_of(command: Any, argv: list[str]) -> list[inspect.Parameter]:
    """The Python parameters of the command ``argv`` names (for the flag in a message)."""
    for name in argv:
        sub = getattr(command, "commands", {}).get(name)
        if sub is None:
            break
        command = sub
    cb = getattr(command, "callback", None)
    target = getattr(cb, "__wrapped__", cb)
    return list(target.parameters) if isinstance(target, Command) else []


def _split_own(tail: list[str], own: dict[str, Any]) -> list[str]:
    """Take ``check``'s own output options out of the question's words."""
    out: list[str] = []
    i = 0
    while i < len(tail):
        a = tail[i]
        key, _, value = a.partition("=")
        if key in _OWN_VALUED and (value or i + 1 < len(tail)):
            if not value:
                i += 1
                value = tail[i]
            own[_OWN_VALUED[key]] = value
        elif a in _OWN_FLAGS:
            own[_OWN_FLAGS[a]] = True
        else:
            out.append(a)
        i += 1
    return out


@app.command(context_settings={"ignore_unknown_options": True, "allow_interspersed_args": False})
def check(
    args: Annotated[
        list[str],
        typer.Argument(
            help="The student's table (CSV, Markdown or JSON), then -- and the question as "
            "scanconv's own arguments. With --batch, only -- and the question.",
            metavar="ANSWER -- COMMAND...",
            show_default=False,
        ),
    ],
    batch: Annotated[
        str | None,
        typer.Option(
            "--batch",
            metavar="DIR",
            help="Mark every file in this folder; write a CSV of name, score, first error and "
            "diagnosis.",
        ),
    ] = None,
    fmt: FormatOpt = Format.auto,
    output: OutputOpt = None,
    brief: BriefOpt = False,
    exact: ExactOpt = False,
) -> None:
    """Mark a student's step table row by row against a question, with follow-through.

    Example: scanconv check alice.csv -- line 2 2 10 6 --algo bresenham
    """
    own: dict[str, Any] = {}
    words = [a for a in args if a != "--"]
    answer: Path | None = None
    if batch is None:
        if not words:
            fail("Missing argument 'ANSWER': give the student's file, then -- and the question")
        answer, words = Path(words[0]), words[1:]
    question = _split_own(words, own)
    try:
        fmt = Format(own.get("fmt", fmt.value))
    except ValueError:
        fail(f"--format: {own['fmt']!r} is not one of {', '.join(f.value for f in Format)}")
    output = Path(own["output"]) if "output" in own else output
    brief = own.get("brief", brief)
    exact = own.get("exact", exact)
    from ..answers.marking import mark, marking_solution
    from ..core.student_table import read_table

    try:
        solution = solve(question)
        text = " ".join(question)
        if batch is not None:
            _batch(Path(batch), solution, text, fmt, output)
            return
        assert answer is not None
        marking = mark(read_table(answer), solution)
        result = marking_solution(marking, solution, answer.name, text)
    except ValueError as err:
        fail(" ".join(str(err).split()))
    emit(result, Output(fmt=fmt, output=output, brief=brief, exact=exact))


def _batch(
    folder: Path, solution: Solution, question: str, fmt: Format, output: Path | None
) -> None:
    """Mark every file of ``folder`` and write one row each (exit 0 whatever the marks): CSV
    (the default, also on a terminal), JSON, or a table in the text formats."""
    from ..answers.marking import mark
    from ..core.student_table import read_table
    from ..render.budget import check_batch
    from ..render.marking import batch_csv, batch_json

    chosen = format_for_file(fmt, output)
    try:
        files = sorted(p for p in folder.iterdir() if not p.name.startswith(".") and p.is_file())
    except OSError as err:
        fail(f"--batch {folder}: cannot read the folder: {err.strerror or err}")
    if not files:
        fail(f"--batch {folder}: no files to mark")
    check_batch([p.stat().st_size for p in files], solution)  # before any file is read
    results = []
    for path in files:
        m = mark(read_table(path), solution)
        results.append((path.name, m.right, m.total, m.first_error, m.diagnosis))
    if chosen not in (Format.auto, Format.csv, Format.json):  # a table to read, not a sheet
        from ..answers.marking import batch_solution

        emit(batch_solution(results, solution, question), Output(fmt=chosen, output=output))
        return
    rows = batch_json(results, question) if chosen is Format.json else batch_csv(results)
    text = "".join(rows)
    if output is None:
        sys.stdout.write(text)
        sys.stdout.flush()
    else:
        write_atomic(output, lambda f: f.write(text))
