"""Signals and write faults, with real processes.

* SIGINT and SIGTERM (also twice in quick succession) while an answer is being written to
  ``--output`` (and ``--svg``/``--png``): exit 130 or 143, one line on stderr, no temporary
  file left, and the previous file's content kept whole; sent at many moments of a run, each
  file is afterwards either the old one or a complete new one, never a partial one.
* SIGINT and SIGTERM while streaming to stdout: the same status and one line.
* ENOSPC (stdout on ``/dev/full`` in every format; a full 64 KiB tmpfs for files, where the
  test may mount one), a read-only directory: one line, exit 1, no file. A directory as the
  output path is bad input, as today: one line, exit 2. A closed pipe: a quiet exit 0 in every
  format.
"""

from __future__ import annotations

import contextlib
import os
import shlex
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from scanconv.render import Format

from .helpers import HANG_SECONDS

pytestmark = pytest.mark.slow

FORMATS = [f.value for f in Format if f is not Format.auto]
LONG = ["line", "0", "0", "1999999", "1", "--format", "csv"]  # 7 to 30 s of csv (ALL_ROWS)
OLD = "the previous answer\n"
_SCANCONV = (sys.executable, "-m", "scanconv")


def _start(*args: str, cwd: Path | None = None, stdout: int | None = None) -> subprocess.Popen:
    return subprocess.Popen(
        [sys.executable, "-m", "scanconv", *args],
        stdout=subprocess.DEVNULL if stdout is None else stdout,
        stderr=subprocess.PIPE,
        cwd=cwd,
        env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1"},
    )


def _temporaries(directory: Path) -> list[Path]:
    return [p for p in directory.iterdir() if p.name.endswith(".tmp")]


def _wait_for(condition, what: str) -> None:
    """Poll until ``condition()``; a guard against a hang (not a speed test) fails after
    :data:`tests.helpers.HANG_SECONDS` with ``what`` was awaited."""
    end = time.monotonic() + HANG_SECONDS
    while not condition():
        if time.monotonic() > end:
            raise AssertionError(f"still waiting after {HANG_SECONDS} s for {what}")
        time.sleep(0.01)


def _finish(proc: subprocess.Popen) -> tuple[int, str]:
    _, err = proc.communicate(timeout=60)
    return proc.returncode, err.decode("utf-8", "replace")


SIGNALS = [
    pytest.param([signal.SIGINT], 130, "interrupted (SIGINT)", id="SIGINT"),
    pytest.param([signal.SIGTERM], 143, "terminated (SIGTERM)", id="SIGTERM"),
    pytest.param([signal.SIGINT, signal.SIGINT], 130, "interrupted", id="SIGINT twice"),
    pytest.param([signal.SIGTERM, signal.SIGTERM], 143, "terminated", id="SIGTERM twice"),
    pytest.param([signal.SIGINT, signal.SIGTERM], 130, "interrupted", id="SIGINT then SIGTERM"),
]


@pytest.mark.parametrize(("signals", "code", "line"), SIGNALS)
def test_a_signal_during_a_file_write_keeps_the_old_file_and_leaves_no_temporary(
    signals, code, line, tmp_path
):
    target = tmp_path / "answer.csv"
    target.write_text(OLD)
    proc = _start(*LONG, "--output", str(target))
    _wait_for(lambda: bool(_temporaries(tmp_path)), "the temporary file")  # the write is under way
    time.sleep(0.3)
    for sig in signals:
        proc.send_signal(sig)
    status, err = _finish(proc)
    assert status == code, err
    assert err == f"scanconv: {line}\n" or (
        err.startswith(f"scanconv: {line}") and err.count("\n") == 1
    )
    assert target.read_text() == OLD
    assert not _temporaries(tmp_path)


@pytest.mark.parametrize(("signals", "code", "line"), SIGNALS[:3])
def test_a_signal_while_streaming_to_stdout_is_one_line(signals, code, line):
    proc = _start(*LONG, stdout=subprocess.PIPE)
    assert proc.stdout is not None
    proc.stdout.read(100_000)  # it is writing
    for sig in signals:
        proc.send_signal(sig)
    proc.stdout.close()
    proc.stdout = None
    status, err = _finish(proc)
    assert status == code and err.startswith(f"scanconv: {line}") and err.count("\n") == 1, err


def _complete_or_old(path: Path, kind: str) -> None:
    data = path.read_bytes()
    if data == OLD.encode():
        return
    if kind == "svg":
        assert data.rstrip().endswith(b"</svg>"), data[-100:]
    elif kind == "png":
        assert data.startswith(b"\x89PNG") and data.endswith(b"IEND\xaeB`\x82"), data[-20:]
    else:
        assert data.rstrip().endswith(b"]}"), data[-100:]  # the json object's end


MOMENTS = 6
"""How many moments of a run the spread test signals (each a process of about a second of
CPU): SIGINT, SIGTERM, each twice or followed by the other, from start-up to the end (12
moments before: the same kinds of signal at twice the density)."""


def test_a_signal_at_any_moment_leaves_each_file_old_or_whole(tmp_path):
    """Figures are written first, then the answer: signals at moments spread over the run."""
    pytest.importorskip("PIL")
    files = {"svg": tmp_path / "f.svg", "png": tmp_path / "f.png", "json": tmp_path / "a.json"}
    args = ["line", "0", "0", "80", "48", "--svg", str(files["svg"]), "--png", str(files["png"])]
    args += ["--output", str(files["json"])]
    # how long a whole run takes, to spread the signals over it
    start = time.monotonic()
    subprocess.run([sys.executable, "-m", "scanconv", *args], check=True, capture_output=True)
    whole = time.monotonic() - start
    for i in range(MOMENTS):
        for path in files.values():
            path.write_text(OLD)
        proc = _start(*args)
        time.sleep(whole * i / MOMENTS)
        proc.send_signal(signal.SIGTERM if i % 2 else signal.SIGINT)
        if i % 3 == 0:
            proc.send_signal(signal.SIGTERM)  # twice in quick succession
        status, err = _finish(proc)
        # -2/-15: killed before Python installed its handlers (nothing was written yet)
        assert status in (0, 130, 143, -signal.SIGINT, -signal.SIGTERM), err
        assert "Traceback" not in err and err.count("\n") <= 1, err
        for kind, path in files.items():
            _complete_or_old(path, kind)
        assert not _temporaries(tmp_path)


# --- write faults ---------------------------------------------------------------------------


@pytest.mark.parametrize("fmt", FORMATS)
def test_a_full_disk_on_stdout_is_one_line_and_exit_1(fmt):
    with open("/dev/full", "wb") as full:
        proc = subprocess.run(
            [sys.executable, "-m", "scanconv", "line", "0", "0", "5000", "3", "--format", fmt],
            stdout=full,
            stderr=subprocess.PIPE,
            text=True,
            timeout=60,
        )
    assert proc.returncode == 1, proc.stderr
    assert proc.stderr.startswith("scanconv: error: ") and proc.stderr.count("\n") == 1, proc.stderr
    assert "No space" in proc.stderr


@contextlib.contextmanager
def _tmpfs(path: Path, options: str) -> Iterator[Path]:
    """A small tmpfs at ``path`` (only root may mount: the test is skipped otherwise)."""
    path.mkdir()
    mounted = subprocess.run(
        ["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(path)], capture_output=True
    )
    if mounted.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {mounted.stderr.decode().strip()}")
    try:
        yield path
    finally:
        subprocess.run(["umount", str(path)], check=False)


def test_a_full_disk_keeps_the_old_file_and_leaves_no_temporary(tmp_path):
    with _tmpfs(tmp_path / "small", "size=64k") as small:
        target = small / "answer.csv"
        target.write_text(OLD)
        proc = subprocess.run(
            [*_SCANCONV, "line", "0", "0", "100000", "3", "-f", "csv", "--output", str(target)],
            capture_output=True,
            text=True,
            timeout=60,
        )
        assert proc.returncode == 1, proc.stderr
        assert proc.stderr.count("\n") == 1 and "No space left" in proc.stderr, proc.stderr
        assert target.read_text() == OLD
        assert [p.name for p in small.iterdir()] == ["answer.csv"]


def _read_only_directory(tmp_path: Path) -> contextlib.AbstractContextManager[Path]:
    if os.geteuid() == 0:  # root writes into a mode-0555 directory: use a read-only mount
        return _tmpfs(tmp_path / "ro", "ro,size=16k")
    directory = tmp_path / "ro"
    directory.mkdir()
    directory.chmod(0o555)
    return contextlib.nullcontext(directory)


@pytest.mark.parametrize("option", ["--output", "--svg"])
def test_a_read_only_directory_is_one_line_and_exit_1(option, tmp_path):
    with _read_only_directory(tmp_path) as directory:
        proc = subprocess.run(
            [*_SCANCONV, "line", "0", "0", "10", "3", option, str(directory / "answer.out")],
            capture_output=True,
            text=True,
            timeout=60,
        )
        assert proc.returncode == 1, proc.stderr
        assert (
            proc.stderr.startswith("scanconv: error: cannot write") and proc.stderr.count("\n") == 1
        )
        assert proc.stdout == "" and not list(directory.iterdir())


@pytest.mark.parametrize("option", ["--output", "--svg", "--png"])
def test_a_directory_as_the_output_path_is_refused_as_bad_input(option, tmp_path):
    """As today: the option's value is checked before any work (exit 2, like any bad
    argument), so nothing is computed or written."""
    proc = subprocess.run(
        [sys.executable, "-m", "scanconv", "line", "0", "0", "10", "3", option, str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert proc.returncode == 2, proc.stderr
    assert proc.stderr.startswith("scanconv: error: ") and proc.stderr.count("\n") == 1
    assert "is a directory" in proc.stderr and proc.stdout == ""
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("fmt", FORMATS)
def test_a_closed_pipe_is_a_quiet_exit_0_in_every_format(fmt):
    args = ["line", "0", "0", "9999", "3", "--format", fmt]
    command = " ".join(shlex.quote(a) for a in (sys.executable, "-m", "scanconv", *args))
    proc = subprocess.run(
        ["bash", "-c", f"set -o pipefail; {command} | head -c 10"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 0 and proc.stderr == "", proc.stderr
    assert len(proc.stdout) == 10
