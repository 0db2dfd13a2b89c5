"""The coverage floor of the README's test command: read SlipCover's JSON report, print the
total and the least covered modules, and fail under the floor.

    python -m slipcover --source scanconv --json --out .coverage.json -m pytest -n auto
    python tests/coverage_floor.py .coverage.json 90

SlipCover (not coverage.py's tracer) measures the suite: on Python 3.11 coverage.py calls a
C trace function on every line of every frame, which made the suite's in-process CLI runs 2.6
times as costly; SlipCover instruments scanconv's bytecode and removes each probe once its line
has run (docs/development.md#coverage). ``pytest --cov`` (pytest-cov, with its ``no_cover``
marks) still works for an HTML report.

Exit status: 0 at or above the floor, 1 under it, 2 for a missing or unreadable report (a run
that stopped before SlipCover wrote it).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

SHOWN = 8
"""How many of the least covered modules are listed."""


def report(data: dict, floor: float) -> tuple[str, bool]:
    """The report's text and whether the total reaches ``floor`` (a percentage).

    >>> text, ok = report({"summary": {"covered_lines": 9, "missing_lines": 1},
    ...                    "files": {"a.py": {"summary": {"covered_lines": 9,
    ...                    "missing_lines": 1}, "missing_lines": [7]}}}, 90)
    >>> ok, text.splitlines()[0]
    (True, 'coverage: 90.00 % of 10 lines of scanconv (floor 90 %)')
    """
    summary = data["summary"]
    total, percent = summary["covered_lines"] + summary["missing_lines"], _percent(summary)
    lines = [f"coverage: {percent:.2f} % of {total:,} lines of scanconv (floor {floor:g} %)"]
    files = data["files"]
    worst = sorted(
        (f for f in files if files[f]["summary"]["missing_lines"]),
        key=lambda f: (_percent(files[f]["summary"]), f),
    )[:SHOWN]
    if worst:
        lines.append("least covered:")
    for name in worst:
        s = files[name]["summary"]
        missed = ", ".join(map(str, files[name]["missing_lines"][:12]))
        more = " ..." if len(files[name]["missing_lines"]) > 12 else ""
        lines.append(f"  {_percent(s):6.2f} %  {name}  (missing {missed}{more})")
    return "\n".join(lines) + "\n", percent >= floor


def _percent(summary: dict) -> float:
    total = summary["covered_lines"] + summary["missing_lines"]
    return 100.0 * summary["covered_lines"] / total if total else 100.0


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        print("usage: python tests/coverage_floor.py REPORT.json FLOOR", file=sys.stderr)
        return 2
    path, floor = Path(argv[0]), float(argv[1])
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as err:
        print(f"coverage_floor: no coverage report: {err}", file=sys.stderr)
        return 2
    text, ok = report(data, floor)
    sys.stdout.write(text)
    if not ok:
        print(f"coverage_floor: under the floor of {floor:g} %", file=sys.stderr)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
