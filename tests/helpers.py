"""Running the CLI in-process and in a subprocess, for the tests."""

from __future__ import annotations

import io
import os
import subprocess
import sys
from collections import deque
from collections.abc import Callable, Set
from contextlib import redirect_stderr, redirect_stdout
from dataclasses import dataclass
from typing import Any, TypeVar

from scanconv.cli import main
from scanconv.core.records import Pixel

T = TypeVar("T")


@dataclass
class Result:
    code: int
    out: str
    err: str


class _Bounded(io.StringIO):
    """Captured output that keeps its first ``limit`` characters and counts the rest: a
    fuzzed command may print a large allowed answer (the CLI streams it; a test that kept it
    whole in memory could hold gigabytes)."""

    def __init__(self, limit: int) -> None:
        super().__init__()
        self.limit, self.dropped = limit, 0

    def write(self, text: str) -> int:
        room = self.limit - self.tell()
        if room > 0:
            super().write(text[:room])
        self.dropped += max(0, len(text) - max(room, 0))
        return len(text)


def run(*args: str) -> Result:
    """Run ``scanconv ARGS`` in-process, capturing stdout and stderr."""
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        code = main(list(args))
    return Result(code, out.getvalue(), err.getvalue())


def run_process(*args: str, env: dict[str, str] | None = None, timeout: float = 60) -> Result:
    """Run ``python -m scanconv ARGS`` as a real process (pipes, signals, exit codes)."""
    full_env = {**os.environ, **(env or {})}
    proc = subprocess.run(
        [sys.executable, "-m", "scanconv", *args],
        capture_output=True,
        text=True,
        env=full_env,
        timeout=timeout,
    )
    return Result(proc.returncode, proc.stdout, proc.stderr)


def assert_refused(r: Result, *words: str) -> None:
    """Bad input: exit 2, nothing on stdout, one line on stderr naming the problem (each of
    ``words``), and no traceback."""
    assert r.code == 2, (r.code, r.out[:200], r.err)
    assert r.out == ""
    assert r.err.startswith("scanconv: error: ") and r.err.count("\n") == 1, r.err
    assert r.err.endswith("\n")
    assert "Traceback" not in r.err
    for word in words:
        assert word in r.err, (word, r.err)


def connected(pixels: Set[Pixel]) -> bool:
    """Every pixel reachable from any other through 8-neighbours (breadth-first search)."""
    start = next(iter(pixels))
    seen, todo = {start}, deque([start])
    while todo:
        x, y = todo.popleft()
        for q in ((x + dx, y + dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1)):
            if q in pixels and q not in seen:
                seen.add(q)
                todo.append(q)
    return len(seen) == len(pixels)


HANG_SECONDS = 60
"""A run that takes longer than this has escaped a work budget (every allowed input ends
within a minute, docs/limits.md): the guard of :func:`run_limited`, not a speed test."""


class Overtime(BaseException):
    """Raised by :func:`run_limited`'s alarm inside a run: a ``BaseException``, so that no
    ``except Exception`` in the code under test swallows it."""


def _run_bounded(*args: str, limit: int = 1 << 20) -> Result:
    """:func:`run`, keeping at most ``limit`` characters of each stream."""
    out, err = _Bounded(limit), _Bounded(limit)
    with redirect_stdout(out), redirect_stderr(err):
        code = main(list(args))
    return Result(code, out.getvalue(), err.getvalue())


def run_limited(*args: str, seconds: float = HANG_SECONDS) -> Result:
    """:func:`run` with hard limits: at most a megabyte of each stream is kept, and a run
    that has used ``seconds`` of CPU time fails the test with its command line instead of
    hanging the suite. CPU time (``ITIMER_PROF``), not
    wall time, so that a busy machine cannot trip it; the alarm interrupts Python code, and a
    ``faulthandler`` watchdog at ten times the limit of wall time ends the process (dumping
    every thread's stack) if the run is stuck where the alarm cannot reach it."""
    import faulthandler
    import signal

    def overtime(signum: int, frame: object) -> None:
        raise Overtime

    previous = signal.signal(signal.SIGPROF, overtime)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    faulthandler.dump_traceback_later(10 * seconds, exit=True)
    try:
        return _run_bounded(*args)
    except Overtime:
        import pytest

        pytest.fail(f"scanconv {' '.join(args)!r} used {seconds:g} s of CPU: a hole in a budget")
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        faulthandler.cancel_dump_traceback_later()
        signal.signal(signal.SIGPROF, previous)


def python_calls(fn: Callable[..., T], *args: Any) -> tuple[T, int]:
    """``fn(*args)`` and the number of Python function calls it made: a measure of the work
    done that, unlike a clock, does not depend on how busy the machine is (``refused before
    any work`` is "in a few thousand calls", where computing the rows takes millions)."""
    count = 0

    def profile(frame: Any, event: str, arg: Any) -> None:
        nonlocal count
        if event == "call":
            count += 1

    previous = sys.getprofile()
    sys.setprofile(profile)
    try:
        result = fn(*args)
    finally:
        sys.setprofile(previous)
    return result, count


def interpreter_calls(
    fn: Callable[..., T], *args: Any, stop_after: int | None = None
) -> tuple[T, int]:
    """:func:`python_calls`, counting calls of built-in functions and methods too (a loop of
    ``str.strip`` and ``re.sub`` over ten million lines is no Python call but 30 million of
    these). ``stop_after``: a run that makes more calls fails the test there (a guard counted
    in calls, so that a test of "refused at once" fails at once instead of doing the work)."""
    count = 0

    def profile(frame: Any, event: str, arg: Any) -> None:
        nonlocal count
        if event in ("call", "c_call"):
            count += 1
            if stop_after is not None and count > stop_after:
                sys.setprofile(None)
                raise Overtime

    previous = sys.getprofile()
    sys.setprofile(profile)
    try:
        result = fn(*args)
    except Overtime:
        import pytest

        pytest.fail(f"{getattr(fn, '__name__', fn)} made over {stop_after:,} calls")
    finally:
        sys.setprofile(previous)
    return result, count
