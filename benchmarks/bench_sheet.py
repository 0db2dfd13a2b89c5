"""A 200-question answer key in one process against 200 separate ``scanconv`` runs:
``python benchmarks/bench_sheet.py`` (issue 15: the sheet must take under 10 % of the time).

The questions are a seeded exam-difficulty practice set of every topic
(:func:`scanconv.practice.notes.practice`, ``--seed 1``). Both sides are real processes
started the same way (``python -m scanconv``) and write the same Markdown answers: the sheet
``scanconv sheet Q --format markdown -o key.md`` once, the loop ``scanconv ARGS --format
markdown`` once per question (stdout to a file, as a shell loop would). Wall time, median of
``--repeat`` runs of the sheet and of ``--loops`` runs of the loop; prints one Markdown table.
Benchmarks never run in the tests.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from scanconv.practice.notes import practice, question_file

SCANCONV = [sys.executable, "-m", "scanconv"]


def _timed(argvs: list[list[str]], out: Path) -> float:
    start = time.perf_counter()
    for argv in argvs:
        with open(out, "w", encoding="utf-8") as f:
            subprocess.run([*SCANCONV, *argv], stdout=f, check=True)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--repeat", type=int, default=5, help="runs of the sheet")
    parser.add_argument("--loops", type=int, default=1, help="runs of the separate loop")
    args = parser.parse_args()
    questions = practice("all", args.count, seed=1, difficulty="exam")
    with tempfile.TemporaryDirectory() as tmp:
        qfile = Path(tmp) / "questions.txt"
        qfile.write_text(question_file(questions, "Benchmark"), encoding="utf-8")
        key, out = Path(tmp) / "key.md", Path(tmp) / "one.md"
        sheet = [["sheet", str(qfile), "--format", "markdown", "-o", str(key)]]
        _timed(sheet, key)  # warm the file cache
        one = statistics.median(_timed(sheet, key) for _ in range(args.repeat))
        loop_argvs = [[*q.argv, "--format", "markdown"] for q in questions]
        many = statistics.median(_timed(loop_argvs, out) for _ in range(args.loops))
    print(f"| {args.count} questions | wall time (s) | share |")
    print("|---|---:|---:|")
    print(f"| `scanconv sheet` (one process) | {one:.2f} | {100 * one / many:.1f} % |")
    print(f"| {args.count} separate `scanconv` runs | {many:.2f} | 100 % |")


if __name__ == "__main__":
    main()
