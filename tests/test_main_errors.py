"""``scanconv.cli.main`` turns whatever goes wrong while the answer streams into an exit status.

The renderer is replaced by one that writes a line and then fails in each way that can reach
``main`` (the reader gone, the disk full, Ctrl-C, a late bad value, memory, recursion): nothing
escapes, stderr gets at most one line, and a file being written keeps its old content.
"""

from __future__ import annotations

import errno
import signal
import stat
import sys
from pathlib import Path

import pytest

import scanconv.cli.entry as entry
import scanconv.cli.output as cli

from .helpers import run

LINE = ("line", "2", "2", "10", "6", "--format", "csv")


def _failing_renderer(exc: BaseException):
    def render(solution, fmt, options=None):
        yield "k,p,decision,x,y,p_next\n"
        raise exc

    return render


CASES = [
    (KeyboardInterrupt(), 130, None),
    (OSError(errno.EIO, "Input/output error"), 1, "cannot write output: Input/output error"),
    (RecursionError(), 2, "too deeply nested"),
    (ValueError("expression 'log(t)' is undefined\nat t = -1"), 2, "undefined at t = -1"),
    (MemoryError(), 1, "out of memory"),
]


@pytest.mark.parametrize(("exc", "code", "words"), CASES, ids=lambda c: type(c).__name__)
def test_a_failure_while_streaming_is_an_exit_status_and_one_line(exc, code, words, monkeypatch):
    monkeypatch.setattr(cli, "render", _failing_renderer(exc))
    r = run(*LINE)
    assert r.code == code
    assert r.out == "k,p,decision,x,y,p_next\n"  # what was written stays written
    if words is None:
        assert r.err == ""
    else:
        assert r.err.startswith("scanconv: error: ") and r.err.count("\n") == 1, r.err
        assert words in r.err


@pytest.mark.parametrize(("exc", "code", "words"), CASES, ids=lambda c: type(c).__name__)
def test_a_failure_while_writing_a_file_keeps_the_old_one(exc, code, words, tmp_path, monkeypatch):
    target = tmp_path / "answer.csv"
    target.write_text("old\n")
    monkeypatch.setattr(cli, "render", _failing_renderer(exc))
    r = run(*LINE, "--output", str(target))
    assert r.code in (code, 1)  # an OSError inside the file write is the file's error (1)
    assert r.out == "" and r.err.count("\n") <= 1
    assert target.read_text() == "old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["answer.csv"]


def test_a_closed_pipe_mid_stream_is_status_0_and_silent(monkeypatch):
    monkeypatch.setattr(cli, "render", _failing_renderer(BrokenPipeError(errno.EPIPE, "pipe")))
    monkeypatch.setattr(cli, "_quiet_pipe", lambda: 0)  # don't redirect the test's stdout
    r = run(*LINE)
    assert r.code == 0 and r.err == ""


def test_rich_closed_pipe_raises_instead_of_exiting_1():
    """rich's Console exits with status 1 on a closed pipe; scanconv's handler raises instead."""
    with pytest.raises(BrokenPipeError):
        cli._broken_pipe()


def test_sigterm_handler_is_installed_during_a_program_run_and_restored(monkeypatch):
    seen = []

    def render(solution, fmt, options=None):
        seen.append(signal.getsignal(signal.SIGTERM))
        yield ""

    before = signal.getsignal(signal.SIGTERM)
    monkeypatch.setattr(cli, "render", render)
    monkeypatch.setattr(sys, "argv", ["scanconv", *LINE])
    assert entry.main() == 0  # as the program: the arguments from sys.argv
    assert run(*LINE).code == 0  # in-process (a test, a notebook): the caller's handlers stay
    assert seen == [entry._terminate, before]
    assert signal.getsignal(signal.SIGTERM) is before
    with pytest.raises(SystemExit) as info:
        entry._terminate(signal.SIGTERM, None)
    assert info.value.code == 143


def test_special_file_that_cannot_be_written_is_exit_1(tmp_path, monkeypatch):
    """A special file (a device, a FIFO) that fails while written into is exit 1."""
    target = tmp_path / "special"
    target.write_text("")
    monkeypatch.setattr(stat, "S_ISREG", _no)  # write_atomic then treats it as a device
    monkeypatch.setattr(cli, "render", _failing_renderer(OSError(errno.ENOSPC, "No space")))
    r = run(*LINE, "--output", str(target))
    assert r.code == 1 and "cannot write" in r.err and r.err.count("\n") == 1


def _no(mode: int) -> bool:
    return False


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_version_and_help_in_process():
    r = run("--version")
    assert r.code == 0 and r.out.startswith("scanconv ") and r.err == ""
    r = run("line", "--help")
    assert r.code == 0 and r.out.startswith("Usage: scanconv line")


def test_an_existing_directory_is_refused_as_an_output(tmp_path: Path):
    r = run(*LINE, "--output", str(tmp_path))
    assert r.code == 2 and r.out == "" and r.err.count("\n") == 1
    assert "directory" in r.err
