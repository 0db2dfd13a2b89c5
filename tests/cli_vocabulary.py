"""Every command of the CLI, enumerated from the typer app, with a vocabulary for each.

``tests/test_bad_input.py``, ``tests/test_fuzz.py`` and ``tests/test_files.py`` walk
:func:`commands`, so a new command is covered as soon as it is registered, and they fail until
it has an entry in :data:`VOCABULARY`: a quick valid invocation, which of its values are
numbers, and its own ways of being out of range, too short, too long or of the wrong type.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from enum import Enum
from pathlib import Path
from types import UnionType
from typing import Any, Union, get_args, get_origin, get_type_hints

import typer

from scanconv.cli import app

Argv = tuple[str, ...]


def _walk(command: Any, path: tuple[str, ...]) -> Iterator[tuple[tuple[str, ...], Any]]:
    subcommands = getattr(command, "commands", None)
    if subcommands:
        for name, sub in sorted(subcommands.items()):
            yield from _walk(sub, (*path, name))
        return
    yield path, command


_ANNOTATIONS: dict[int, tuple[Any, Any]] = {}
"""``id(param) -> (param, annotation)``, filled by :func:`commands` (the param is kept alive)."""


def _annotations(command: Any) -> None:
    """Record each parameter's Python annotation, read from the command's own function.

    Read from the signature rather than from typer's parameter objects, whose attributes
    differ between typer releases. ``X | None`` counts as ``X``.
    """
    function = getattr(command.callback, "__wrapped__", command.callback)
    hints = get_type_hints(function)
    for param in command.params:
        if param.name not in hints:
            continue
        hint = hints[param.name]
        if get_origin(hint) in (Union, UnionType):
            (hint,) = (a for a in get_args(hint) if a is not type(None))
        _ANNOTATIONS[id(param)] = (param, hint)


NOT_WALKED = {
    ("site", "build"): "writes a 16 MB folder (and fetches the Pyodide runtime the first time): "
    "tests/test_site_build.py holds its bad input, its failures and its output",
    ("mcp",): "runs a server until its client goes away: tests/test_mcp.py drives it as a "
    "client does, its bad flags and its message without the extra included",
}
"""Commands the walking tests (bad input, fuzz, files, html) leave out, and where they are tested."""


def commands() -> list[tuple[tuple[str, ...], Any]]:
    """``(path, click command)`` for every leaf command: ``("line",)``, ``("image", "ramp")``,
    but those of :data:`NOT_WALKED`."""
    found = [c for c in _walk(typer.main.get_command(app), ()) if c[0] not in NOT_WALKED]
    for _, command in found:
        _annotations(command)
    return found


def annotation(param: Any) -> Any:
    """The Python type a parameter of a command from :func:`commands` is declared with."""
    return _ANNOTATIONS[id(param)][1]


def choices(param: Any) -> tuple[str, ...]:
    """The values an option accepts, if it is a choice (an Enum), else ``()``."""
    ann = annotation(param)
    if isinstance(ann, type) and issubclass(ann, Enum):
        return tuple(m.value for m in ann)
    return ()


def options(command: Any) -> list[Any]:
    """The command's options (not its positional arguments), ``--help`` excluded."""
    return [p for p in command.params if getattr(p, "opts", None) and p.opts[0].startswith("-")]


def file_options(command: Any) -> list[str]:
    """The options that name a file to write: ``--output``, ``--svg``, ``--png``."""
    return [p.opts[0] for p in options(command) if annotation(p) is Path]


@dataclass(frozen=True)
class Vocab:
    """What a command accepts, for building good and bad argument vectors."""

    valid: tuple[Argv, ...]
    """Quick valid invocations (after the command path), each finishing in well under a second."""
    numbers: tuple[tuple[int, ...], ...]
    """For each valid invocation, the indexes of its values that are numbers (or formulas)."""
    out_of_range: tuple[tuple[Argv, str], ...]
    """Invocations just beyond a limit, with a word the message must contain."""
    too_few: tuple[Argv, str]
    too_many: tuple[Argv, str]
    wrong_type: tuple[Argv, str]
    """A value of the right kind but the wrong type (a fraction where an integer is needed)."""
    small: dict[str, tuple[str, ...]] = field(default_factory=dict)
    """Plausible values per option for the fuzz test, kept small so that a valid run is quick."""
    positional: tuple[str, ...] = ()
    """Plausible positional values for the fuzz test (repeated as the command needs)."""


COORD = ("0", "1", "2", "-3", "7", "10", "1/2", "2.5", "-0.25")
SMALL_INT = ("1", "2", "3", "4", "8")
POINTS = ("0", "0", "1", "2", "3", "3", "4", "0", "5", "2")
TOO_MANY_POINTS = tuple(str(i % 7) for i in range(202))  # 101 points, one beyond MAX_POINTS

VOCABULARY: dict[tuple[str, ...], Vocab] = {
    ("line",): Vocab(
        valid=(("2", "2", "10", "6"),),
        numbers=((0, 1, 2, 3),),
        out_of_range=((("0", "0", "1e10", "1"), "out of range"),),
        too_few=(("1", "2", "3"), "Missing argument"),
        too_many=(("1", "2", "3", "4", "5"), "unexpected extra argument"),
        wrong_type=(("2.5", "2", "3", "4", "--algo", "bresenham"), "integer end points"),
        small={"--algo": ("bresenham", "dda", "basic")},
        positional=COORD,
    ),
    ("storage",): Vocab(
        valid=(("1024", "768", "--levels", "256"), ("640", "480", "--bits", "8", "--frames", "2")),
        numbers=((0, 1, 3), (0, 1, 3, 5)),
        out_of_range=(
            (("8", "8", "--levels", "16777217"), "at most 24 bits"),
            (("8", "8", "--bits", "25"), "at most 24"),
            (("8", "8", "--bits", "8", "--frames", "1e10"), "out of range"),
            (("1e10", "8", "--bits", "8"), "out of range"),
        ),
        too_few=(("1024",), "Missing argument"),
        too_many=(("1", "2", "3", "--bits", "8"), "unexpected extra argument"),
        wrong_type=(("2.5", "8", "--bits", "8"), "must be an integer"),
        small={
            "--levels": ("2", "3", "256"),
            "--bits": SMALL_INT,
            "--frames": ("1", "30"),
            "--color": ("rgb24",),
        },
        positional=("1", "8", "640", "1024", "0"),
    ),
    ("quantize",): Vocab(
        valid=(("--bits", "3", "--range", "0", "255"),),
        numbers=((1, 3, 4),),
        out_of_range=((("--bits", "25"), "at most 24"),),
        too_few=(("--bits", "3", "--range", "0"), "requires 2 arguments"),
        too_many=(("--bits", "3", "7"), "unexpected extra argument"),
        wrong_type=(("--bits", "2.5"), "must be an integer"),
        small={"--bits": SMALL_INT, "--range": ("0", "1", "255", "-1")},
    ),
    ("sample",): Vocab(
        valid=(("x + y", "--size", "4x4", "--levels", "4"),),
        numbers=((0, 2, 4),),
        out_of_range=(
            (("x", "--size", "4097x4096", "--levels", "4"), "too large"),
            (("x", "--size", "4", "--levels", "16777217"), "at most 24 bits"),
        ),
        too_few=(("x + y", "--size", "4x4"), "Missing option"),
        too_many=(("x", "y", "--size", "4", "--levels", "4"), "unexpected extra argument"),
        wrong_type=(("x", "--size", "2.5x4", "--levels", "4"), "size must be"),
        small={
            "--size": ("1", "3x5", "8", "2x2"),
            "--levels": ("2", "4", "8"),
            "--domain": ("0", "1", "-1", "pi"),
            "--range": ("0", "1", "10"),
        },
        positional=("x + y", "sin(x)*cos(y)", "x*y/4", "log(x)", "1/x", "x**2"),
    ),
    ("image", "ramp"): Vocab(
        valid=(("--size", "4", "--levels", "4"),),
        numbers=((1, 3),),
        out_of_range=((("--size", "4097x4096"), "too large"),),
        too_few=(("--size",), "requires an argument"),
        too_many=(("--size", "4", "9"), "unexpected extra argument"),
        wrong_type=(("--levels", "2.5"), "must be an integer"),
        small={"--size": ("1", "3x5", "8"), "--levels": ("2", "4", "8")},
    ),
    ("compare", "line"): Vocab(
        valid=(("2", "8", "10", "4"),),
        numbers=((0, 1, 2, 3),),
        out_of_range=((("0", "0", "1e10", "1"), "out of range"),),
        too_few=(("1", "2", "3"), "Missing argument"),
        too_many=(("1", "2", "3", "4", "5"), "unexpected extra argument"),
        wrong_type=(("2", "8", "10", "4", "--explain=yes"), "does not take a value"),
        positional=COORD,
    ),
    ("compare", "circle"): Vocab(
        valid=(("5",),),
        numbers=((0,),),
        out_of_range=((("1e10",), "out of range"),),
        too_few=((), "Missing argument"),
        too_many=(("5", "6"), "unexpected extra argument"),
        wrong_type=(("2.5",), "integer"),
        positional=("0", "1", "4", "10", "2.5"),
    ),
    ("circle",): Vocab(
        valid=(("5", "--center", "1", "2"),),
        numbers=((0, 2, 3),),
        out_of_range=((("1e10",), "out of range"),),
        too_few=(("5", "--center", "1"), "requires 2 arguments"),
        too_many=(("5", "6"), "unexpected extra argument"),
        wrong_type=(("2.5",), "integer"),
        small={
            "--center": ("0", "1", "-2"),
            "--method": ("midpoint", "bresenham", "polynomial", "general", "trig"),
            "--rounding": ("half-up", "trunc"),
        },
        positional=("0", "1", "5", "10", "2.5"),
    ),
    ("ellipse",): Vocab(
        valid=(("5", "3"),),
        numbers=((0, 1),),
        out_of_range=((("1e10", "3"), "out of range"),),
        too_few=(("5",), "Missing argument"),
        too_many=(("5", "3", "1"), "unexpected extra argument"),
        wrong_type=(("2.5", "3"), "integer"),
        small={"--center": ("0", "1", "-2")},
        positional=("0", "1", "3", "8", "2.5"),
    ),
    ("parametric", "circle"): Vocab(
        valid=(
            (
                *("--radius", "5", "--samples", "8", "--center", "0", "0"),
                *("--t-range", "0", "1"),
            ),
        ),
        numbers=((1, 3, 5, 6, 8, 9),),
        out_of_range=(
            (("--radius", "1e10"), "out of range"),
            (("--samples", "100001"), "at most 100000"),
            (("--radius", "1000000000", "--samples", "4"), "1,000,000"),
        ),
        too_few=(("--center", "1"), "requires 2 arguments"),
        too_many=(("--radius", "5", "7"), "unexpected extra argument"),
        wrong_type=(("--samples", "2.5"), "not an integer"),
        small={
            "--radius": ("1", "5", "1/2"),
            "--samples": SMALL_INT,
            "--center": ("0", "1", "-2"),
            "--t-range": ("0", "1", "pi", "2*pi", "-1"),
        },
    ),
    ("parametric", "ellipse"): Vocab(
        valid=(("--a", "4", "--b", "2", "--samples", "8"),),
        numbers=((1, 3, 5),),
        out_of_range=((("--a", "1e10"), "out of range"),),
        too_few=(("--center", "1"), "requires 2 arguments"),
        too_many=(("--a", "4", "7"), "unexpected extra argument"),
        wrong_type=(("--samples", "2.5"), "not an integer"),
        small={
            "--a": ("1", "4"),
            "--b": ("1", "2"),
            "--samples": SMALL_INT,
            "--center": ("0", "1"),
            "--t-range": ("0", "pi"),
        },
    ),
    ("parametric", "parabola"): Vocab(
        valid=(("--vertex", "0", "0", "--a", "1", "--samples", "8"),),
        numbers=((1, 2, 4, 6),),
        out_of_range=((("--a", "1e10"), "out of range"),),
        too_few=(("--vertex", "1"), "requires 2 arguments"),
        too_many=(("--a", "1", "7"), "unexpected extra argument"),
        wrong_type=(("--samples", "2.5"), "not an integer"),
        small={
            "--vertex": ("0", "1", "-2"),
            "--a": ("1", "-1", "1/2"),
            "--samples": SMALL_INT,
            "--t-range": ("-3", "3", "0", "1"),
        },
    ),
    ("parametric", "line"): Vocab(
        valid=(("0", "0", "4", "2", "--samples", "4"),),
        numbers=((0, 1, 2, 3, 5),),
        out_of_range=(
            (("0", "0", "1e10", "1"), "out of range"),
            (("0", "0", "1000000000", "1", "--samples", "2"), "1,000,000"),
        ),
        too_few=(("0", "0", "4"), "Missing argument"),
        too_many=(("0", "0", "4", "2", "9"), "unexpected extra argument"),
        wrong_type=(("0", "0", "4", "2", "--samples", "2.5"), "not an integer"),
        small={"--samples": SMALL_INT, "--t-range": ("0", "1", "1/2")},
        positional=COORD,
    ),
    ("parametric", "custom"): Vocab(
        valid=(("--x", "t", "--y", "t*t", "--samples", "4"),),
        numbers=((1, 3, 5),),
        out_of_range=(
            (("--x", "9**9**9", "--y", "t"), "exponent"),
            (("--x", "t", "--y", "t", "--samples", "100001"), "at most 100000"),
            (("--x", "1e10 + t", "--y", "t"), "out of range"),
        ),
        too_few=(("--x", "t"), "Missing option"),
        too_many=(("--x", "t", "--y", "t", "t"), "unexpected extra argument"),
        wrong_type=(("--x", "'t'", "--y", "t"), "strings are not allowed"),
        small={
            "--x": ("t", "3*cos(t)", "t**2", "sqrt(t)", "1/t"),
            "--y": ("t", "2*sin(t)", "-t", "log(t)"),
            "--samples": SMALL_INT,
            "--t-range": ("0", "1", "2*pi", "-1"),
        },
    ),
    ("bezier",): Vocab(
        valid=((*POINTS[:8], "--samples", "4"), (*POINTS[:8], "--at", "1/2")),
        numbers=((0, 1, 2, 3, 4, 5, 6, 7, 9), (0, 1, 2, 3, 4, 5, 6, 7, 9)),
        out_of_range=(
            (("0", "0", "1e10", "1"), "out of range"),
            (("0", "0", "1", "1", "--samples", "100001"), "at most 100000"),
            (("0", "0", "1", "1", "--at", "1.5"), "[0, 1]"),
            (("0", "0", "1000000000", "1"), "1,000,000"),
            (("0", "0", "1", "1", "--samples", "50000"), "at most 100,000"),
        ),
        too_few=(("0", "0"), "at least 2 control points"),
        too_many=(TOO_MANY_POINTS, "at most 100 control points"),
        wrong_type=(("0", "0", "1", "1", "--samples", "2.5"), "not an integer"),
        small={"--samples": SMALL_INT, "--at": ("0", "1/2", "1", "0.25")},
        positional=COORD,
    ),
    ("bspline",): Vocab(
        valid=(
            (*POINTS, "--degree", "2", "--samples", "4"),
            (*POINTS[:6], "--degree", "2", "--at", "1/2"),
        ),
        numbers=((0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 13), (0, 1, 2, 3, 4, 5, 7, 9)),
        out_of_range=(
            (("0", "0", "1e10", "1"), "out of range"),
            ((*POINTS, "--degree", "5"), "1 <= p <= n"),
            ((*TOO_MANY_POINTS[:24], "--degree", "11"), "at most 10"),
            (("0", "0", "1", "1", "--degree", "1", "--samples", "50000"), "at most 100,000"),
        ),
        too_few=(("0", "0"), "at least 2 control points"),
        too_many=(TOO_MANY_POINTS, "at most 100 control points"),
        wrong_type=((*POINTS, "--degree", "1.5"), "not an integer"),
        small={
            "--degree": ("1", "2", "3"),
            "--knots": ("open", "uniform", "0,0,0,1,2,3,3,3", "0,1"),
            "--samples": SMALL_INT,
            "--at": ("0", "1", "1/2", "3"),
        },
        positional=COORD,
    ),
    ("continuity",): Vocab(
        valid=(
            ("0", "0", "1", "1", "2", "0", ":", "2", "0", "3", "-1", "4", "0", "--samples", "4"),
        ),
        numbers=((0, 1, 2, 3, 4, 5, 7, 8, 9, 10, 11, 12, 14),),
        out_of_range=(
            (("0", "0", "1e10", "1", ":", "1", "1", "2", "2"), "out of range"),
            (
                ("0", "0", "1", "1", ":", "1", "1", "2", "2", "--samples", "50000"),
                "at most 100,000",
            ),
        ),
        too_few=(("0", "0", "1", "1", ":", "1", "1"), "at least 2 control points"),
        too_many=(("0", "0", "1", "1", ":", "1", "1", "2", "2", ":", "3", "3"), "separated by ':'"),
        wrong_type=(("0", "0", "1", "1", ":", "1", "1", "2", "2", "-n", "0.5"), "not an integer"),
        small={"--samples": SMALL_INT},
        positional=(*COORD, ":"),
    ),
    ("local-control",): Vocab(
        valid=((*POINTS, "--move", "2", "3", "4", "--degree", "2", "--samples", "4"),),
        numbers=((0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 12, 13, 15, 17),),
        out_of_range=(
            ((*POINTS, "--move", "9", "1", "1"), "index"),
            ((*POINTS, "--move", "1", "1e10", "1"), "out of range"),
        ),
        too_few=((*POINTS, "--move", "1", "2"), "requires 3 arguments"),
        too_many=((*TOO_MANY_POINTS, "--move", "1", "1", "1"), "at most 100 control points"),
        wrong_type=((*POINTS, "--move", "1.5", "1", "1"), "must be an integer"),
        small={
            "--move": ("0", "1", "2", "3", "-1"),
            "--degree": ("1", "2", "3"),
            "--samples": SMALL_INT,
            "--knots": ("open", "uniform"),
        },
        positional=COORD,
    ),
}


# For tests/cli_vocabulary.py, appended inside VOCABULARY: transform, viewport, clip, pipeline.
WINDOW = ("--window", "0", "0", "4", "4")
VIEWPORT = ("--viewport", "0", "0", "8", "8")
RECT_VALUES = ("0", "1", "2", "4", "10", "-2", "1/2")

PROCESS_VOCABULARY = {
    ("transform",): Vocab(
        valid=(
            (
                "0",
                "0",
                "4",
                "0",
                "4",
                "3",
                "--rotate",
                "90",
                "--about",
                "2",
                "1",
                "--translate",
                "3",
                "0",
            ),
        ),
        numbers=((0, 1, 2, 3, 4, 5, 7, 9, 10, 12, 13),),
        out_of_range=(
            (("0", "0", "--translate", "1e10", "1"), "out of range"),
            (("0", "0", *["--translate", "1", "1"] * 21), "at most 20 transformations"),
        ),
        too_few=(("0", "0", "--translate", "1"), "needs 2 numbers"),
        too_many=((*TOO_MANY_POINTS, "--translate", "1", "1"), "at most 100 points"),
        wrong_type=(("0", "0", "--rotate", "north"), "not an angle"),
        positional=(
            "0",
            "1",
            "-3",
            "1/2",
            "--rotate",
            "90",
            "pi/4",
            "--about",
            "--translate",
            "--scale",
            "2",
            "--reflect",
            "y=x",
            "--shear",
        ),
    ),
    ("viewport",): Vocab(
        valid=(
            (
                "0",
                "0",
                "2",
                "1",
                "--window",
                "0",
                "0",
                "4",
                "4",
                "--viewport",
                "10",
                "10",
                "20",
                "16",
            ),
        ),
        numbers=((0, 1, 2, 3, 5, 6, 7, 8, 10, 11, 12, 13),),
        out_of_range=(
            (("--window", "0", "0", "1e10", "1", *VIEWPORT), "out of range"),
            ((*WINDOW, "--viewport", "5", "5", "5", "9"), "xmin < xmax"),
        ),
        too_few=((*VIEWPORT, "--window", "0", "0", "4"), "requires 4 arguments"),
        too_many=((*TOO_MANY_POINTS, *WINDOW, *VIEWPORT), "at most 100 points"),
        wrong_type=(("0", "0", "1", *WINDOW, *VIEWPORT), "odd"),
        small={"--window": RECT_VALUES, "--viewport": RECT_VALUES},
        positional=COORD,
    ),
    ("clip", "line"): Vocab(
        valid=(("7", "9", "11", "4", "--window", "4", "4", "10", "8"),),
        numbers=((0, 1, 2, 3, 5, 6, 7, 8),),
        out_of_range=(
            (("0", "0", "1e10", "1", *WINDOW), "out of range"),
            (("0", "0", "1", "1", "--window", "4", "4", "4", "8"), "xmin < xmax"),
        ),
        too_few=(("1", "2", "3", *WINDOW), "Missing argument"),
        too_many=(("1", "2", "3", "4", "5", *WINDOW), "unexpected extra argument"),
        wrong_type=(("1", "2", "3", "4", "--window", "0", "0", "4"), "requires 4 arguments"),
        small={
            "--window": RECT_VALUES,
            "--method": ("cohen-sutherland", "liang-barsky", "nicholl-lee-nicholl"),
        },
        positional=COORD,
    ),
    ("clip", "polygon"): Vocab(
        valid=(("100", "150", "200", "250", "300", "200", "--window", "150", "150", "200", "200"),),
        numbers=((0, 1, 2, 3, 4, 5, 7, 8, 9, 10),),
        out_of_range=((("0", "0", "1e10", "1", "2", "2", *WINDOW), "out of range"),),
        too_few=(("0", "0", "1", "1", *WINDOW), "at least 3"),
        too_many=((*TOO_MANY_POINTS, *WINDOW), "at most 100 polygon vertices"),
        wrong_type=(("0", "0", "1", "1", "2", *WINDOW), "odd"),
        small={"--window": RECT_VALUES, "--method": ("sutherland-hodgman",)},
        positional=COORD,
    ),
    ("pipeline", "line"): Vocab(
        valid=(
            (
                "-5",
                "0",
                "15",
                "10",
                "--window",
                "0",
                "0",
                "10",
                "10",
                "--viewport",
                "0",
                "0",
                "20",
                "10",
            ),
        ),
        numbers=((0, 1, 2, 3, 5, 6, 7, 8, 10, 11, 12, 13),),
        out_of_range=(
            (("0", "0", "1e10", "1", *WINDOW, *VIEWPORT), "out of range"),
            (("0", "0", "1", "1", *WINDOW, "--viewport", "0", "0", "9", "0"), "ymin < ymax"),
        ),
        too_few=(("1", "2", "3", *WINDOW, *VIEWPORT), "Missing argument"),
        too_many=(("1", "2", "3", "4", "5", *WINDOW, *VIEWPORT), "unexpected extra argument"),
        wrong_type=(
            ("1", "2", "3", "4", *WINDOW, "--viewport", "0", "0", "8"),
            "requires 4 arguments",
        ),
        small={
            "--window": RECT_VALUES,
            "--viewport": RECT_VALUES,
            "--algo": ("bresenham", "dda", "basic"),
            "--clip": ("cohen-sutherland", "liang-barsky", "nicholl-lee-nicholl"),
        },
        positional=COORD,
    ),
    ("pipeline", "polygon"): Vocab(
        valid=(("-2", "0", "6", "0", "2", "6", *WINDOW, *VIEWPORT, "--fill"),),
        numbers=((0, 1, 2, 3, 4, 5, 7, 8, 9, 10, 12, 13, 14, 15),),
        out_of_range=(
            (("0", "0", "1e10", "1", "2", "2", *WINDOW, *VIEWPORT), "out of range"),
            (
                (
                    "0",
                    "0",
                    "4",
                    "0",
                    "2",
                    "4",
                    *WINDOW,
                    "--viewport",
                    "0",
                    "0",
                    "1e9",
                    "1e9",
                    "--fill",
                ),
                "1,000,000",
            ),
            (
                ("0", "0", "4", "0", "2", "4", *WINDOW, "--viewport", "0", "0", "1e9", "1e9"),
                "1,000,000",
            ),
        ),
        too_few=(("0", "0", "1", "1", *WINDOW, *VIEWPORT), "at least 3"),
        too_many=((*TOO_MANY_POINTS, *WINDOW, *VIEWPORT), "at most 100 polygon vertices"),
        wrong_type=(("0", "0", "1", "1", "2", *WINDOW, *VIEWPORT), "odd"),
        small={
            "--window": RECT_VALUES,
            "--viewport": RECT_VALUES,
            "--rule": ("even-odd", "nonzero"),
        },
        positional=COORD,
    ),
}
VOCABULARY.update(PROCESS_VOCABULARY)

# Polygon filling, seed fill and anti-aliasing.

TRIANGLE = ("0", "0", "7", "2", "4", "6")
DIAMOND = ("2", "0", "4", "2", "2", "4", "0", "2")
TOO_MANY_VERTICES = tuple(str(i % 7) for i in range(2002))  # 1001 vertices
FILL_VOCABULARY = {
    ("polygon",): Vocab(
        valid=(TRIANGLE, (*TRIANGLE, "--rule", "nonzero")),
        numbers=((0, 1, 2, 3, 4, 5), (0, 1, 2, 3, 4, 5)),
        out_of_range=(
            (("0", "0", "1e10", "1", "2", "3"), "out of range"),
            (("0", "0", "1000", "0", "0", "1000"), "1,000,000"),
            (("0", "0", "2", "2", "5", "5"), "degenerate"),
        ),
        too_few=(("0", "0", "4", "0"), "at least 3 vertices"),
        too_many=(TOO_MANY_VERTICES, "at most 1000 polygon vertices"),
        wrong_type=(("0", "0", "4", "0", "2"), "odd number"),
        small={"--rule": ("even-odd", "nonzero")},
        positional=("0", "1", "2", "5", "-3", "1/2", "2.5"),
    ),
    ("fill", "boundary"): Vocab(
        valid=((*DIAMOND, "--seed", "2", "2"), ("--rows", "####/#..#/####", "--seed", "1", "1")),
        numbers=((0, 1, 2, 3, 4, 5, 6, 7, 9, 10), (3, 4)),
        out_of_range=(
            (("--rows", "####/#..#/####", "--seed", "9", "9"), "outside the grid"),
            (("--rows", "####/#..#/####", "--seed", "0", "0"), "on the boundary"),
            (("--rows", "/".join(["." * 101] * 100), "--seed", "1", "1"), "10,000"),
            ((*DIAMOND, "--seed", "2", "2", "--connectivity", "6"), "4 or 8"),
        ),
        too_few=(("--rows", "####/#..#/####", "--seed", "1"), "requires 2 arguments"),
        too_many=(("0", "0", "4", "0", "--seed", "1", "1"), "at least 3 vertices"),
        wrong_type=(("--rows", "####/#..#/####", "--seed", "1.5", "1"), "not an integer"),
        small={
            "--seed": ("0", "1", "2", "3"),
            "--connectivity": ("4", "8"),
            "--order": ("stack", "queue"),
        },
        positional=("0", "1", "2", "4", "5"),
    ),
    ("antialias", "line"): Vocab(
        valid=(("0", "0", "8", "3"), ("0", "0", "8", "3", "--method", "wu", "--levels", "4")),
        numbers=((0, 1, 2, 3), (0, 1, 2, 3, 7)),
        out_of_range=(
            (("0", "0", "1e10", "1"), "out of range"),
            (("0", "0", "200", "60"), "10,000"),
            (("0", "0", "8", "3", "--method", "supersample", "--samples", "17"), "at most 16"),
            (("0", "0", "8", "3", "--levels", "1"), "at least 2"),
        ),
        too_few=(("1", "2", "3"), "Missing argument"),
        too_many=(("1", "2", "3", "4", "5"), "unexpected extra argument"),
        wrong_type=(("0", "0", "8", "3", "--samples", "2.5"), "integer"),
        small={
            "--method": ("area", "supersample", "wu", "subpixel"),
            "--samples": SMALL_INT,
            "--levels": ("2", "4", "8"),
            "--ends": ("full", "coverage"),
            "--subgrid": ("span", "centre"),
            "--divide": ("n", "n2"),
            "--width": ("1", "2", "1/2"),
            "--across": ("minor", "perpendicular"),
        },
        positional=COORD,
    ),
    ("antialias", "circle"): Vocab(
        valid=(("3",), ("3", "--center", "1", "1", "--method", "supersample", "--samples", "2")),
        numbers=((0,), (0, 2, 3, 7)),
        out_of_range=(
            (("1e10",), "out of range"),
            (("49",), "10,000"),
            (("3", "--method", "wu"), "lines only"),
        ),
        too_few=((), "Missing argument"),
        too_many=(("3", "4"), "unexpected extra argument"),
        wrong_type=(("2.5",), "integer"),
        small={
            "--method": ("area", "supersample"),
            "--samples": SMALL_INT,
            "--levels": ("2", "4", "8"),
        },
        positional=("0", "1", "2", "3", "5"),
    ),
    ("antialias", "polygon"): Vocab(
        valid=(TRIANGLE, (*TRIANGLE, "--method", "supersample", "--samples", "3")),
        numbers=((0, 1, 2, 3, 4, 5), (0, 1, 2, 3, 4, 5, 9)),
        out_of_range=(
            (("0", "0", "1e10", "1", "2", "3"), "out of range"),
            (("0", "0", "100", "0", "0", "99"), "10,000"),
            ((*TRIANGLE, "--method", "supersample", "--samples", "17"), "at most 16"),
        ),
        too_few=(("0", "0", "4", "0"), "at least 3 vertices"),
        too_many=(TOO_MANY_VERTICES, "at most 1000 polygon vertices"),
        wrong_type=((*TRIANGLE, "--samples", "2.5"), "not an integer"),
        small={
            "--method": ("area", "supersample"),
            "--samples": SMALL_INT,
            "--rule": ("even-odd", "nonzero"),
        },
        positional=("0", "1", "2", "5", "-3", "1/2", "2.5"),
    ),
}
FILL_VOCABULARY[("fill", "flood")] = FILL_VOCABULARY[("fill", "boundary")]
VOCABULARY.update(FILL_VOCABULARY)

#: Commands that take no value at all: nothing to make out of range or of the wrong type.
ARGUMENTLESS = {("compare", "curves")}
VOCABULARY[("compare", "curves")] = Vocab(
    valid=((),),
    numbers=((),),
    out_of_range=(),
    too_few=(("bezier",), "unexpected extra argument"),
    too_many=(("1", "2"), "unexpected extra argument"),
    wrong_type=(("--format", "docx"), "docx"),
)
VOCABULARY[("color",)] = Vocab(
    valid=(("rgb", "51", "102", "153"), ("hsv", "210", "2/3", "0.6", "--to", "rgb", "cmy")),
    numbers=((1, 2, 3), (1, 2, 3)),
    out_of_range=(
        (("rgb", "51", "102", "256"), "out of range"),
        (("hsv", "360", "1", "1"), "out of range"),
        (("rgb", "1", "2", "3", "--bits", "17"), "1..16"),
    ),
    too_few=(("rgb", "1", "2"), "takes 3 values"),
    too_many=(("rgb", "1", "2", "3", "4"), "takes 3 values"),
    wrong_type=(("rgb", "1.5", "2", "3"), "must be an integer"),
    small={"--to": ("cmy", "hsv", "hsi", "grey", "rgb"), "--bits": ("1", "4", "8")},
    positional=("rgb", "hsv", "0", "1", "1/2", "255", "120"),
)

# Teacher tools: sheet takes a question file (golden/teach/*.questions), practice
# numbers only.
TEACH = Path(__file__).resolve().parent.parent / "golden" / "teach"
QUESTIONS = str(TEACH / "short.questions")
VOCABULARY[("sheet",)] = Vocab(
    valid=((QUESTIONS,), (QUESTIONS, "--worksheet", "--format", "latex")),
    numbers=((0,), (0,)),
    out_of_range=(((str(TEACH / "out-of-range.questions"),), "out of range"),),
    too_few=((), "Missing argument"),
    too_many=((QUESTIONS, QUESTIONS), "unexpected extra argument"),
    wrong_type=((str(TEACH),), "is a directory"),
    small={"--format": ("markdown", "latex", "html", "json", "plain", "moodle", "gift")},
    positional=(QUESTIONS, "-", "missing.questions"),
)
VOCABULARY[("practice",)] = Vocab(
    valid=(("--count", "2", "--seed", "1"), ("--topic", "line", "-n", "3", "--seed", "5")),
    numbers=((1, 3), (3, 5)),
    out_of_range=((("--count", "201", "--seed", "1"), "1 to 200"), (("--seed", "-1"), "--seed")),
    too_few=(("--count",), "requires an argument"),
    too_many=(("--seed", "1", "2"), "unexpected extra argument"),
    wrong_type=(("--count", "2.5", "--seed", "1"), "not an integer"),
    small={
        "--count": ("1", "2", "3"),
        "--seed": ("0", "1", "7"),
        "--topic": ("line", "circle", "storage"),
        "--difficulty": ("easy", "exam", "hard"),
    },
)
ARGUMENTLESS.add(("theory",))  # a topic name, no number
VOCABULARY[("theory",)] = Vocab(
    valid=(("raster-display",), ("symmetry",)),
    numbers=((), ()),
    out_of_range=((("nope",), "unknown theory topic"),),
    too_few=(("--format", "plain"), "Missing argument"),
    too_many=(("symmetry", "dda"), "unexpected extra argument"),
    wrong_type=(("3",), "unknown theory topic"),
    positional=("raster-display", "dda", "symmetry", "nope", "3"),
)

# check: a student's table, then -- and the question; the numbers are the question's.
CHECK_DATA = Path(__file__).resolve().parent / "data" / "check"
STUDENT = str(CHECK_DATA / "slip.csv")
VOCABULARY[("check",)] = Vocab(
    valid=(
        (STUDENT, "--", "line", "2", "2", "10", "6"),
        (str(CHECK_DATA / "old-x.md"), "--", "circle", "10", "--center", "1", "2"),
    ),
    numbers=((3, 4, 5, 6), (3, 5, 6)),
    out_of_range=(
        ((STUDENT, "--", "line", "0", "0", "1e10", "1"), "out of range"),
        ((str(CHECK_DATA / "too-many-rows.csv"), "--", "line", "2", "2", "10", "6"), "rows"),
    ),
    too_few=((), "Missing argument"),
    too_many=((STUDENT, "--", "line", "1", "2", "3", "4", "5"), "unexpected extra argument"),
    wrong_type=((STUDENT, "--", "line", "2.5", "2", "3", "4"), "integer end points"),
    small={"--format": ("markdown", "plain", "json", "csv")},
    positional=(STUDENT, "--", "line", "circle", "0", "2", "10", "-3"),
)
ARGUMENTLESS.add(("exam",))  # a section name, no number
VOCABULARY[("exam",)] = Vocab(
    valid=(("--contents",), ("--section", "2", "--format", "plain")),
    numbers=((), ()),
    out_of_range=((("--section", "9"), "is not a section"),),
    too_few=(("--section",), "requires an argument"),
    too_many=(("extra",), "unexpected extra argument"),
    wrong_type=(("--section", "nope"), "is not a section"),
    small={"--section": ("1", "dda", "14", "circle", "3d")},
)

# The commands beyond lines and curves: dithering, halftones, the inside-outside test, the
# frame buffer, line attributes, characters, and clipping against a convex window.
IMAGE = ("--image", "10 200; 60 90")
BIG_IMAGE = "; ".join([" ".join(["0"] * 64)] * 65)  # 4160 cells, beyond MAX_CELLS
IMAGE_VALUES = ("0 255", "10 200; 60 90", "1/2 1; 0 1", "100, 100 / 100, 100")
TRIANGLE_WINDOW = ("--window-vertices", "0", "0", "8", "0", "0", "8")
for _name, _extra in (
    ("threshold", ("--at", "128")),
    ("floyd-steinberg", ("--order", "serpentine")),
):
    VOCABULARY[("dither", _name)] = Vocab(
        valid=((*IMAGE, "--top", "255", *_extra),),
        numbers=((3, 5) if _name == "threshold" else (3,),),
        out_of_range=(
            (("--image", BIG_IMAGE), "4,096"),
            ((*IMAGE, "--top", "1e10"), "out of range"),
        ),
        too_few=(("--image",), "requires an argument"),
        too_many=((*IMAGE, "5"), "unexpected extra argument"),
        wrong_type=(("--image", "1 2; 3"), "every row"),
        small={"--image": IMAGE_VALUES, "--top": ("1", "255"), "--at": ("0", "1", "128")},
    )
VOCABULARY[("dither", "ordered")] = Vocab(
    valid=((*IMAGE, "--top", "255", "--matrix", "4"), (*IMAGE, "--matrix", "0 2; 3 1")),
    numbers=((3, 5), (1,)),
    out_of_range=(
        ((*IMAGE, "--matrix", "3"), "2, 4, 8 or 16"),
        (("--image", BIG_IMAGE), "4,096"),
    ),
    too_few=(("--image",), "requires an argument"),
    too_many=((*IMAGE, "5"), "unexpected extra argument"),
    wrong_type=((*IMAGE, "--matrix", "2.5"), "must be an integer"),
    small={"--image": IMAGE_VALUES, "--top": ("1", "255"), "--matrix": ("2", "4", "0 1; 1 0")},
)
VOCABULARY[("dither", "lookup")] = Vocab(
    valid=(("5", "2", "--matrix", "4", "--value", "100"), ("1", "1", "--count", "1")),
    numbers=((0, 1, 3, 5), (0, 1)),
    out_of_range=(
        (("5", "2", "--matrix", "3"), "2, 4, 8 or 16"),
        (("1", "1", *["1"] * 128), "1 .. 64 pixels"),
    ),
    too_few=((), "Missing argument"),
    too_many=(("5", "2", "--matrix"), "requires an argument"),
    wrong_type=(("5", "2", "3"), "pairs"),
    small={"--matrix": ("2", "4"), "--value": ("0", "100", "255"), "--top": ("1", "255")},
    positional=("0", "1", "2", "5"),
)
VOCABULARY[("halftone",)] = Vocab(
    valid=(("2",), ("4", "--level", "5", "--bits", "1")),
    numbers=((0,), (0, 2, 4)),
    out_of_range=((("32",), "1 .. 16"), (("2", "--level", "9"), "levels 0 .. 4")),
    too_few=((), "Missing argument"),
    too_many=(("2", "3"), "unexpected extra argument"),
    wrong_type=(("2.5",), "must be an integer"),
    small={"--level": ("0", "1", "3"), "--bits": ("1", "2")},
    positional=("2", "4", "3", "0"),
)
VOCABULARY[("printer",)] = Vocab(
    valid=(("--dpi", "300", "--lpi", "60"), ("--lpi", "150", "--cell", "16", "--count", "n2")),
    numbers=((1, 3), (1, 3)),
    out_of_range=(
        (("--dpi", "300", "--cell", "5000"), "1 .. 4096"),
        (("--dpi", "1e7", "--lpi", "60"), "1,000,000"),
    ),
    too_few=(("--dpi", "300"), "give two of"),
    too_many=(("--dpi", "300", "--lpi", "60", "--cell", "5"), "give two of"),
    wrong_type=(("--dpi", "300", "--cell", "2.5"), "must be an integer"),
    small={"--dpi": ("300", "600"), "--lpi": ("60", "100"), "--cell": ("2", "5")},
)
VOCABULARY[("inside",)] = Vocab(
    valid=(("0", "0", "6", "0", "6", "6", "3", "2", "0", "6", "--points", "3", "1", "3", "4"),),
    numbers=((0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 12, 13, 14),),
    out_of_range=(
        (("0", "0", "6", "0", "6", "6", "--points", "1e10", "1"), "out of range"),
        (("0", "0", "6", "0", "6", "6", "--points", *["1"] * 202), "at most 100 points"),
    ),
    too_few=(("0", "0", "6", "0", "6", "6"), "Missing option '--points'"),
    too_many=((*TOO_MANY_VERTICES, "--points", "1", "1"), "at most 1000 polygon vertices"),
    wrong_type=(("0", "0", "6", "0", "6", "--points", "1", "1"), "odd"),
    positional=("0", "1", "2", "6", "-3", "1/2", "--points"),
)
VOCABULARY[("framebuffer",)] = Vocab(
    valid=(("640", "480", "8"), ("1280", "1024", "8", "--lut", "24", "--rate", "1e6")),
    numbers=((0, 1, 2), (0, 1, 2, 4, 6)),
    out_of_range=(
        (("640", "480", "65"), "at most 64"),
        (("640", "480", "8", "--rate", "0"), "positive"),
    ),
    too_few=(("640", "480"), "Missing argument"),
    too_many=(("640", "480", "8", "1"), "unexpected extra argument"),
    wrong_type=(("640.5", "480", "8"), "must be an integer"),
    small={"--lut": ("8", "24"), "--rate": ("1", "1e6"), "--refresh": ("30", "60")},
    positional=("1", "8", "640", "480", "0"),
)
VOCABULARY[("linestyle",)] = Vocab(
    valid=(
        ("0", "0", "12", "4", "--mask", "1110"),
        ("0", "0", "7", "2", "--mask", "110", "--repeat", "2"),
    ),
    numbers=((0, 1, 2, 3), (0, 1, 2, 3, 7)),
    out_of_range=(
        (("0", "0", "12", "4", "--mask", "1" * 65), "at most 64 bits"),
        (("0", "0", "1e10", "4", "--mask", "1"), "out of range"),
    ),
    too_few=(("0", "0", "12", "4"), "Missing option"),
    too_many=(("0", "0", "12", "4", "5", "--mask", "1"), "unexpected extra argument"),
    wrong_type=(("0", "0", "12", "4", "--mask", "11", "--repeat", "1.5"), "must be an integer"),
    small={"--mask": ("1", "10", "1110", "0x0f"), "--repeat": ("1", "2")},
    positional=("0", "1", "2", "5", "-3"),
)
VOCABULARY[("thickline",)] = Vocab(
    valid=(("0", "0", "8", "3", "--width", "3"), ("0", "0", "3", "8", "--width", "2", "--brush")),
    numbers=((0, 1, 2, 3, 5), (0, 1, 2, 3, 5)),
    out_of_range=(
        (("0", "0", "8", "3", "--width", "26"), "1..25"),
        (("0", "0", "1e10", "3", "--width", "3"), "out of range"),
    ),
    too_few=(("0", "0", "8", "3"), "Missing option"),
    too_many=(("0", "0", "8", "3", "5", "--width", "3"), "unexpected extra argument"),
    wrong_type=(("0", "0", "8", "3", "--width", "2.5"), "must be an integer"),
    small={"--width": ("1", "2", "3")},
    positional=("0", "1", "2", "5", "-3"),
)
VOCABULARY[("char", "bitmap")] = Vocab(
    valid=(("A", "--at", "2", "1"), ("X", "--rows", "101/010/101", "--scale", "2")),
    numbers=((2, 3), (4,)),
    out_of_range=((("A", "--scale", "17"), "1..16"), (("A", "--rows", "1" * 65), "at most 64")),
    too_few=((), "Missing argument"),
    too_many=(("A", "B"), "unexpected extra argument"),
    wrong_type=(("A", "--scale", "1.5"), "must be an integer"),
    small={"--scale": ("1", "2"), "--at": ("0", "1", "-2"), "--rows": ("1", "10/01", "#./.#")},
    positional=("A", "L", "7", "?", "AB"),
)
VOCABULARY[("char", "stroke")] = Vocab(
    valid=(("T", "--scale", "2"), ("A", "--at", "1", "1", "--algo", "dda")),
    numbers=((2,), (2, 3)),
    out_of_range=((("T", "--scale", "17"), "1..16"), (("T", "--at", "1e10", "0"), "out of range")),
    too_few=((), "Missing argument"),
    too_many=(("T", "L"), "unexpected extra argument"),
    wrong_type=(("T", "--scale", "1.5"), "must be an integer"),
    small={"--scale": ("1", "2"), "--at": ("0", "1", "-2")},
    positional=("T", "L", "7", "?"),
)
VOCABULARY[("char", "storage")] = Vocab(
    valid=(("128", "5", "7"), ("256", "7", "9", "--packing", "columns")),
    numbers=((0, 1, 2), (0, 1, 2)),
    out_of_range=((("2097152", "5", "7"), "at most 2^20"),),
    too_few=(("128", "5"), "Missing argument"),
    too_many=(("128", "5", "7", "1"), "unexpected extra argument"),
    wrong_type=(("128", "5.5", "7"), "must be an integer"),
    positional=("1", "5", "7", "128", "0"),
)
VOCABULARY[("clip", "convex")] = Vocab(
    valid=(
        ("-1", "2", "9", "2", *TRIANGLE_WINDOW),
        ("-1", "2", "9", "2", *TRIANGLE_WINDOW, "--normals", "inward"),
    ),
    numbers=((0, 1, 2, 3, 5, 6, 7, 8, 9, 10), (0, 1, 2, 3, 5, 6, 7, 8, 9, 10)),
    out_of_range=((("0", "0", "1e10", "1", *TRIANGLE_WINDOW), "out of range"),),
    too_few=(("0", "0", "1", *TRIANGLE_WINDOW), "X1 Y1 X2 Y2"),
    too_many=(("0", "0", "1", "1", "1", *TRIANGLE_WINDOW), "X1 Y1 X2 Y2"),
    wrong_type=(("0", "0", "1", "1", "--window-vertices", "0", "0", "8", "0", "0"), "at least 3"),
    positional=("0", "1", "2", "8", "-3", "1/2", "--window-vertices"),
)


#: Commands that write a whole document (a sheet of answers, a practice set, the exam book)
#: rather than one answer: they have no API function returning one Solution, no terminal
#: layout of their own (``--format rich``) and no ``--brief``/``--explain`` (which shape one
#: answer); their documents are tested by their own tests (pdflatex, pandoc, Chromium).
DOCUMENTS = {("sheet",), ("practice",), ("exam",)}

# The 3D chapter: 3d transform, 3d project.
TOO_MANY_VERTICES_3D = tuple(str(i % 7) for i in range(303))  # 101 vertices, one beyond 100
VOCABULARY[("3d", "transform")] = Vocab(
    valid=(
        ("1", "2", "3", "--rotate-x", "90", "--about", "0", "1", "1", "--translate", "1", "1", "1"),
        ("--solid", "unit-cube", "--rotate-axis", "0", "0", "0", "1", "1", "1", "120"),
    ),
    numbers=((0, 1, 2, 4, 6, 7, 8, 10, 11, 12), (3, 4, 5, 6, 7, 8, 9)),
    out_of_range=(
        (("0", "0", "0", "--translate", "1e10", "1", "1"), "out of range"),
        (("0", "0", "0", *["--translate", "1", "1", "1"] * 21), "at most 20 transformations"),
    ),
    too_few=(("0", "0", "--translate", "1", "1", "1"), "triples"),
    too_many=((*TOO_MANY_VERTICES_3D, "--translate", "1", "1", "1"), "at most 100 vertices"),
    wrong_type=(("0", "0", "0", "--shear", "w", "1", "1"), "axis x, y or z"),
    small={
        "--solid": ("unit-cube", "cube", "pyramid", "tetrahedron"),
        "--convention": ("hearn-baker", "foley", "rogers"),
        "--vectors": ("column", "row"),
        "--sense": ("standard", "reversed"),
    },
    positional=(
        "0",
        "1",
        "-3",
        "1/2",
        "--rotate-x",
        "90",
        "--rotate-z",
        "30",
        "--translate",
        "--scale",
        "2",
        "--about",
        "--reflect",
        "xy",
        "--shear",
        "z",
    ),
)
VOCABULARY[("3d", "project")] = Vocab(
    valid=(
        ("--solid", "unit-cube", "--perspective", "one-point", "--d", "2"),
        ("0", "0", "0", "1", "1", "1", "--parallel", "cabinet", "--angle", "30"),
    ),
    numbers=((5,), (0, 1, 2, 3, 4, 5, 9)),
    out_of_range=(
        (("--solid", "cube", "--perspective", "one-point", "--d", "1e10"), "out of range"),
        (("--solid", "cube", "--parallel", "dimetric", "--ratio", "2"), "(0, 1]"),
    ),
    too_few=(("0", "0", "--parallel", "cabinet"), "triples"),
    too_many=((*TOO_MANY_VERTICES_3D, "--parallel", "cabinet"), "at most 100 vertices"),
    wrong_type=(("--solid", "cube", "--parallel", "cabinet", "--angle", "20"), "multiple of 15"),
    small={
        "--solid": ("unit-cube", "cube", "pyramid"),
        "--parallel": ("cavalier", "cabinet", "isometric", "orthographic"),
        "--perspective": ("one-point", "two-point"),
        "--d": ("2", "4", "10"),
        "--angle": ("30", "45"),
        "--cop": ("minus-d", "plus-d", "origin"),
    },
    positional=("0", "1", "2", "-3", "1/2", "--translate", "--rotate-y", "30"),
)


# Visible-surface detection (scanconv 3d).

FACE = ("0", "0", "0", "1", "0", "0", "0", "1", "0")
FACE_UP = ("0", "0", "1", "0", "1", "1", "1", "0", "1")
ZA = ("0", "0", "1", "3", "0", "1", "0", "3", "1")
ZB = ("0", "0", "2", "2", "0", "2", "0", "2", "2")
VOCABULARY[("3d", "backface")] = Vocab(
    valid=(
        ("--solid", "cube", "--view", "0", "0", "-1"),
        (*FACE, ":", *FACE_UP, "--direction", "to-viewer"),
    ),
    numbers=((3, 4, 5), (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, 18)),
    out_of_range=(
        (("0", "0", "0", "1", "0", "0", "1e10", "1", "0"), "out of range"),
        (tuple(w for _ in range(25) for w in (*FACE, ":")), "at most 24"),
    ),
    too_few=(("0", "0", "0", "1", "0", "0"), "at least 3 vertices"),
    too_many=(tuple(str(c) for i in range(17) for c in (i, i * i, 0)), "at most 16"),
    wrong_type=(("0", "0", "0", "1", "0", "0", "0", "1"), "each vertex is x y z"),
    small={
        "--solid": ("cube", "pyramid", "tetrahedron"),
        "--direction": ("into-scene", "to-viewer"),
        "--convention": ("hearn-baker", "foley", "rogers"),
    },
    positional=("0", "1", "2", "-1", "1/2", ":"),
)
VOCABULARY[("3d", "zbuffer")] = Vocab(
    valid=((*ZA, ":", *ZB), (*ZA, ":", *ZB, "--size", "4", "--ties", "replace")),
    numbers=(
        (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, 18),
        (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, 18),
    ),
    out_of_range=(
        ((*ZA, "--size", "33"), "1 to 32"),
        (("0", "0", "1", "3", "0", "1e10", "0", "3", "1"), "out of range"),
    ),
    too_few=(("0", "0", "1", "3", "0", "1"), "at least 3 vertices"),
    too_many=(tuple(w for _ in range(9) for w in (*ZA, ":")), "at most 8"),
    wrong_type=(("0", "0", "1", "3", "0", "1", "0", "3"), "each vertex is x y z"),
    small={
        "--size": ("3", "4x3"),
        "--depth": ("larger-nearer", "smaller-nearer"),
        "--clear": ("zero", "farthest"),
        "--convention": ("hearn-baker", "foley", "rogers"),
    },
    positional=("0", "1", "2", "3", "1/2", ":"),
)
VOCABULARY[("3d", "warnock")] = Vocab(
    valid=((*ZA, ":", *ZB), (*ZA, ":", *ZB, "--size", "4", "--depth", "smaller-nearer")),
    numbers=(
        (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, 18),
        (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, 18),
    ),
    out_of_range=(
        ((*ZA, "--size", "64"), "1 to 32"),
        (("0", "0", "1", "3", "0", "1e10", "0", "3", "1"), "out of range"),
    ),
    too_few=(("0", "0", "1", "3", "0", "1"), "at least 3 vertices"),
    too_many=(tuple(w for _ in range(9) for w in (*ZA, ":")), "at most 8"),
    wrong_type=((*ZA, "--size", "6"), "2^n"),
    small={
        "--size": ("2", "4"),
        "--ties": ("keep", "replace"),
        "--convention": ("hearn-baker", "foley", "rogers"),
    },
    positional=("0", "1", "2", "3", "1/2", ":"),
)
VOCABULARY[("3d", "scanline")] = Vocab(
    valid=((*ZA, ":", *ZB), (*ZA, ":", *ZB, "--size", "4", "--ties", "replace")),
    numbers=(
        (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, 18),
        (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, 18),
    ),
    out_of_range=(
        ((*ZA, "--size", "33"), "1 to 32"),
        (("0", "0", "1", "3", "0", "1e10", "0", "3", "1"), "out of range"),
    ),
    too_few=(("0", "0", "1", "3", "0", "1"), "at least 3 vertices"),
    too_many=(tuple(w for _ in range(9) for w in (*ZA, ":")), "at most 8"),
    wrong_type=(("0", "0", "1", "3", "0", "1", "0", "3"), "each vertex is x y z"),
    small={
        "--size": ("3", "4x3"),
        "--depth": ("larger-nearer", "smaller-nearer"),
        "--convention": ("hearn-baker", "foley", "rogers"),
    },
    positional=("0", "1", "2", "3", "1/2", ":"),
)
VOCABULARY[("3d", "depth-sort")] = Vocab(
    valid=((*ZA, ":", *ZB), (*ZA, ":", *ZB, "--size", "4", "--depth", "smaller-nearer")),
    numbers=(
        (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, 18),
        (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, 18),
    ),
    out_of_range=(
        ((*ZA, "--size", "33"), "1 to 32"),
        (("0", "0", "1", "3", "0", "1e10", "0", "3", "1"), "out of range"),
    ),
    too_few=(("0", "0", "1", "3", "0", "1"), "at least 3 vertices"),
    too_many=(tuple(w for _ in range(9) for w in (*ZA, ":")), "at most 8"),
    wrong_type=(("0", "0", "1", "3", "0", "1", "0", "3"), "each vertex is x y z"),
    small={
        "--size": ("3", "4x3"),
        "--depth": ("larger-nearer", "smaller-nearer"),
        "--convention": ("hearn-baker", "foley", "rogers"),
    },
    positional=("0", "1", "2", "3", "1/2", ":"),
)
