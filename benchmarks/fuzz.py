"""The long fuzz: random command lines and random question files, each run a limited process.

``python benchmarks/fuzz.py`` (about 15 minutes on 2 quiet cores; ``--argv 200 --questions
50`` for a smoke run) draws

* ``--argv`` (default 2,000) argument vectors spread evenly over every command of the CLI
  (enumerated from the app, ``tests/cli_vocabulary.py``): each starts from one of the
  command's quick valid calls and is mutated as ``tests/test_fuzz.py`` does (numbers at a
  validator's edge or beyond every limit, options with plausible or junk values, tokens
  replaced by junk or dropped);
* ``--questions`` (default 500) question files: titles, sections, marks, comments, prose and
  mutated questions of every command a sheet takes, with a BOM, NUL bytes, U+2028, very long
  lines and many large questions now and then. Each file goes through ``scanconv sheet``
  (a random format, key or worksheet) and one of its questions through ``scanconv check``
  against a student's table (one of ``tests/data/check``, or a random one).

Every run is a process of its own, in a scratch folder, limited to 60 s (SIGTERM, then SIGKILL
10 s later) and 1 GiB of address space (``RLIMIT_AS``). By default each is forked from a
process that has imported scanconv once and runs ``scanconv.cli.main`` as the program does
(signal handlers included), which makes the fuzz about three times cheaper than starting an
interpreter per run; ``--exec`` runs each as ``timeout 60 prlimit --as=1073741824 python -m
scanconv ...`` instead (the same exit statuses on a smoke run). The report counts the runs that printed a traceback, ran over the time
limit, or ran out of memory (the limit refused an allocation: a ``MemoryError``, the CLI's
"out of memory" line, or a crash by signal), and those that broke the CLI's contract (an exit
status other than 0, 1 or 2; an error that is not one line; output on stdout with exit 2), and
lists each one's command line. The exit status is the number of such runs (0: none).

Options: ``--seed`` (default 2026), ``--jobs`` (parallel runs, default 2), ``--timeout``,
``--memory`` (bytes), ``--json FILE`` (the runs that failed and the counts, as JSON).
"""

from __future__ import annotations

import argparse
import json
import os
import random
import resource
import shlex
import subprocess
import sys
import tempfile
import threading
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tests.cli_vocabulary import (  # noqa: E402
    VOCABULARY,
    Vocab,
    choices,
    commands,
    file_options,
    options,
)
from tests.test_fuzz import BOUNDARY, SPECIAL  # noqa: E402

CHECK_DATA = ROOT / "tests" / "data" / "check"
#: The commands a question file cannot hold (documents and marking, not questions).
NOT_QUESTIONS = {"sheet", "practice", "exam", "check", "theory"}
SMALL = ("0", "1", "2", "3", "-1", "-2", "5", "7", "10", "16", "1/2", "-7/4", "0.5", "2.5")
BEYOND = ("1000000001", "-1000000001", "99999999999999999999", "1e40", "-1e40")
UNICODE = ("é", "∞", "½", "\u2212" + "3", "𝟙", "\u202e", "\u2028", "\x1b[31m", "\ufeff")
FORMATS = ("markdown", "latex", "html", "json", "plain", "csv", "rich")


# --- argument vectors ----------------------------------------------------------------------------


def _junk(rng: random.Random) -> str:
    kind = rng.randrange(5)
    if kind == 0:
        return rng.choice(SPECIAL)
    if kind == 1:
        return rng.choice(BEYOND)
    if kind == 2:
        return rng.choice(SMALL)
    if kind == 3:
        return rng.choice(UNICODE)
    return "".join(rng.choice("abcxyz0123456789-+/.*()tT ") for _ in range(rng.randrange(1, 12)))


def _value(rng: random.Random, plausible: tuple[str, ...]) -> str:
    roll = rng.random()
    if plausible and roll < 0.5:
        return rng.choice(plausible)
    if roll < 0.8:
        return rng.choice(SMALL + BOUNDARY)
    return _junk(rng)


def _piece(rng: random.Random, command: Any, vocab: Vocab) -> list[str]:
    files = set(file_options(command))
    params = [p for p in options(command) if p.opts[0] != "--help"]
    roll = rng.random()
    if params and roll < 0.6:
        param = rng.choice(params)
        name = rng.choice([*param.opts, *param.secondary_opts])
        if param.opts[0] in files:
            return [name, "FILE"]
        if getattr(param, "is_flag", False):
            return [name]
        plausible = choices(param) or vocab.small.get(param.opts[0], ())
        return [name, *(_value(rng, plausible) for _ in range(max(1, param.nargs)))]
    if roll < 0.85:
        return [_value(rng, vocab.positional)]
    return [_junk(rng)]


def mutate(rng: random.Random, command: Any, vocab: Vocab) -> list[str]:
    """One of the command's valid calls, mutated up to four times (as tests/test_fuzz.py)."""
    which = rng.randrange(len(vocab.valid))
    argv = list(vocab.valid[which])
    numbers = list(vocab.numbers[which]) if which < len(vocab.numbers) else []
    for _ in range(rng.randrange(5)):
        action = rng.choice(("insert", "replace", "drop", "append", "edge", "edge", "beyond"))
        live = [i for i in numbers if i < len(argv)]
        if action in ("edge", "beyond") and live:
            pool = BOUNDARY if action == "edge" else (*BEYOND, "1000000000", "-1000000000")
            argv[rng.choice(live)] = rng.choice(pool)
        elif action in ("insert", "append") or (not argv and action != "edge"):
            where = len(argv) if action == "append" else rng.randrange(len(argv) + 1)
            argv[where:where] = _piece(rng, command, vocab)
        elif action == "replace" and argv:
            argv[rng.randrange(len(argv))] = _junk(rng)
        elif action == "drop" and argv:
            del argv[rng.randrange(len(argv))]
    return argv


def place_files(argv: list[str], files: set[str], directory: Path, tag: int) -> list[str]:
    """Every file option's value into the scratch folder: a new file, a missing folder, the
    folder itself."""
    out: list[str] = []
    for i, token in enumerate(argv):
        if token == "FILE" and i and argv[i - 1] in files:
            token = str(
                [directory / f"f{tag}-{i}.out", directory / "missing" / "x.out", directory][tag % 3]
            )
        out.append(token)
    return out


# --- question files ------------------------------------------------------------------------------


def question(
    rng: random.Random, pool: list[tuple[tuple[str, ...], Any, Vocab]], *, dirty: bool
) -> str:
    """A question line: one of a command's valid calls or (``dirty``, now and then) a mutated
    one, with marks and a comment now and then."""
    path, command, vocab = rng.choice(pool)
    mutated = dirty and rng.random() < 0.3
    argv = mutate(rng, command, vocab) if mutated else list(rng.choice(vocab.valid))
    argv = [a for a in argv if a != "FILE"]
    text = " ".join(shlex.quote(a) for a in (*path, *argv))
    if rng.random() < 0.4:
        marks = ("1", "2", "4", "10", "0", "-1", "1.5", "99999") if dirty else ("1", "2", "4")
        text = f"[{rng.choice(marks)}] {text}"
    if rng.random() < 0.1:
        text += "   # " + (_junk(rng) if dirty else "a comment")
    return text


def question_file(rng: random.Random, pool: list[tuple[tuple[str, ...], Any, Vocab]]) -> str:
    """Half the files are clean (every question one of its command's valid calls, so the
    sheet is made); the other half mutated questions, junk lines and odd characters."""
    dirty = rng.random() < 0.5
    lines: list[str] = []
    if rng.random() < 0.5:
        words = (_junk(rng) if dirty else rng.choice(UNICODE + SMALL) for _ in range(4))
        lines.append("title: Unit " + " ".join(words))
    for _ in range(rng.randrange(1, 16)):
        roll = rng.random()
        if roll < 0.08:
            lines.append("section: " + _junk(rng))
        elif roll < 0.16:
            lines.append("# " + _junk(rng))
        elif roll < 0.2 and dirty:
            lines.append(_junk(rng))
        if roll < 0.3:  # wording, then its question
            lines.append("> " + " ".join(_junk(rng) for _ in range(rng.randrange(1, 6))))
        lines.append(question(rng, pool, dirty=dirty))
    roll = rng.random()
    if roll < 0.03:  # many large questions: the sheet's total budget
        lines += ["line 0 0 9999 1"] * rng.choice((50, 200, 1000))
    elif roll < 0.05:
        lines.append("line 0 0 " + "1" * rng.randrange(5, 400) + " 1")
    elif roll < 0.06:
        lines.append("x" * rng.choice((10_000, 1_000_000)))
    elif roll < 0.08:
        lines.append("sample 'x+y' --size 1024 -L 8")
    text = "\n".join(lines) + "\n"
    roll = rng.random()
    if roll < 0.04:
        text = "\ufeff" + text
    elif roll < 0.07:
        text = text.replace("\n", "\u2028", 1)
    elif roll < 0.09:
        text = text.replace(" ", "\x00", 1)
    elif roll < 0.11:
        text = text.replace("\n", "\r\n")
    return text


def student_table(rng: random.Random, directory: Path, tag: int) -> Path:
    """One of tests/data/check, or a random table (rows of numbers, junk, a wrong header)."""
    real = sorted(p for p in CHECK_DATA.iterdir() if p.is_file())
    if rng.random() < 0.6:
        return rng.choice(real)
    rows = ["k,x,y,plot", *(",".join(_value(rng, SMALL) for _ in range(4)) for _ in range(9))]
    if rng.random() < 0.3:
        rows.insert(rng.randrange(len(rows)), _junk(rng))
    path = directory / f"student{tag}.{rng.choice(('csv', 'md', 'json', 'txt'))}"
    path.write_text("\n".join(rows) + "\n", encoding="utf-8", errors="surrogatepass")
    return path


# --- running -------------------------------------------------------------------------------------


@dataclass
class Run:
    argv: list[str]
    kind: str
    status: int = 0
    seconds: float = 0.0
    cpu: float = 0.0
    peak_mib: float = 0.0
    problems: list[str] = field(default_factory=list)
    err: str = ""


FORKER = r"""
import json, os, resource, signal, sys, time
# what every run imports anyway, imported once here: each run is a fork of this process
import numpy, rich, tabulate, typer
from scanconv.cli import main

requests, replies = sys.stdin, sys.stdout
for request in requests:
    job = json.loads(request)
    pid = os.fork()
    if pid == 0:  # the run: its own limits, folder, stdio and arguments, as the program
        try:
            resource.setrlimit(resource.RLIMIT_AS, (job["memory"], job["memory"]))
            os.chdir(job["cwd"])
            for fd, path, mode in ((0, os.devnull, os.O_RDONLY), (1, job["out"], os.O_WRONLY),
                                   (2, job["err"], os.O_WRONLY)):
                os.dup2(os.open(path, mode), fd)
            sys.stdin = open(0, closefd=False)
            sys.stdout = open(1, "w", closefd=False)
            sys.stderr = open(2, "w", closefd=False)
            sys.argv = ["scanconv", *job["argv"]]
            code = main()
            sys.stdout.flush()
            sys.stderr.flush()
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else 1
        except BaseException:
            import traceback
            traceback.print_exc()
            sys.stderr.flush()
            code = 1
        os._exit(code)
    start = time.monotonic()
    killed = False
    while True:
        done, status, usage = os.wait4(pid, os.WNOHANG)
        if done:
            break
        elapsed = time.monotonic() - start
        if elapsed > job["timeout"] and not killed:
            os.kill(pid, signal.SIGTERM)
            killed = True
        if elapsed > job["timeout"] + 10:
            os.kill(pid, signal.SIGKILL)
        time.sleep(0.005)
    replies.write(json.dumps({
        "status": os.waitstatus_to_exitcode(status), "killed": killed,
        "seconds": time.monotonic() - start, "cpu": usage.ru_utime + usage.ru_stime,
        "peak": usage.ru_maxrss,
    }) + "\n")
    replies.flush()
"""


class Forker:
    """A process that has imported scanconv once and forks one child per run (saving the
    interpreter's start-up and imports, most of a quick run's cost): the child sets its own
    address-space limit (``RLIMIT_AS``, as ``prlimit --as``) and runs ``scanconv.cli.main``
    as the program would (signal handlers included); the forker ends it with SIGTERM at the
    time limit (as ``timeout``), then SIGKILL 10 s later."""

    def __init__(self) -> None:
        env = {**os.environ, "NO_COLOR": "1", "COLUMNS": "100", "PYTHONDONTWRITEBYTECODE": "1"}
        self.proc = subprocess.Popen(
            [sys.executable, "-c", FORKER],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
            env=env,
        )

    def run(self, job: dict[str, Any]) -> dict[str, Any]:
        assert self.proc.stdin is not None and self.proc.stdout is not None
        self.proc.stdin.write(json.dumps(job) + "\n")
        self.proc.stdin.flush()
        return dict(json.loads(self.proc.stdout.readline()))

    def close(self) -> None:
        if self.proc.stdin is not None:
            self.proc.stdin.close()
        self.proc.wait()


def run_one(
    run: Run, directory: Path, timeout: float, memory: int, forker: Forker | None = None
) -> Run:
    """``run.argv`` in ``directory`` under the time and memory limits: forked by ``forker``,
    or without one as ``timeout T prlimit --as=M python -m scanconv ...``."""
    with (
        tempfile.NamedTemporaryFile(dir=directory) as out,
        tempfile.NamedTemporaryFile(dir=directory) as err,
    ):
        if forker is not None:
            job = {"argv": run.argv, "cwd": str(directory), "out": out.name, "err": err.name}
            reply = forker.run({**job, "timeout": timeout, "memory": memory})
            run.status = 124 if reply["killed"] else reply["status"]
            run.seconds, run.cpu, run.peak_mib = (
                reply["seconds"],
                reply["cpu"],
                reply["peak"] / 1024,
            )
        else:
            _exec(run, directory, timeout, memory, out, err)
        size = os.path.getsize(out.name)
        run.err = Path(err.name).read_bytes()[:20_000].decode("utf-8", "replace")
    run.problems = problems(run, size)
    return run


def _exec(run: Run, directory: Path, timeout: float, memory: int, out: Any, err: Any) -> None:
    limits = ["timeout", "-k", "10", f"{timeout:g}", "prlimit", f"--as={memory}", "--"]
    env = {**os.environ, "NO_COLOR": "1", "PYTHONDONTWRITEBYTECODE": "1", "COLUMNS": "100"}
    start = time.monotonic()
    proc = subprocess.Popen(
        [*limits, sys.executable, "-m", "scanconv", *run.argv],
        stdin=subprocess.DEVNULL,
        stdout=out,
        stderr=err,
        cwd=directory,
        env=env,
    )
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = run.status = os.waitstatus_to_exitcode(status)
    run.seconds = time.monotonic() - start
    run.cpu = usage.ru_utime + usage.ru_stime
    run.peak_mib = usage.ru_maxrss / 1024


def problems(run: Run, stdout_size: int) -> list[str]:
    found: list[str] = []
    err = run.err
    if "Traceback" in err:
        found.append("traceback")
    if run.status in (124, 137, -9):
        found.append("over time")
    if (
        "MemoryError" in err
        or "out of memory" in err
        or "Cannot allocate" in err
        or run.status in (-6, -11)
    ):
        found.append("over memory")
    if run.status not in (0, 1, 2) and not found:
        found.append(f"exit {run.status}")
    if run.status in (1, 2) and not (err.startswith("scanconv: error: ") and err.count("\n") == 1):
        found.append("not one line")
    if run.status == 2 and stdout_size:
        found.append("stdout with exit 2")
    return found


def plan(rng: random.Random, argvs: int, questions: int, scratch: Path) -> list[Run]:
    """Every run to do (the question files and students' tables are written here)."""
    found = commands()
    runs: list[Run] = []
    for i in range(argvs):
        path, command = found[i % len(found)]
        vocab = VOCABULARY[path]
        argv = place_files(mutate(rng, command, vocab), set(file_options(command)), scratch, i)
        runs.append(Run([*path, *argv], "argv"))
    pool = [(p, c, VOCABULARY[p]) for p, c in found if p[0] not in NOT_QUESTIONS]
    for i in range(questions):
        text = question_file(rng, pool)
        qfile = scratch / f"q{i}.questions"
        qfile.write_text(text, encoding="utf-8", errors="surrogatepass")
        sheet = ["sheet", str(qfile), "-f", rng.choice(FORMATS)]
        if rng.random() < 0.4:
            sheet.append("--worksheet")
        if rng.random() < 0.2:
            sheet += ["-o", str(scratch / f"sheet{i}.out")]
        runs.append(Run(sheet, "sheet"))
        lines = [
            ln
            for ln in text.splitlines()
            if ln and not ln.startswith(("#", ">", "title:", "section:"))
        ] or ["line 2 2 10 6"]
        chosen = rng.choice(lines)
        if chosen.startswith("["):
            chosen = chosen.partition("]")[2]
        try:
            asked = shlex.split(chosen.partition("   #")[0])
        except ValueError:
            asked = chosen.split()
        student = student_table(rng, scratch, i)
        check = ["check", str(student), "--", *asked, "-f", rng.choice(FORMATS)]
        runs.append(Run(check, "check"))
    return runs


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--argv", type=int, default=2000)
    parser.add_argument("--questions", type=int, default=500)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--memory", type=int, default=2**30)
    parser.add_argument("--json", type=Path)
    parser.add_argument(
        "--exec",
        action="store_true",
        help="run each as timeout/prlimit/python -m scanconv (slower: a fresh interpreter each)",
    )
    args = parser.parse_args()
    rng = random.Random(args.seed)
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="scanconv-fuzz-") as tmp:
        scratch = Path(tmp)
        runs = plan(rng, args.argv, args.questions, scratch)
        done: list[Run] = []
        forkers: list[Forker] = []
        local = threading.local()

        def one(run: Run) -> Run:
            if args.exec:
                return run_one(run, scratch, args.timeout, args.memory)
            if not hasattr(local, "forker"):
                local.forker = Forker()
                forkers.append(local.forker)
            return run_one(run, scratch, args.timeout, args.memory, local.forker)

        with ThreadPoolExecutor(args.jobs) as pool:
            for n, run in enumerate(pool.map(one, runs), 1):
                done.append(run)
                if run.problems:
                    print(f"FAIL {run.problems} {shlex.join(['scanconv', *run.argv])[:300]}")
                    last = run.err.strip().splitlines()[-1][:200] if run.err.strip() else ""
                    print(
                        f"     exit {run.status}, {run.seconds:.1f} s, {run.cpu:.1f} s CPU: {last}"
                    )
                    sys.stdout.flush()
                if n % 100 == 0:
                    print(f"... {n}/{len(runs)} runs", file=sys.stderr, flush=True)
        for forker in forkers:
            forker.close()
    failed = [r for r in done if r.problems]
    counts = Counter(p for r in failed for p in r.problems)
    kinds = Counter(r.kind for r in done)
    statuses = Counter((r.kind, r.status) for r in done)
    slowest = max(done, key=lambda r: r.seconds)
    biggest = max(done, key=lambda r: r.peak_mib)
    summary = {
        "runs": dict(kinds),
        "commands": len(commands()),
        "exit statuses": {f"{k} {s}": n for (k, s), n in sorted(statuses.items())},
        "tracebacks": counts["traceback"],
        "over time": counts["over time"],
        "over memory": counts["over memory"],
        "other contract breaks": sum(
            1 for r in failed if not {"traceback", "over time", "over memory"} & set(r.problems)
        ),
        "slowest run": [
            round(slowest.seconds, 1),
            round(slowest.cpu, 1),
            shlex.join(slowest.argv)[:200],
        ],
        "largest peak (MiB)": [round(biggest.peak_mib), shlex.join(biggest.argv)[:200]],
        "wall (s)": round(time.monotonic() - started),
        "seed": args.seed,
        "limits": f"timeout {args.timeout:g} s, address space {args.memory} bytes",
        "runner": "exec (timeout, prlimit)" if args.exec else "fork (SIGTERM, RLIMIT_AS)",
        "self peak (MiB)": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024),
    }
    print(json.dumps(summary, indent=2, ensure_ascii=False))
    if args.json:
        args.json.write_text(
            json.dumps({"summary": summary, "failed": [asdict(r) for r in failed]}, indent=1)
        )
    return min(len(failed), 255)


if __name__ == "__main__":
    sys.exit(main())
