"""The ``scanconv`` command line: parse, pick the renderer, print.

This is the only module that writes to stdout or stderr. The algorithms and renderers never
print; they return generators, and :func:`emit` writes what they yield. Errors in the input
become one line on stderr and exit status 2; a failure to write is exit status 1.
"""

from __future__ import annotations

import copy
import os
import re
import signal
import sys
from collections.abc import Iterable
from enum import Enum
from fractions import Fraction
from pathlib import Path
from typing import Annotated, Any, NoReturn

import typer

from .. import __version__
from ..core.numeric import parse_number
from ..core.records import Solution
from ..render import Format, Notice, Options, render

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


def integer(text: str | int) -> int:
    """typer parser for a whole number (``16``, ``1e3``); the error names the bad value."""
    if isinstance(text, int):  # a default value
        return text
    value = number(text)
    if value.denominator != 1:
        raise typer.BadParameter(f"{text!r} is not an integer")
    return value.numerator


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
ExplainOpt = Annotated[
    bool,
    typer.Option(
        "--explain",
        help="rich format: also show the derivation (given values, working with the numbers "
        "substituted, notes). markdown, latex and plain always show it.",
    ),
]
SvgOpt = Annotated[
    Path | None,
    typer.Option(
        "--svg",
        help="Also draw the figure (pixels, ideal primitive, step numbers, axes) as SVG into "
        "this file, atomically.",
        dir_okay=False,
    ),
]
PngOpt = Annotated[
    Path | None,
    typer.Option(
        "--png",
        help="Also draw the figure as PNG into this file (needs Pillow: the png extra).",
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


def _write(chunks: Iterable[Any], out: Any) -> None:
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
                console.on_broken_pipe = _broken_pipe  # type: ignore[method-assign]
            console.print(chunk)


def _broken_pipe() -> NoReturn:
    """rich's own handler exits with status 1 when the reader leaves; raise, so that
    :func:`emit` stops quietly with status 0 as for every other format."""
    raise BrokenPipeError(32, "Broken pipe")


def emit(
    solution: Solution,
    fmt: Format,
    *,
    grid: bool = True,
    origin: Origin = Origin.bottom_left,
    output: Path | None = None,
    explain: bool = False,
    svg: Path | None = None,
    png: Path | None = None,
) -> None:
    """Render ``solution`` and write it to stdout or, atomically, to ``output``.

    The figures (``svg``, ``png``) are drawn and written first, so a figure that cannot be
    drawn (exit 2) or written (exit 1) leaves stdout empty.
    """
    if svg is not None or png is not None:
        write_figures(solution, origin, svg, png)
    fmt = resolve(fmt, output is not None)
    chunks = render(solution, fmt, Options(grid=grid, origin=origin.value, explain=explain))
    if output is None:
        try:
            _write(chunks, sys.stdout)
            sys.stdout.flush()
        except BrokenPipeError:
            _quiet_pipe()
        return
    write_atomic(output, lambda f: _write(chunks, f))


def write_figures(solution: Solution, origin: Origin, svg: Path | None, png: Path | None) -> None:
    """Draw the figure of ``solution`` and write it, atomically, as SVG and/or PNG."""
    from ..render import figure

    fig = library_call(figure.build, solution, origin.value)
    if svg is not None:
        text = figure.to_svg(fig)
        write_atomic(svg, lambda f: f.write(text))
    if png is not None:
        try:
            data = figure.to_png(fig)
        except ModuleNotFoundError:
            fail("--png needs Pillow: pip install 'scanconv[png]' (or use --svg)", 1)
        write_atomic(png, lambda f: f.write(data), binary=True)


def write_atomic(path: Path, fill: Any, *, binary: bool = False) -> None:
    """Create ``path`` through a temporary file in its directory and a rename.

    A failure leaves any existing file untouched and no partial file behind (exit 1).
    ``fill`` gets a text file (UTF-8, ``\\n`` line ends), or a binary one with ``binary``.
    """
    import stat
    import tempfile  # here, not at the top: only a file output needs it (start-up time)

    try:
        special = not stat.S_ISREG(os.stat(path).st_mode)
    except OSError:  # missing (or unreadable): created below, or the error is reported there
        special = False
    if special:  # /dev/null, /dev/stdout, a FIFO: nothing to replace, so write into it
        try:
            with (
                open(path, "wb") if binary else open(path, "w", encoding="utf-8", newline="\n")
            ) as f:
                fill(f)
        except OSError as err:
            fail(f"cannot write {path}: {err.strerror or err}", 1)
        return
    target = Path(os.path.realpath(path))  # through a symlink: replace its target, keep the link
    directory = target.parent
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=directory)
    except OSError as err:
        fail(f"cannot write {path}: {err.strerror or err}", 1)
    try:
        with (
            os.fdopen(fd, "wb") if binary else os.fdopen(fd, "w", encoding="utf-8", newline="\n")
        ) as f:
            fill(f)
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; give the mode open() would
        os.replace(tmp, target)
    except OSError as err:
        _unlink(tmp)
        fail(f"cannot write {path}: {err.strerror or err}", 1)
    except BaseException:
        _unlink(tmp)
        raise


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


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
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """Draw the line from (X1, Y1) to (X2, Y2), with the step table of the chosen algorithm.

    Example: scanconv line 2 2 10 6 --algo bresenham --svg line.svg
    """
    from ..answers.line import line_solution

    solution = library_call(line_solution, algo.value, x1, y1, x2, y2)
    emit(
        solution,
        fmt,
        grid=grid,
        origin=origin,
        output=output,
        explain=explain,
        svg=svg,
        png=png,
    )


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


# --- image representation (storage, quantize, sample, image ramp) -----------------------------


class ColorModel(str, Enum):
    """Colour pixel formats of ``storage --color``."""

    rgb24 = "rgb24"


class InputKind(str, Enum):
    """What the input range of ``quantize --range`` holds."""

    integer = "integer"
    real = "real"


class Recon(str, Enum):
    """Reconstruction value of a quantization level."""

    mid = "midpoint"
    low = "lower"  # not ``lower``: that name is str.lower


def _exact_values(texts: tuple[str, ...] | None) -> tuple[Any, ...] | None:
    """Constant expressions (``2*pi``, ``-1/3``) from the command line, exact when rational."""
    if texts is None:
        return None
    from ..core.expr import parse_exact

    return tuple(library_call(parse_exact, t) for t in texts)


@app.command(context_settings=NUMERIC_ARGS)
def storage(
    m: Num,
    n: Num,
    levels: Annotated[
        Fraction | None,
        typer.Option("--levels", "-L", parser=number, help="Gray levels L (k = ceil(log2 L))."),
    ] = None,
    bits: Annotated[
        Fraction | None, typer.Option("--bits", parser=number, help="Bits per pixel B (1-24).")
    ] = None,
    binary: Annotated[
        bool, typer.Option("--binary", help="Binary image: 1 bit per pixel.")
    ] = False,
    color: Annotated[
        ColorModel | None,
        typer.Option("--color", case_sensitive=False, help="Colour image: rgb24 = 24 bits."),
    ] = None,
    frames: Annotated[
        Fraction | None,
        typer.Option("--frames", parser=number, help="Number of frames F (default 1)."),
    ] = None,
    fmt: FormatOpt = Format.auto,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
) -> None:
    """Storage of an M x N image: M x N x ceil(log2 L) bits, in bytes, KB/MB and KiB/MiB.

    Give exactly one of --levels, --bits, --binary, --color.
    Example: scanconv storage 1024 768 --levels 256
    """
    from ..answers.image import storage_solution

    solution = library_call(
        storage_solution,
        m,
        n,
        levels=levels,
        bits=bits,
        binary=binary,
        color=None if color is None else color.value,
        frames=1 if frames is None else frames,
    )
    emit(solution, fmt, output=output, explain=explain)


@app.command(context_settings=NUMERIC_ARGS)
def quantize(
    bits: Annotated[
        Fraction, typer.Option("--bits", parser=number, help="Bits per pixel B (1-24).")
    ],
    value_range: Annotated[
        tuple[Fraction, Fraction] | None,
        typer.Option(
            "--range",
            parser=number,
            metavar="LO HI",
            help="Input range: add each level's inputs and reconstruction value.",
        ),
    ] = None,
    kind: Annotated[
        InputKind,
        typer.Option(
            "--input",
            case_sensitive=False,
            help="integer: the inputs are the integers LO..HI (8-bit: --range 0 255); "
            "real: any value in [LO, HI].",
        ),
    ] = InputKind.integer,
    recon: Annotated[
        Recon,
        typer.Option(
            "--recon",
            case_sensitive=False,
            help="Reconstruction value: the midpoint of each level's cell or its lower end.",
        ),
    ] = Recon.mid,
    fmt: FormatOpt = Format.auto,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
) -> None:
    """The quantization table: decimal value, binary code and gray-level name of each level.

    Example: scanconv quantize --bits 3 --range 0 255
    """
    from ..answers.image import quantize_solution

    solution = library_call(
        quantize_solution,
        bits,
        value_range,
        integer=kind is InputKind.integer,
        recon=recon.value,
    )
    emit(solution, fmt, output=output, explain=explain)


SizeOpt = Annotated[
    str, typer.Option("--size", help="M x N: M rows, N columns (8x8, or 8 for square).")
]
LevelsOpt = Annotated[
    Fraction, typer.Option("--levels", "-L", parser=number, help="Gray levels L.")
]


@app.command(context_settings=NUMERIC_ARGS)
def sample(
    expr: Annotated[
        str, typer.Argument(metavar="EXPR", help="f(x, y), e.g. 'x + y' or 'sin(x)*cos(y)'.")
    ],
    size: SizeOpt,
    levels: LevelsOpt,
    domain: Annotated[
        tuple[str, str, str, str] | None,
        typer.Option(
            "--domain",
            metavar="X0 X1 Y0 Y1",
            help="Sample x from X0 to X1 and y from Y0 to Y1 (default: 0..N-1, 0..M-1).",
        ),
    ] = None,
    value_range: Annotated[
        tuple[str, str] | None,
        typer.Option(
            "--range",
            metavar="LO HI",
            help="Range of f quantized onto the levels (default: the samples' min and max).",
        ),
    ] = None,
    fmt: FormatOpt = Format.auto,
    grid: Annotated[
        bool, typer.Option("--grid/--no-grid", help="Draw the shaded text picture.")
    ] = True,
    origin: Annotated[
        Origin,
        typer.Option(
            "--origin",
            case_sensitive=False,
            help="Row 0 is the top: bottom-left: y up (row 0 is y1); top-left: y down.",
        ),
    ] = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
) -> None:
    """Sample f(x, y) on an M x N grid, quantize to L levels: the matrix and a shaded picture.

    Example: scanconv sample "x + y" --size 8x8 --levels 8
    """
    from ..answers.image import parse_size, sample_levels, sample_solution

    m, n = library_call(parse_size, size)
    sampled = library_call(
        sample_levels,
        expr,
        m,
        n,
        levels,
        domain=_exact_values(domain),
        value_range=_exact_values(value_range),
        origin=origin.value,
    )
    solution = library_call(sample_solution, sampled)
    emit(solution, fmt, grid=grid, origin=origin, output=output, explain=explain)


image_app = typer.Typer(
    help="Image representation examples from the notes.",
    add_completion=False,
    rich_markup_mode=None,
    no_args_is_help=True,
    context_settings={"help_option_names": ["-h", "--help"]},
)
app.add_typer(image_app, name="image")


@image_app.command("ramp")
def image_ramp(
    size: Annotated[
        str, typer.Option("--size", help="M x N: M rows, N columns (8x8, or 8 for square).")
    ] = "8",
    levels: Annotated[
        Fraction | None,
        typer.Option("--levels", "-L", parser=number, help="Gray levels L (default 8)."),
    ] = None,
    fmt: FormatOpt = Format.auto,
    grid: Annotated[
        bool, typer.Option("--grid/--no-grid", help="Draw the shaded text picture.")
    ] = True,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
) -> None:
    """The notes' grayscale example: level i + j folded back at L - 1, for any size and L.

    Example: scanconv image ramp --size 8 --levels 8
    """
    from ..answers.image import parse_size, ramp_solution

    m, n = library_call(parse_size, size)
    solution = library_call(ramp_solution, m, n, 8 if levels is None else levels)
    emit(solution, fmt, grid=grid, output=output, explain=explain)


# --- compare: every method for one primitive, side by side (issue 6) -------------------------

compare_app = typer.Typer(
    help="Every method for one primitive side by side, with the reason wherever they differ.",
    add_completion=False,
    rich_markup_mode=None,
    no_args_is_help=True,
    context_settings={"help_option_names": ["-h", "--help"]},
)
app.add_typer(compare_app, name="compare")


@compare_app.command("line", context_settings=NUMERIC_ARGS)
def compare_line(
    x1: Num,
    y1: Num,
    x2: Num,
    y2: Num,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
) -> None:
    """The basic method, DDA and Bresenham for one line: one row per major-axis coordinate.

    Example: scanconv compare line 2 8 10 4
    """
    from ..answers.compare import compare_lines

    solution = library_call(compare_lines, x1, y1, x2, y2)
    emit(solution, fmt, grid=grid, origin=origin, output=output, explain=explain)


@compare_app.command("circle", context_settings=NUMERIC_ARGS)
def compare_circle(
    r: Num,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
) -> None:
    """Every circle method over the first octant (one row per x), against the midpoint method.

    Example: scanconv compare circle 10
    """
    from ..answers.compare import compare_circles

    solution = library_call(compare_circles, r)
    emit(solution, fmt, grid=grid, origin=origin, output=output, explain=explain)


# --- curves (issue 4): parametric, Bezier, B-spline, continuity, local control -----------------

SamplesOpt = Annotated[
    int | None,
    typer.Option(
        "--samples",
        "-n",
        parser=integer,
        help="Steps of t: the curve is tabulated at N + 1 values of t, both ends included "
        "(default 16; parametric line: max(|dx|, |dy|)).",
        show_default=False,
    ),
]
TRangeOpt = Annotated[
    tuple[str, str] | None,
    typer.Option(
        "--t-range",
        metavar="T0 T1",
        help="Parameter range; numbers or formulas such as 2*pi (default: the curve's own).",
        show_default=False,
    ),
]
DegreeOpt = Annotated[
    int,
    typer.Option(
        "--degree", "-p", parser=integer, help="B-spline degree p (1 <= p <= n, at most 10)."
    ),
]
KnotsOpt = Annotated[
    str,
    typer.Option(
        "--knots",
        help="open (clamped uniform), uniform, or an explicit comma list of n + p + 2 values.",
    ),
]
Coords = Annotated[
    list[str], typer.Argument(metavar="X0 Y0 X1 Y1 ...", help="Control points as x y pairs.")
]


def _control_points(values: list[str]) -> list[tuple[Any, Any]]:
    """``X0 Y0 X1 Y1 ...`` as exact points (``ValueError`` for a bad number or an odd count)."""
    from ..answers.curves import pairs

    return pairs([parse_number(v) for v in values])


def _parameter(text: str) -> Any:
    """A value of t: a number or a constant formula (exact when rational)."""
    from ..core.expr import parse_exact

    value = parse_exact(text)
    return value.numerator if isinstance(value, Fraction) and value.denominator == 1 else value


def _curve_emit(
    solution: Solution,
    fmt: Format,
    grid: bool,
    origin: Origin,
    output: Path | None,
    explain: bool,
    svg: Path | None,
    png: Path | None,
) -> None:
    emit(
        solution,
        fmt,
        grid=grid,
        origin=origin,
        output=output,
        explain=explain,
        svg=svg,
        png=png,
    )


parametric_app = typer.Typer(
    help="Parametric curves x(t), y(t): line, circle, ellipse, parabola or your own formulas.",
    add_completion=False,
    rich_markup_mode=None,
    no_args_is_help=True,
    context_settings={"help_option_names": ["-h", "--help"]},
)
app.add_typer(parametric_app, name="parametric")


def _parametric(
    kind: str,
    fmt: Format,
    grid: bool,
    origin: Origin,
    output: Path | None,
    explain: bool,
    svg: Path | None,
    png: Path | None,
    **kwargs: Any,
) -> None:
    from ..answers.curves import parametric_solution

    solution = library_call(parametric_solution, kind, **kwargs)
    _curve_emit(solution, fmt, grid, origin, output, explain, svg, png)


def _pair(values: tuple[str, str]) -> tuple[Fraction, Fraction]:
    return parse_number(values[0]), parse_number(values[1])


@parametric_app.command("circle", context_settings=NUMERIC_ARGS)
def parametric_circle(
    center: Annotated[
        tuple[str, str], typer.Option("--center", metavar="X Y", help="Centre (xc, yc).")
    ] = ("0", "0"),
    radius: Annotated[str, typer.Option("--radius", "-r", help="Radius r.")] = "1",
    t_range: TRangeOpt = None,
    samples: SamplesOpt = None,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """x = xc + r cos t, y = yc + r sin t, 0 <= t <= 2 pi.

    Example: scanconv parametric circle --center 0 0 --radius 5 --samples 16
    """
    c = library_call(_pair, center)
    r = library_call(parse_number, radius)
    _parametric(
        "circle",
        fmt,
        grid,
        origin,
        output,
        explain,
        svg,
        png,
        center=c,
        radius=r,
        t_range=t_range,
        samples=samples,
    )


@parametric_app.command("ellipse", context_settings=NUMERIC_ARGS)
def parametric_ellipse(
    center: Annotated[
        tuple[str, str], typer.Option("--center", metavar="X Y", help="Centre (xc, yc).")
    ] = ("0", "0"),
    a: Annotated[str, typer.Option("--a", help="Semi-axis a (along x).")] = "2",
    b: Annotated[str, typer.Option("--b", help="Semi-axis b (along y).")] = "1",
    t_range: TRangeOpt = None,
    samples: SamplesOpt = None,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """x = xc + a cos t, y = yc + b sin t, 0 <= t <= 2 pi.

    Example: scanconv parametric ellipse --center 0 0 --a 8 --b 4
    """
    c = library_call(_pair, center)
    av, bv = library_call(parse_number, a), library_call(parse_number, b)
    _parametric(
        "ellipse",
        fmt,
        grid,
        origin,
        output,
        explain,
        svg,
        png,
        center=c,
        a=av,
        b=bv,
        t_range=t_range,
        samples=samples,
    )


@parametric_app.command("parabola", context_settings=NUMERIC_ARGS)
def parametric_parabola(
    vertex: Annotated[
        tuple[str, str], typer.Option("--vertex", metavar="H K", help="Vertex (h, k).")
    ] = ("0", "0"),
    a: Annotated[str, typer.Option("--a", help="Coefficient a in y = k + a t^2.")] = "1",
    t_range: TRangeOpt = None,
    samples: SamplesOpt = None,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """x = h + t, y = k + a t^2 (the notes' x = t, y = t^2 by default), -3 <= t <= 3.

    Example: scanconv parametric parabola --t-range -3 3
    """
    v = library_call(_pair, vertex)
    av = library_call(parse_number, a)
    _parametric(
        "parabola",
        fmt,
        grid,
        origin,
        output,
        explain,
        svg,
        png,
        vertex=v,
        a=av,
        t_range=t_range,
        samples=samples,
    )


@parametric_app.command("line", context_settings=NUMERIC_ARGS)
def parametric_line(
    x0: Num,
    y0: Num,
    x1: Num,
    y1: Num,
    t_range: TRangeOpt = None,
    samples: SamplesOpt = None,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """x = x0 + t (x1 - x0), y = y0 + t (y1 - y0), 0 <= t <= 1.

    Example: scanconv parametric line 0 0 10 4
    """
    _parametric(
        "line",
        fmt,
        grid,
        origin,
        output,
        explain,
        svg,
        png,
        points=(x0, y0, x1, y1),
        t_range=t_range,
        samples=samples,
    )


@parametric_app.command("custom", context_settings=NUMERIC_ARGS)
def parametric_custom(
    x: Annotated[str, typer.Option("--x", help="x(t), e.g. '3*cos(t)'.", show_default=False)],
    y: Annotated[str, typer.Option("--y", help="y(t), e.g. '2*sin(t)'.", show_default=False)],
    t_range: TRangeOpt = None,
    samples: SamplesOpt = None,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """Your own x(t) and y(t): numbers, t, + - * / **, pi, e, sin cos tan sqrt exp log abs.

    Example: scanconv parametric custom --x "3*cos(t)" --y "2*sin(t)" --t-range 0 2*pi
    """
    _parametric(
        "custom",
        fmt,
        grid,
        origin,
        output,
        explain,
        svg,
        png,
        x=x,
        y=y,
        t_range=t_range,
        samples=samples,
    )


@app.command(context_settings=NUMERIC_ARGS)
def bezier(
    coords: Coords,
    samples: SamplesOpt = None,
    at: Annotated[
        str | None,
        typer.Option("--at", metavar="T", help="De Casteljau's construction at this t in [0, 1]."),
    ] = None,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """Bezier curve of the control points P0 .. Pn: Bernstein weights per t, pixels, grid.

    Example: scanconv bezier 0 0 1 2 3 3 4 0 --samples 8   (or --at 0.5)
    """
    from ..answers.curves import DEFAULT_SAMPLES, bezier_at_solution, bezier_solution

    points = library_call(_control_points, coords)
    if at is not None:
        t = library_call(_parameter, at)
        solution = library_call(bezier_at_solution, points, t)
    else:
        solution = library_call(
            bezier_solution, points, DEFAULT_SAMPLES if samples is None else samples
        )
    _curve_emit(solution, fmt, grid, origin, output, explain, svg, png)


@app.command(context_settings=NUMERIC_ARGS)
def bspline(
    coords: Coords,
    degree: DegreeOpt = 3,
    knots: KnotsOpt = "open",
    basis: Annotated[
        bool, typer.Option("--basis", help="Print only the table of basis values N_i,p(t).")
    ] = False,
    at: Annotated[
        str | None,
        typer.Option(
            "--at", metavar="T", help="Evaluate one t: Cox-de Boor, the non-zero terms, C(t)."
        ),
    ] = None,
    samples: SamplesOpt = None,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """B-spline of degree p (Cox-de Boor): basis values N_i,p(t) per t, the curve, pixels.

    Example: scanconv bspline 0 0 1 2 3 3 4 0 5 2 --degree 2 --knots open
    """
    from ..answers.curves import bspline_at_solution, bspline_solution, parse_knots

    points = library_call(_control_points, coords)
    knot_spec = library_call(parse_knots, knots)
    if at is not None:
        t = library_call(_parameter, at)
        solution = library_call(bspline_at_solution, points, degree, knot_spec, t)
    else:
        solution = library_call(
            bspline_solution,
            points,
            degree,
            knot_spec,
            samples,
            basis_only=basis,
        )
    _curve_emit(solution, fmt, grid, origin, output, explain, svg, png)


def _two_segments(values: list[str]) -> tuple[list[Any], list[Any]]:
    if values.count(":") != 1:
        raise ValueError(
            "give two Bezier segments separated by ':', e.g. 0 0 1 1 2 0 : 2 0 3 -1 4 0"
        )
    i = values.index(":")
    return _control_points(values[:i]), _control_points(values[i + 1 :])


@app.command(context_settings=NUMERIC_ARGS)
def continuity(
    coords: Annotated[
        list[str],
        typer.Argument(
            metavar="X0 Y0 ... : X0 Y0 ...",
            help="The control points of the first segment, ':', those of the second.",
        ),
    ],
    samples: SamplesOpt = None,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """Continuity (C0, C1, C2) at the join of two Bezier segments, with the derivatives.

    Example: scanconv continuity 0 0 1 2 3 3 4 0 : 4 0 5 -3 7 -2 8 0
    """
    from ..answers.curves import DEFAULT_SAMPLES, continuity_solution

    first, second = library_call(_two_segments, coords)
    solution = library_call(
        continuity_solution, first, second, DEFAULT_SAMPLES if samples is None else samples
    )
    _curve_emit(solution, fmt, grid, origin, output, explain, svg, png)


@app.command("local-control", context_settings=NUMERIC_ARGS)
def local_control(
    coords: Coords,
    move: Annotated[
        tuple[str, str, str],
        typer.Option(
            "--move",
            metavar="I X Y",
            help="Move control point P_I to (X, Y).",
            show_default=False,
        ),
    ],
    degree: DegreeOpt = 3,
    knots: KnotsOpt = "open",
    samples: SamplesOpt = None,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
) -> None:
    """Bezier vs B-spline: move one control point, see which samples and pixels change.

    Example: scanconv local-control 0 0 1 2 3 3 4 0 5 2 7 1 --move 5 7 5 --degree 2
    """
    from ..answers.curves import DEFAULT_SAMPLES, local_control_solution, parse_knots

    points = library_call(_control_points, coords)
    knot_spec = library_call(parse_knots, knots)
    index = library_call(_index, move[0])
    new = library_call(_pair, (move[1], move[2]))
    solution = library_call(
        local_control_solution,
        points,
        index,
        new,
        degree,
        knot_spec,
        DEFAULT_SAMPLES if samples is None else samples,
    )
    emit(solution, fmt, grid=grid, origin=origin, output=output, explain=explain)


def _index(text: str) -> int:
    value = parse_number(text)
    if value.denominator != 1:
        raise ValueError(f"--move index must be an integer, got {text}")
    return value.numerator


# --- circles and ellipses (issue 3) ------------------------------------------------------------


class CircleMethod(str, Enum):
    """Circle methods; ``general`` is the notes' name for ``polynomial``."""

    midpoint = "midpoint"
    bresenham = "bresenham"
    polynomial = "polynomial"
    general = "general"
    trig = "trig"
    symmetric_dda = "symmetric-dda"


class Rounding(str, Enum):
    """How the floating-point circle methods turn coordinates into pixels."""

    half_up = "half-up"
    trunc = "trunc"


CenterOpt = Annotated[
    tuple[Fraction, Fraction] | None,
    typer.Option(
        "--center",
        "-c",
        parser=number,
        metavar="XC YC",
        show_default=False,
        help="Centre (xc, yc), integers; default (0, 0).",
    ),
]


@app.command(context_settings=NUMERIC_ARGS)
def circle(
    r: Num,
    center: CenterOpt = None,
    method: Annotated[
        CircleMethod,
        typer.Option("--method", "-m", case_sensitive=False, help="Circle method."),
    ] = CircleMethod.midpoint,
    rounding: Annotated[
        Rounding,
        typer.Option(
            "--rounding",
            case_sensitive=False,
            help="polynomial, trig and symmetric-dda: round half up, floor(v + 1/2), or "
            "truncate like a C (int) cast.",
        ),
    ] = Rounding.half_up,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """Draw the circle of radius R: one octant's step table, the 8-way symmetry, the pixels.

    Example: scanconv circle 8 --center 10 10 --method bresenham
    """
    from ..answers.circle import circle_solution

    xc, yc = center or (0, 0)
    solution = library_call(circle_solution, method.value, r, xc, yc, rounding.value)
    emit(
        solution,
        fmt,
        grid=grid,
        origin=origin,
        output=output,
        explain=explain,
        svg=svg,
        png=png,
    )


@app.command(context_settings=NUMERIC_ARGS)
def ellipse(
    rx: Num,
    ry: Num,
    center: CenterOpt = None,
    fmt: FormatOpt = Format.auto,
    grid: GridOpt = True,
    origin: OriginOpt = Origin.bottom_left,
    output: OutputOpt = None,
    explain: ExplainOpt = False,
    svg: SvgOpt = None,
    png: PngOpt = None,
) -> None:
    """Draw the ellipse with semi-axes RX, RY by the midpoint method (regions 1 and 2).

    Example: scanconv ellipse 8 6 --center 0 0
    """
    from ..answers.ellipse import ellipse_solution

    xc, yc = center or (0, 0)
    solution = library_call(ellipse_solution, rx, ry, xc, yc)
    emit(
        solution,
        fmt,
        grid=grid,
        origin=origin,
        output=output,
        explain=explain,
        svg=svg,
        png=png,
    )


# --- entry point ------------------------------------------------------------------------------


_MINUS = "\u2212"
_NEG_NONFINITE = re.compile(r"-(inf|infinity|nan)$", re.IGNORECASE)


def _command_for(argv: list[str]) -> Any:
    """The click command for ``argv``, building only the subcommand it names.

    typer turns the signature of every command into click parameters each time the CLI
    starts, a cost that grows with each command added. A run that names its subcommand
    (``scanconv line ...``) gets a group holding just that one, with the same callback and
    settings, so its parsing, help and errors are unchanged; anything else (``--help``,
    ``--version``, an unknown name) gets the whole group.
    """
    if argv and not argv[0].startswith("-"):
        commands = [
            c
            for c in app.registered_commands
            if c.callback is not None
            and (c.name or typer.main.get_command_name(c.callback.__name__)) == argv[0]
        ]
        groups = [g for g in app.registered_groups if g.name == argv[0]]
        if commands or groups:
            one = copy.copy(app)
            one.registered_commands, one.registered_groups = commands, groups
            return typer.main.get_command(one)
    return typer.main.get_command(app)


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
        code = _quiet_pipe()
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
