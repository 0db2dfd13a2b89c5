"""The third attack's reproducing commands (``../shared/reference/attack-report.md``), each
run as a process with its time and memory measured, against the bound issue 38 sets: refused
(exit 2, one line) in under 2 s, or ended within 60 s of CPU and 1 GB.

``python benchmarks/attack_repro.py`` (a few minutes on 2 quiet cores) prints a Markdown table:
defect, command, exit status, wall and CPU seconds, peak memory, and whether it kept its
bound; the exit status is the number of commands that did not. Each run has a scratch folder
of its own (the setup lines of a case run there first), ``timeout 120`` and an address-space
limit of 4 GB, so that a regression is measured, not waited for.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from typing import NamedTuple

PY = sys.executable
SCANCONV = f"{PY} -m scanconv"
LINES_1000 = f"{PY} -c \"print('\\n'.join('line 0 0 79 %d' % (i%40+1) for i in range(1000)))\""


class Case(NamedTuple):
    defect: str
    command: str
    setup: str = ""
    bound: str = "refused"  # "refused": exit 2 within 2 s; "ends": exit 0 within 60 s, 1 GB
    check: str = ""  # a shell test run afterwards in the folder (exit 0: the files are right)


CASES = (
    Case(
        "N1",
        f"{SCANCONV} transform 123456 654321 --rotate 37 --translate 1000000 2000000 -f latex",
        bound="ends",
    ),
    Case(
        "N1",
        f"{SCANCONV} sheet qt.txt -o key.tex",
        "printf 'transform 123456 654321 --rotate 37 --translate 1000000 2000000\\n' > qt.txt",
        "ends",
        "test -s key.tex",
    ),
    Case(
        "N1",
        f"{SCANCONV} check --batch cr -f latex -o s.tex -- line 2 2 10 6",
        "mkdir cr; printf 'k,p_k,x,y\\n0,0,2,2\\n' > cr/$(printf '0%.0s' $(seq 32)).csv",
        "ends",
        "test -s s.tex",
    ),
    Case(
        "N2",
        f'{PY} -c "from scanconv.site import page; import json; '
        "r = json.loads(page.answer('circle 2800000')); print(r['ok'], r.get('error'))\"",
        bound="ends-fast",
    ),
    Case(
        "N3",
        f"{SCANCONV} site build proj",
        "mkdir proj; echo '{}' > proj/site.json; echo thesis > proj/thesis.tex",
        check="test -f proj/thesis.tex",
    ),
    Case(
        "N4",
        f"{SCANCONV} check --batch cb -o cb/a.csv -- line 2 2 10 6",
        "mkdir cb; printf 'k,p_k,x,y\\n0,0,2,2\\n' > cb/a.csv",
        check="grep -q '^0,0,2,2' cb/a.csv",
    ),
    Case(
        "N5",
        f"{SCANCONV} bezier 0 0 1 2 999999999 999999999 1000000 0 --at 1/2 -f html -o b.html",
        bound="ends",
        check="test $(stat -c %s b.html) -lt 5000000",
    ),
    Case(
        "N5",
        f"{SCANCONV} bezier -1000000000 -1000000000 1000000000 1000000000 -1000000000 "
        "1000000000 --at 1/2 -f html -o x.html",
        bound="ends",
    ),
    Case("N6", f"{SCANCONV} sheet g1000.txt -o g1000.gift", f"{LINES_1000} > g1000.txt"),
    Case(
        "N7",
        f"{SCANCONV} thickline 0 0 1999999 1 --width 2 -f csv -o t.csv",
        bound="ends",
    ),
    Case(
        "N7",
        f"{SCANCONV} sample 'x + y' --size 4096 -L 256 -f csv -o s.csv",
        bound="ends",
    ),
    Case(
        "N8",
        f'{PY} -c "from scanconv import questions\n'
        "try: questions.answer('polygon ' + '0 0 1 0 ' * 50000)\n"
        'except ValueError as e: print(e)"',
        bound="ends-fast",
    ),
    Case(
        "N8",
        f'{PY} -c "from scanconv import questions\n'
        "try: questions.read_questions(chr(13) * 10**7 + 'circle 2')\n"
        'except ValueError as e: print(str(e)[:80])"',
        bound="ends-fast",
    ),
    Case("N9", f"{SCANCONV} line 2 2 10 6 -o f.svg --svg f.svg"),
    Case(
        "N10",
        f"{SCANCONV} site build .",
        "echo '{}' > site.json",
        check="! ls -a .. | grep -q '\\.old'",
    ),
    Case("N11", f"{SCANCONV} sheet ff", "mkfifo ff"),
    Case("N13", f"{SCANCONV} exam -s -1"),
    Case("N15", f"{SCANCONV} sheet p1000.txt --pdf p.pdf -o p.md", f"{LINES_1000} > p1000.txt"),
    Case(
        "D16",
        f"{SCANCONV} check big.json -- line 2 2 10 6",
        f'{PY} -c "print(\'{{\\"steps\\": [{{\\"k\\": 0, \\"p\\": \' + \'9\' * 5000 + \'}}]}}\')" > big.json',
    ),
)


class Measured(NamedTuple):
    code: int
    wall: float
    cpu: float
    rss_mb: float
    err: str
    checked: bool


def measure(case: Case, folder: str) -> Measured:
    if case.setup:
        subprocess.run(case.setup, shell=True, cwd=folder, check=True)
    script = f"prlimit --as=4000000000 timeout 120 {case.command}"
    started = time.perf_counter()
    before = os.times()
    proc = subprocess.run(
        ["/usr/bin/time", "-f", "%M", "bash", "-c", script],
        cwd=folder,
        capture_output=True,
        text=True,
    )
    wall = time.perf_counter() - started
    after = os.times()
    cpu = (after.children_user - before.children_user) + (
        after.children_system - before.children_system
    )
    lines = proc.stderr.strip().splitlines()
    rss = float(lines[-1]) / 1024 if lines and lines[-1].isdigit() else 0.0
    err = " ".join(lines[:-1])[:140]
    ok = True
    if case.check:
        ok = subprocess.run(case.check, shell=True, cwd=folder).returncode == 0
    return Measured(proc.returncode, wall, cpu, rss, err, ok)


def kept(case: Case, m: Measured) -> bool:
    if not m.checked or m.rss_mb > 1000:
        return False
    if case.bound == "refused":
        return m.code == 2 and m.wall < 2 and m.err.count("scanconv: error:") == 1
    if case.bound == "ends-fast":
        return m.code == 0 and m.wall < 2
    return m.code == 0 and m.cpu < 60


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-k", default="", help="only the defects whose name contains this")
    args = parser.parse_args()
    print("| defect | command | exit | wall s | CPU s | peak MB | bound | kept |")
    print("|---|---|--:|--:|--:|--:|---|---|")
    failed = 0
    for case in CASES:
        if args.k not in case.defect:
            continue
        with tempfile.TemporaryDirectory() as top:
            folder = os.path.join(top, "work")
            os.mkdir(folder)
            m = measure(case, folder)
            shutil.rmtree(folder, ignore_errors=True)
        ok = kept(case, m)
        failed += not ok
        shown = case.command.replace(PY, "python").replace("\n", "; ")[:90]
        print(
            f"| {case.defect} | `{shown}` | {m.code} | {m.wall:.2f} | {m.cpu:.2f} | "
            f"{m.rss_mb:.0f} | {case.bound} | {'yes' if ok else 'NO: ' + m.err[:60]} |",
            flush=True,
        )
    return failed


if __name__ == "__main__":
    sys.exit(main())
