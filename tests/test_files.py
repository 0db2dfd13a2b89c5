"""Every option that writes a file (--output, --svg, --png, enumerated from the app) writes it
atomically: complete or not at all, an existing file never truncated, no temporary left
behind; a path that cannot be written is exit 1 with one line. Special files (/dev/null, a
FIFO) are written into, and a symlink's target is replaced, not the link. (The special-file
case is tested with a FIFO, never with /dev/null: a regression, run as root, would replace it.)
The in-process runs have a hard limit (:func:`tests.helpers.run_limited`).
"""

from __future__ import annotations

import errno
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from .cli_vocabulary import VOCABULARY, commands, file_options
from .helpers import run_limited

pytestmark = pytest.mark.slow

WRITERS = [
    (path, option)
    for path, command in commands()
    if path in VOCABULARY
    for option in file_options(command)
]
IDS = [f"{' '.join(path)} {option}" for path, option in WRITERS]
PRECIOUS = "precious: must survive\n"


def _args(path: tuple[str, ...], option: str, target: Path | str) -> list[str]:
    return [*path, *VOCABULARY[path].valid[0], "--format", "markdown", option, str(target)]


def _needs_pillow(option: str) -> None:
    if option == "--png":
        pytest.importorskip("PIL")


def _only(directory: Path, *names: str) -> None:
    """Nothing but ``names`` in ``directory``: no temporary file left behind."""
    assert sorted(p.name for p in directory.iterdir()) == sorted(names)


def test_every_file_option_is_covered():
    options = {option for _, option in WRITERS}
    assert {"--output"} <= options
    assert all(o in ("--output", "--svg", "--png") for o in options), options
    assert len({path for path, _ in WRITERS}) == len(VOCABULARY)  # every command has --output


@pytest.mark.parametrize(("path", "option"), WRITERS, ids=IDS)
def test_writes_the_file_complete_and_leaves_nothing_else(path, option, tmp_path):
    _needs_pillow(option)
    target = tmp_path / "answer"
    target.write_text(PRECIOUS)
    r = run_limited(*_args(path, option, target))
    assert r.code == 0, r.err
    data = target.read_bytes()
    if option == "--output":
        assert r.out == "" and data.startswith((b"## ", b"# "))  # an answer, or a sheet's title
    else:
        assert r.out.startswith("## ")  # the answer still goes to stdout
        assert data.startswith(b"\x89PNG" if option == "--png" else (b"<?xml", b"<svg"))
        assert data.rstrip().endswith(b"IEND\xaeB`\x82" if option == "--png" else b"</svg>")
    _only(tmp_path, "answer")
    assert oct(target.stat().st_mode & 0o777) == oct(0o666 & ~_umask())


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


@pytest.mark.parametrize(("path", "option"), WRITERS, ids=IDS)
def test_an_unwritable_path_is_exit_1_with_one_line(path, option, tmp_path):
    _needs_pillow(option)
    blocker = tmp_path / "a-file"
    blocker.write_text(PRECIOUS)
    for target in (tmp_path / "missing" / "x", blocker / "x"):
        r = run_limited(*_args(path, option, target))
        assert r.code == 1, (target, r.code, r.err)
        assert r.err.startswith("scanconv: error: cannot write") and r.err.count("\n") == 1
        assert str(target) in r.err
        assert r.out == ""  # figures are written before the answer, so nothing was printed
        assert "Traceback" not in r.err
    _only(tmp_path, "a-file")
    assert blocker.read_text() == PRECIOUS


@pytest.mark.parametrize(("path", "option"), WRITERS, ids=IDS)
def test_bad_input_never_touches_an_existing_file(path, option, tmp_path):
    _needs_pillow(option)
    target = tmp_path / "keep"
    target.write_text(PRECIOUS)
    argv = _args(path, option, target)
    argv[len(path)] = "nan"  # the first value of a valid invocation, made bad
    r = run_limited(*argv)
    assert r.code == 2 and r.out == "" and r.err.count("\n") == 1, r.err
    assert target.read_text() == PRECIOUS
    _only(tmp_path, "keep")


class _FailingFile:
    """A file object that fails with ENOSPC after ``budget`` bytes, like a full disk."""

    def __init__(self, real, budget: int) -> None:
        self.real, self.budget = real, budget

    def write(self, data):
        self.budget -= len(data)
        if self.budget < 0:
            raise OSError(errno.ENOSPC, "No space left on device")
        return self.real.write(data)

    def __getattr__(self, name):
        return getattr(self.real, name)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.real.close()


@pytest.mark.parametrize("budget", [0, 100])
@pytest.mark.parametrize(("path", "option"), WRITERS, ids=IDS)
def test_a_failure_while_writing_leaves_the_old_file_whole(
    path, option, budget, tmp_path, monkeypatch
):
    """The disk fills up after ``budget`` bytes: exit 1, the old file intact, no temporary."""
    _needs_pillow(option)
    target = tmp_path / "keep"
    target.write_text(PRECIOUS)
    real_fdopen = os.fdopen
    monkeypatch.setattr(os, "fdopen", lambda *a, **k: _FailingFile(real_fdopen(*a, **k), budget))
    r = run_limited(*_args(path, option, target))
    assert r.code == 1, (r.code, r.err)
    assert "No space left on device" in r.err and r.err.count("\n") == 1
    assert target.read_text() == PRECIOUS
    _only(tmp_path, "keep")


@pytest.mark.parametrize(("path", "option"), WRITERS, ids=IDS)
def test_a_failed_rename_leaves_the_old_file_whole(path, option, tmp_path, monkeypatch):
    _needs_pillow(option)
    target = tmp_path / "keep"
    target.write_text(PRECIOUS)

    def no_rename(src, dst):
        raise OSError(errno.EXDEV, "Invalid cross-device link")

    monkeypatch.setattr(os, "replace", no_rename)
    r = run_limited(*_args(path, option, target))
    assert r.code == 1 and "cannot write" in r.err and r.err.count("\n") == 1
    assert target.read_text() == PRECIOUS
    _only(tmp_path, "keep")


def test_a_symlink_keeps_pointing_at_the_new_file(tmp_path):
    real = tmp_path / "real.md"
    real.write_text(PRECIOUS)
    link = tmp_path / "link.md"
    link.symlink_to(real.name)
    r = run_limited("line", "2", "2", "10", "6", "-f", "csv", "--output", str(link))
    assert r.code == 0, r.err
    assert link.is_symlink() and real.read_text().startswith("k,p,decision")
    _only(tmp_path, "link.md", "real.md")


def test_a_fifo_is_written_into_not_replaced(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    received: list[bytes] = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_bytes()), daemon=True)
    reader.start()
    r = run_limited("line", "2", "2", "10", "6", "-f", "csv", "--output", str(fifo))
    reader.join(timeout=30)
    assert r.code == 0, r.err
    assert received and received[0].startswith(b"k,p,decision,x,y,p_next\n")
    assert fifo.is_fifo()
    _only(tmp_path, "pipe")


@pytest.mark.parametrize(("sig", "status"), [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_signal_while_writing_leaves_the_old_file_whole(sig, status, tmp_path):
    target = tmp_path / "keep.csv"
    target.write_text(PRECIOUS)
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "scanconv",
            "line",
            "0",
            "0",
            "1999999",
            "1",
            "-f",
            "csv",
            "--output",
            str(target),
        ],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    deadline = time.monotonic() + 60
    while not any(p.name.endswith(".tmp") for p in tmp_path.iterdir()):  # writing has started
        assert time.monotonic() < deadline and proc.poll() is None, proc.stderr
        time.sleep(0.05)
    time.sleep(0.2)
    proc.send_signal(sig)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == status, err
    assert out == "" and "Traceback" not in err
    assert target.read_text() == PRECIOUS
    _only(tmp_path, "keep.csv")
