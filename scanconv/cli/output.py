"""Writing an answer: stdout or a file (atomically), the figures, and the reader leaving.

This module and :mod:`scanconv.cli.entry` are the only ones that write to stdout or stderr.
The renderers never print; they return generators, and :func:`emit` writes what they yield.
A failure to write is exit status 1.
"""

import io
import os
import signal
import stat
import sys
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any, NamedTuple, NoReturn

import typer

from ..core import lazy
from ..core.records import Solution
from ..render import EXTENSIONS, FORMATS, Format, Notice, Options, render
from .options import Origin

if TYPE_CHECKING:
    import tempfile

    from rich import console as rich_console

    from ..render.figures import figure
else:  # each only on the path that uses it (start-up time)
    tempfile = lazy.module("tempfile")  # a file output
    rich_console = lazy.module("rich.console")  # the terminal format
    figure = lazy.module("scanconv.render.figures.figure")  # --svg, --png

PROG = "scanconv"


class Output(NamedTuple):
    """How and where to write an answer: the shared output options of every command."""

    fmt: Format = Format.auto
    grid: bool = True
    origin: Origin = Origin.bottom_left
    output: Path | None = None
    explain: bool = False
    brief: bool = False
    exact: bool = False
    svg: Path | None = None
    png: Path | None = None


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


#: The flags that show what a :class:`~scanconv.render.Notice` says was left out.
_WAYS = {"plain": "--format plain", "svg": "--svg FILE"}


def notice_text(notice: Notice) -> str:
    """A notice in the CLI's words: its message, then how to see what it left out.

    >>> notice_text(Notice("a figure is left out", ("plain",)))
    'a figure is left out; widen the terminal or see it with --format plain'
    >>> notice_text(Notice("grid left out", ("plain", "svg", "no-grid")))
    'grid left out; widen the terminal, see it with --format plain or --svg FILE, or leave it out with --no-grid'
    """
    if not notice.ways:
        return notice.message
    see = " or ".join(_WAYS[w] for w in notice.ways if w in _WAYS)
    steps = ["widen the terminal", f"see it with {see}"]
    if "no-grid" in notice.ways:
        steps.append("leave it out with --no-grid")
    words = " or ".join(steps) if len(steps) == 2 else ", ".join(steps[:-1]) + ", or " + steps[-1]
    return f"{notice.message}; {words}"


class Interrupted(SystemExit):
    """A run stopped by a signal: ``code`` is 130 for SIGINT (Ctrl-C), 143 for SIGTERM.

    A ``SystemExit``, so nothing on the way out (click turns a ``KeyboardInterrupt`` into an
    abort with an empty line on stderr) mistakes it for an error; every ``try`` that writes a
    file removes its temporary on the way (:func:`write_atomic`).
    """

    def __init__(self, signum: int) -> None:
        super().__init__(128 + signum)
        self.signum = signum

    def __str__(self) -> str:
        name = signal.Signals(self.signum).name
        return f"{'interrupted' if name == 'SIGINT' else 'terminated'} ({name})"


_signalled = False


def on_signal(signum: int, frame: Any) -> None:
    """The handler of SIGINT and SIGTERM during a run: the first raises :class:`Interrupted`;
    any later one (Ctrl-C pressed twice) is ignored, so that the clean-up it started (removing
    a temporary file, the one-line message) is not cut short."""
    global _signalled
    if _signalled:
        return
    _signalled = True
    raise Interrupted(signum)


def catch_signals() -> Callable[[], None]:
    """Install :func:`on_signal` for SIGINT and SIGTERM; return what restores the previous
    handlers. Outside the main thread signals are left alone."""
    global _signalled
    _signalled = False
    previous: dict[int, Any] = {}
    for sig in (signal.SIGINT, signal.SIGTERM):
        try:
            previous[sig] = signal.signal(sig, on_signal)
        except ValueError:  # not the main thread
            break

    def restore() -> None:
        for sig, handler in previous.items():
            signal.signal(sig, handler if handler is not None else signal.SIG_DFL)

    return restore


def _write(chunks: Iterable[Any], out: Any, width: int | None = None) -> None:
    console = None
    for chunk in chunks:
        if isinstance(chunk, str):
            out.write(chunk)
        elif isinstance(chunk, Notice):
            out.flush()
            note(notice_text(chunk))
        else:
            if console is None:
                console = rich_console.Console(
                    file=out, highlight=False, emoji=False, markup=False, width=width
                )
                console.on_broken_pipe = _broken_pipe  # type: ignore[method-assign]
            console.print(chunk)


def _broken_pipe() -> NoReturn:
    """rich's own handler exits with status 1 when the reader leaves; raise, so that
    :func:`emit` stops quietly with status 0 as for every other format."""
    raise BrokenPipeError(32, "Broken pipe")


def emit(solution: Solution, out: Output) -> None:
    """Render ``solution`` and write it to stdout or, atomically, to ``out.output``.

    The figures (``out.svg``, ``out.png``) are drawn and written first, so a figure that
    cannot be drawn (a ``ValueError``, exit 2 by the caller) or written (exit 1) leaves stdout
    empty.
    """
    # a command that declares its own --origin (sample) has it as the library's text
    out = out._replace(fmt=format_for_file(out.fmt, out.output), origin=Origin(out.origin))
    if out.svg is not None or out.png is not None:
        write_figures(solution, out.origin, out.svg, out.png)
    fmt = resolve(out.fmt, out.output is not None)
    width = None
    if fmt is Format.rich:
        width = terminal_width(sys.stdout if out.output is None else None)
    options = Options(
        grid=out.grid, origin=out.origin.value, brief=out.brief, exact=out.exact, width=width
    )
    chunks = render(solution, fmt, options)
    if out.output is None:
        try:
            _write(chunks, sys.stdout, width)
            sys.stdout.flush()
        except BrokenPipeError:
            _quiet_pipe()
        return
    write_atomic(out.output, lambda f: _write(chunks, f, width))


def terminal_width(stream: Any) -> int:
    """The width the rich format fits: the terminal's, or ``COLUMNS``, or 80 (rich's own
    rule, so the answer and the console that prints it agree)."""
    return rich_console.Console(file=stream if stream is not None else io.StringIO()).width


def named_format(fmt: str, path: Path | None) -> str | None:
    """The format the extension of ``path`` names (:data:`scanconv.render.EXTENSIONS`), or
    ``None``: the one rule of format conflicts, for every command (answers and documents). A
    ``--format`` that contradicts a ``.tex``, ``.csv``, ``.json``, ``.html``, ``.xml`` (Moodle
    XML) or ``.gift`` file (a binding extension) is refused (exit 2, nothing written); ``.md``
    and ``.txt`` files take any format.

    >>> named_format("auto", Path("a.tex")), named_format("csv", Path("notes.md"))
    ('latex', 'markdown')
    """
    if path is not None and path.suffix.lower() == ".pdf":  # never text under a PDF's name
        fail(
            f"--output {path}: this command writes text, not a PDF: -o "
            f"{path.with_suffix('.tex')} for LaTeX, or a question file through scanconv sheet "
            f"FILE --pdf {path}"
        )
    named = EXTENSIONS.get(path.suffix.lower()) if path is not None else None
    if named is not None and fmt not in ("auto", named) and FORMATS[named].binding:
        fail(f"--output {path} is {named} by its extension, but --format is {fmt}")
    return named


def format_for_file(fmt: Format, path: Path | None) -> Format:
    """The format of a single answer written to ``-o path``: the one ``--format`` names, else
    the extension's if it names a single-answer format (``answer.tex``: latex, ``a.csv``: csv,
    ``a.json``: json, ``a.md``: markdown, ``a.txt``: plain, ``a.html``: html), else ``auto``;
    conflicts are refused by :func:`named_format`.

    >>> format_for_file(Format.auto, Path("answer.tex")).value
    'latex'
    >>> format_for_file(Format.csv, Path("notes.md")).value
    'csv'
    """
    named = named_format(fmt.value, path)
    if fmt is not Format.auto or named is None or not FORMATS[named].renderer:
        return fmt
    return Format(named)


def document_format(fmt: str, path: Path | None) -> str:
    """The format of a document (a sheet, the exam book, a practice set) written to ``-o
    path``: ``--format``, else the extension's if it names a document format, else markdown;
    conflicts are refused by :func:`named_format`.

    >>> document_format("auto", Path("key.tex")), document_format("json", None)
    ('latex', 'json')
    """
    named = named_format(fmt, path)
    if fmt != "auto":
        return fmt
    return named if named is not None and FORMATS[named].sheet else "markdown"


def write_figures(solution: Solution, origin: Origin, svg: Path | None, png: Path | None) -> None:
    """Draw the figure of ``solution`` and write it, atomically, as SVG and/or PNG."""
    fig = figure.build(solution, origin.value)
    if svg is not None:
        text = figure.to_svg(fig)
        write_atomic(svg, lambda f: f.write(text))
    if png is not None:
        try:
            data = figure.to_png(fig)
        except ModuleNotFoundError:
            fail(
                "--png needs Pillow: pip install 'scanconv[png]' (in a source checkout: "
                "pip install -e '.[png]'), or use --svg",
                1,
            )
        write_atomic(png, lambda f: f.write(data), binary=True)


Pending = tuple[Path, Callable[[IO[Any]], object], bool]
"""A file to write: its path, what fills it, and whether it is binary."""


def write_atomic(path: Path, fill: Callable[[IO[Any]], object], *, binary: bool = False) -> None:
    """Create ``path`` through a temporary file in its directory and a rename.

    A failure leaves any existing file untouched and no partial file behind (exit 1).
    ``fill`` gets a text file (UTF-8, ``\\n`` line ends), or a binary one with ``binary``.
    """
    write_all([(path, fill, binary)])


def write_all(files: Iterable[Pending]) -> None:
    """Write several files all or none: each is written in full to a temporary file beside
    it, and only when every one is complete are they all renamed into place. A failure
    before the renames leaves none of them and the old files untouched (exit 1).

    A special file (``/dev/null``, ``/dev/stdout``, a FIFO) has nothing to replace: it is
    written into, after the renames.
    """
    staged: list[tuple[str, Path, Path]] = []
    special: list[Pending] = []
    try:
        for path, fill, binary in files:
            if _is_special(path):
                special.append((path, fill, binary))
            else:
                staged.append(_stage(path, fill, binary))
        while staged:
            tmp, target, path = staged[0]
            try:
                os.replace(tmp, target)
            except OSError as err:
                fail(f"cannot write {path}: {err.strerror or err}", 1)
            staged.pop(0)
    finally:
        for tmp, _, _ in staged:
            _unlink(tmp)
    for path, fill, binary in special:
        try:
            with (
                open(path, "wb") if binary else open(path, "w", encoding="utf-8", newline="\n")
            ) as f:
                fill(f)
        except OSError as err:
            fail(f"cannot write {path}: {err.strerror or err}", 1)


def _is_special(path: Path) -> bool:
    """Whether ``path`` exists and is not a regular file (a device, a FIFO)."""
    try:
        return not stat.S_ISREG(os.stat(path).st_mode)
    except OSError:  # missing (or unreadable): created, or the error is reported then
        return False


def _stage(path: Path, fill: Callable[[IO[Any]], object], binary: bool) -> tuple[str, Path, Path]:
    """Write the whole of ``path``'s content to a temporary file in its directory: the
    temporary file, the target (a symlink's target: the link is kept) and ``path``."""
    target = Path(os.path.realpath(path))
    blocked = _block_signals()  # a signal between creating the temporary and naming it: later
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    except OSError as err:
        _unblock_signals(blocked)
        fail(f"cannot write {path}: {err.strerror or err}", 1)
    try:
        _unblock_signals(blocked)  # one that came meanwhile is raised here, inside the clean-up
        with (
            os.fdopen(fd, "wb") if binary else os.fdopen(fd, "w", encoding="utf-8", newline="\n")
        ) as f:
            fill(f)
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; give the mode open() would
    except OSError as err:
        _unlink(tmp)
        fail(f"cannot write {path}: {err.strerror or err}", 1)
    except BaseException:
        _unlink(tmp)
        raise
    return tmp, target, path


def check_paths(inputs: Iterable[tuple[str, Any]], outputs: Iterable[tuple[str, Any]]) -> None:
    """Refuse, before any work (exit 2), an output that is a directory or that names the same
    file as an input or as another output (it would be overwritten). Each is ``(label,
    path)``: ``("QUESTIONS", "q.txt")``, ``("--pdf", "a.pdf")``; ``None`` and ``-`` (standard
    input or output) are skipped, and so are devices such as ``/dev/null``."""
    seen: dict[Any, tuple[str, Any]] = {}
    for label, path in inputs:
        if path not in (None, "", "-"):
            seen.setdefault(_identity(path), (label, path))
    for label, path in outputs:
        if path in (None, "", "-"):
            continue
        if os.path.isdir(path):
            fail(f"{label} {path}: is a directory; give a file name")
        if _is_special(Path(path)):
            continue
        key = _identity(path)
        if key in seen:
            other, other_path = seen[key]
            fail(f"{label} {path}: the same file as {other} {other_path}; give another name")
        seen[key] = (label, path)


def _identity(path: Any) -> Any:
    """What names one file: its device and inode if it exists, else its resolved path."""
    try:
        st = os.stat(path)
        return (st.st_dev, st.st_ino)
    except (OSError, ValueError):
        return os.path.normcase(os.path.realpath(path))


def _block_signals() -> Any:
    """Hold SIGINT and SIGTERM back (they stay pending); returns the mask to restore."""
    return signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})


def _unblock_signals(mask: Any) -> None:
    signal.pthread_sigmask(signal.SIG_SETMASK, mask)


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _unlink(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass


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
