"""The long fuzz: random command lines and random question files, each run a limited process.

``python benchmarks/fuzz.py`` (about half an hour on 2 cores; ``--argv 200 --questions 50``
for a smoke run) draws

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

Every run is a process under ``timeout 60`` and ``prlimit --as`` (1 GiB of address space),
in a scratch folder. The report counts the runs that printed a traceback, ran over the time
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


def question(rng: random.Random, pool: list[tuple[tuple[str, ...], Any, Vocab]]) -> str:
    path, command, vocab = rng.choice(pool)
    argv = mutate(rng, command, vocab) if rng.random() < 0.3 else list(rng.choice(vocab.valid))
    argv = [a for a in argv if a != "FILE"]
    text = " ".join(shlex.quote(a) for a in (*path, *argv))
    if rng.random() < 0.4:
        text = f"[{rng.choice(('1', '2', '4', '10', '0', '-1', '1.5', '99999'))}] {text}"
    if rng.random() < 0.1:
        text += "   # " + _junk(rng)
    return text


def question_file(rng: random.Random, pool: list[tuple[tuple[str, ...], Any, Vocab]]) -> str:
    lines: list[str] = []
    if rng.random() < 0.5:
        lines.append("title: " + " ".join(_junk(rng) for _ in range(rng.randrange(1, 5))))
    for _ in range(rng.randrange(1, 16)):
        roll = rng.random()
        if roll < 0.8:
            lines.append(question(rng, pool))
        elif roll < 0.86:
            lines.append("section: " + _junk(rng))
        elif roll < 0.93:
            lines.append("> " + " ".join(_junk(rng) for _ in range(rng.randrange(1, 6))))
        elif roll < 0.97:
            lines.append("# " + _junk(rng))
        else:
            lines.append(_junk(rng))
    roll = rng.random()
    if roll < 0.03:  # many large questions: the sheet's total budget
        lines += ["line 0 0 9999 1"] * rng.choice((50, 200, 1000))
    elif roll < 0.05:
        lines.append("line 0 0 " + "1" * rng.randrange(5, 400) + " 1")
    elif roll < 0.07:
        lines.append("x" * rng.choice((10_000, 1_000_000)))
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


def _limits(memory: int) -> list[str]:
    return ["prlimit", f"--as={memory}", "--"]


def run_one(
    run: Run, directory: Path, timeout: float, memory: int, stdin: bytes | None = None
) -> Run:
    """``run.argv`` as ``timeout T prlimit --as=M python -m scanconv ...`` in ``directory``."""
    command = [
        "timeout",
        "-k",
        "10",
        f"{timeout:g}",
        *_limits(memory),
        sys.executable,
        "-m",
        "scanconv",
        *run.argv,
    ]
    env = {**os.environ, "NO_COLOR": "1", "PYTHONDONTWRITEBYTECODE": "1", "COLUMNS": "100"}
    with tempfile.TemporaryFile(dir=directory) as out, tempfile.TemporaryFile(dir=directory) as err:
        start = time.monotonic()
        proc = subprocess.Popen(
            command,
            stdin=subprocess.PIPE if stdin is not None else subprocess.DEVNULL,
            stdout=out,
            stderr=err,
            cwd=directory,
            env=env,
        )
        if stdin is not None:
            assert proc.stdin is not None
            proc.stdin.write(stdin)
            proc.stdin.close()
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
        run.seconds = time.monotonic() - start
        run.cpu = usage.ru_utime + usage.ru_stime
        run.peak_mib = usage.ru_maxrss / 1024
        run.status = proc.returncode
        size = out.tell()
        err.seek(0)
        run.err = err.read(20_000).decode("utf-8", "replace")
    run.problems = problems(run, size)
    return run


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


def plan(rng: random.Random, argvs: int, questions: int, scratch: Path) -> list[tuple[Run, Any]]:
    """Every run to do, with its stdin (None) — the question files are written here."""
    found = commands()
    runs: list[tuple[Run, Any]] = []
    for i in range(argvs):
        path, command = found[i % len(found)]
        vocab = VOCABULARY[path]
        argv = place_files(mutate(rng, command, vocab), set(file_options(command)), scratch, i)
        runs.append((Run([*path, *argv], "argv"), None))
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
        runs.append((Run(sheet, "sheet"), None))
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
        runs.append((Run(check, "check"), None))
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
    args = parser.parse_args()
    rng = random.Random(args.seed)
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="scanconv-fuzz-") as tmp:
        scratch = Path(tmp)
        runs = plan(rng, args.argv, args.questions, scratch)
        done: list[Run] = []
        with ThreadPoolExecutor(args.jobs) as pool:
            futures = [
                pool.submit(run_one, r, scratch, args.timeout, args.memory, stdin)
                for r, stdin in runs
            ]
            for n, future in enumerate(futures, 1):
                run = future.result()
                done.append(run)
                if run.problems:
                    print(f"FAIL {run.problems} {shlex.join(['scanconv', *run.argv])[:300]}")
                    print("     " + run.err.strip().splitlines()[-1][:200] if run.err else "")
                if n % 100 == 0:
                    print(f"... {n}/{len(futures)} runs", file=sys.stderr, flush=True)
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
        "limits": f"timeout {args.timeout:g} s, prlimit --as={args.memory}",
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
