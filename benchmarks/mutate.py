"""Mutation testing of the modules that produce numbers, marks and escapes:
``nice -n 10 python benchmarks/mutate.py`` (about 45 minutes on one core; see
docs/development.md, "Mutation testing").

Each target module is parsed with :mod:`ast` and its first-order mutants are listed by
operator: a comparison flipped (``<`` and ``<=``, ``>`` and ``>=``, ``==`` and ``!=``, ``is``
and ``is not``, ``in`` and ``not in``), ``+`` and ``-`` swapped, an integer constant moved by
one where it bounds or offsets something (a ``range`` bound, a slice, ``n + 1``, a compared
value), ``and`` and ``or`` swapped, a ``not`` or a unary minus dropped; in the escapers an
escaping call dropped (``esc(c)`` becomes ``c``, ``pattern.sub(r, t)`` becomes ``t``,
``t.replace(a, b)`` becomes ``t``), a character removed from a string of a regex or a table
and an entry removed from an escape table. Docstrings, f-strings and ``raise`` statements are
never mutated. The mutants of a module are sampled deterministically (``--seed``, at most
``--cap`` a module), so two runs on the same source try the same mutants.

Every mutant is written over one temporary copy of the tree (never the worktree's files), its
file given a modification time of its own so no stale compiled file is read, and the module's
tests are run there, one mutant at a time: the module's doctests and its test files
(:data:`TARGETS`), then, if those pass, ``tests/test_golden.py -k TOPIC``, each with
``pytest -x -q -p no:cacheprovider -n 0`` under ``HYPOTHESIS_PROFILE=dev``, within
``--timeout`` seconds (120) and :data:`MEMORY` (a timeout counts as killed, reported apart).
A mutant survives when both runs pass. Mutants proved equivalent (:data:`EQUIVALENT`, each
with its proof) are run all the same but left out of the ratio and listed. The mutation
report's hand-made survivors (:data:`REPORT`) are run beside the sampled mutants.

Writes ``--out`` (default ``benchmarks/mutation-report``) ``.json`` and ``.md``: per module
the mutants tried, killed, timed out, survived and equivalent, and each survivor's
``file:line`` and mutation. ``--list`` prints the sampled mutants without running them;
``--only ID`` (repeatable) runs just those; ``--rerun REPORT.json`` keeps that report's killed
and runs the rest (after tests were added), writing a report of them all. The targets, the
report's mutations and the equivalents are in ``benchmarks/mutation_targets.py``.
"""

from __future__ import annotations

import argparse
import ast
import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import asdict, dataclass
from pathlib import Path

from mutation_targets import EQUIVALENT, ESCAPING_CALLS, REPORT, TARGETS, Target

ROOT = Path(__file__).resolve().parent.parent


def report_mutants(modules: list[str]) -> list[Mutant]:
    """The report's mutations (:data:`REPORT`) of ``modules`` as mutants (id ``report:ID``)."""
    out = []
    for name, path, old, new in REPORT:
        if path not in modules:
            continue
        source = (ROOT / path).read_text()
        if source.count(old) != 1:
            raise SystemExit(f"mutate.py: {name}: {old!r} is not once in {path}")
        at = source.index(old)
        line = source.count("\n", 0, at) + 1
        col = len(source[source.rfind("\n", 0, at) + 1 : at].encode())
        end_line = line + old.count("\n")
        last = old.rsplit("\n", 1)[-1]
        end_col = len(last.encode()) + (col if end_line == line else 0)
        out.append(
            Mutant(path, line, col, end_line, end_col, "report", old, new, id=f"report:{name}")
        )
    return out


_FLIP: dict[type, type] = {
    ast.Lt: ast.LtE,
    ast.LtE: ast.Lt,
    ast.Gt: ast.GtE,
    ast.GtE: ast.Gt,
    ast.Eq: ast.NotEq,
    ast.NotEq: ast.Eq,
    ast.Is: ast.IsNot,
    ast.IsNot: ast.Is,
    ast.In: ast.NotIn,
    ast.NotIn: ast.In,
}


@dataclass
class Mutant:
    """One first-order mutant: a source segment of ``path`` replaced."""

    path: str
    line: int
    col: int
    end_line: int
    end_col: int
    kind: str  # compare, arith, constant, bool, not, neg, call, string, entry
    old: str
    new: str
    id: str = ""
    label: str = ""
    status: str = ""  # killed, timeout, survived, equivalent (survived, proved equivalent)
    seconds: float = 0.0
    killed_by: str = ""
    reason: str = ""

    def describe(self) -> str:
        if self.label:
            return self.label
        return f"`{_short(self.old)}` → `{_short(self.new)}`"


def _short(text: str, width: int = 90) -> str:
    one = " ".join(text.split())
    return one if len(one) <= width else one[: width - 1] + "…"


def _parents(tree: ast.AST) -> dict[ast.AST, ast.AST]:
    up: dict[ast.AST, ast.AST] = {}
    for node in ast.walk(tree):
        for child in ast.iter_child_nodes(node):
            up[child] = node
    return up


def _skipped(node: ast.AST, up: dict[ast.AST, ast.AST]) -> bool:
    """Docstrings, f-strings, raise statements, annotations and ``TYPE_CHECKING`` blocks."""
    child, node = node, up.get(node)
    while node is not None:
        if isinstance(node, (ast.JoinedStr, ast.Raise, ast.Assert)):
            return True
        if isinstance(node, ast.AnnAssign) and child is node.annotation:
            return True
        if isinstance(node, ast.arg) or (
            isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and child is node.returns
        ):
            return True
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            return True
        child, node = node, up.get(node)
    return False


def _raised(node: ast.AST, up: dict[ast.AST, ast.AST]) -> bool:
    while node is not None:
        if isinstance(node, (ast.Raise, ast.Assert)):
            return True
        node = up.get(node)
    return False


def _owner(node: ast.AST, up: dict[ast.AST, ast.AST]) -> str:
    """The outermost function or module-level assignment target around ``node``."""
    name = ""
    while node is not None:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            name = node.name
        elif isinstance(node, (ast.Assign, ast.AnnAssign)) and isinstance(up.get(node), ast.Module):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            name = next((t.id for t in targets if isinstance(t, ast.Name)), name)
        node = up.get(node)
    return name


def _is_docstring(node: ast.AST, up: dict[ast.AST, ast.AST]) -> bool:
    parent = up.get(node)
    return isinstance(parent, ast.Expr) and isinstance(node, ast.Constant)


def _call_name(call: ast.Call) -> str:
    f = call.func
    return f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""


def _int_matters(node: ast.Constant, up: dict[ast.AST, ast.AST]) -> bool:
    """An int bounding a range, a slice, an offset (``n + 1``), a compared value or an index."""
    parent = up.get(node)
    if isinstance(parent, ast.Call) and _call_name(parent) == "range":
        return True
    if isinstance(parent, ast.Slice):
        return True
    if isinstance(parent, ast.BinOp) and isinstance(parent.op, (ast.Add, ast.Sub)):
        return True
    if isinstance(parent, ast.Compare):
        return True
    return isinstance(parent, ast.Subscript) and parent.slice is node


def _regex_ok(pattern: str) -> bool:
    try:
        re.compile(pattern)
    except re.error:
        return False
    return True


def _string_mutants(node: ast.Constant, up: dict[ast.AST, ast.AST]) -> list[str]:
    """A character removed from a regex's or an escaper's string (each position that keeps a
    regex compilable); an empty string is not mutated."""
    s = node.value
    assert isinstance(s, str)
    parent = up.get(node)
    is_regex = isinstance(parent, ast.Call) and _call_name(parent) == "compile"
    out = []
    for i in range(len(s)):
        new = s[:i] + s[i + 1 :]
        if new == s or (is_regex and not _regex_ok(new)):
            continue
        if new not in out:
            out.append(new)
    return out


def _segment(lines: list[bytes], node: ast.AST) -> str:
    """The source text of ``node`` (offsets are UTF-8 bytes)."""
    l0, c0 = node.lineno - 1, node.col_offset  # type: ignore[attr-defined]
    l1, c1 = node.end_lineno - 1, node.end_col_offset  # type: ignore[attr-defined]
    if l0 == l1:
        return lines[l0][c0:c1].decode()
    parts = [lines[l0][c0:], *lines[l0 + 1 : l1], lines[l1][:c1]]
    return b"".join(parts).decode()


def candidates(path: str, target: Target) -> list[Mutant]:
    """Every first-order mutant of ``path`` that the target's filters allow, in source order."""
    source = (ROOT / path).read_text()
    tree = ast.parse(source)
    up = _parents(tree)
    lines = source.encode().splitlines(keepends=True)
    out: list[Mutant] = []

    def add(node: ast.AST, kind: str, new: str, label: str = "") -> None:
        old = _segment(lines, node)
        if new == old:
            return
        out.append(
            Mutant(
                path,
                node.lineno,  # type: ignore[attr-defined]
                node.col_offset,  # type: ignore[attr-defined]
                node.end_lineno,  # type: ignore[attr-defined]
                node.end_col_offset,  # type: ignore[attr-defined]
                kind,
                old,
                new,
                label=label,
            )
        )

    def replaced(node: ast.AST, make) -> str:
        copy = ast.parse(ast.unparse(node), mode="eval").body
        return "(" + ast.unparse(make(copy)) + ")"

    for node in ast.walk(tree):
        if not hasattr(node, "lineno"):
            continue
        if _skipped(node, up):
            # an escaping call inside an f-string is still dropped (html.py's ``{esc(title)}``)
            if not (target.escaper and isinstance(node, ast.Call) and not _raised(node, up)):
                continue
            if not _segment(lines, node).startswith(_call_name(node) + "("):
                continue
        if target.only and _owner(node, up) not in target.only:
            continue
        found: list[tuple[str, ...]] = []
        if isinstance(node, ast.Compare):
            for i, op in enumerate(node.ops):
                if type(op) in _FLIP:

                    def flip(c, i=i, op=op):
                        c.ops[i] = _FLIP[type(op)]()
                        return c

                    found.append(("compare", replaced(node, flip)))
        elif isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)):
            strings = any(
                isinstance(s, ast.JoinedStr)
                or (isinstance(s, ast.Constant) and isinstance(s.value, str))
                for s in (node.left, node.right)
            )
            if not strings:

                def swap(b):
                    b.op = ast.Sub() if isinstance(b.op, ast.Add) else ast.Add()
                    return b

                found.append(("arith", replaced(node, swap)))
        elif isinstance(node, ast.BoolOp):

            def other(b):
                b.op = ast.Or() if isinstance(b.op, ast.And) else ast.And()
                return b

            found.append(("bool", replaced(node, other)))
        elif isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.Not, ast.USub)):
            if not (isinstance(node.op, ast.USub) and isinstance(node.operand, ast.Constant)):
                kind = "not" if isinstance(node.op, ast.Not) else "neg"
                found.append((kind, "(" + _segment(lines, node.operand) + ")"))
        elif isinstance(node, ast.Constant) and type(node.value) is int and _int_matters(node, up):
            found += [("constant", str(node.value + 1)), ("constant", str(node.value - 1))]
        elif target.escaper and isinstance(node, ast.Call):
            name = _call_name(node)
            if name in ESCAPING_CALLS and len(node.args) == 1 and not node.keywords:
                found.append(("call", "(" + _segment(lines, node.args[0]) + ")"))
            elif name == "sub" and len(node.args) == 2 and isinstance(node.func, ast.Attribute):
                found.append(("call", "(" + _segment(lines, node.args[1]) + ")"))
            elif name == "replace" and len(node.args) == 2 and isinstance(node.func, ast.Attribute):
                found.append(("call", "(" + _segment(lines, node.func.value) + ")"))
        elif (
            target.escaper
            and isinstance(node, ast.Constant)
            and isinstance(node.value, str)
            and not _is_docstring(node, up)
            and len(node.value) <= 40
        ):
            # one character removed a string, its position chosen by the string's own text
            removals = _string_mutants(node, up)
            if removals:
                pick = random.Random(f"{node.value}:{node.lineno}").choice(removals)
                found.append(("string", repr(pick)))
        elif target.escaper and isinstance(node, ast.Dict) and len(node.keys) > 1:
            for i in range(len(node.keys)):

                def drop(d, i=i):
                    del d.keys[i], d.values[i]
                    return d

                key = node.keys[i]
                label = f"{{…}} without {_segment(lines, key)}" if key is not None else ""
                found.append(("entry", replaced(node, drop), label))
        for kind, new, *label in found:
            if not target.kinds or kind in target.kinds:
                add(node, kind, new, *label)
    out.sort(key=lambda m: (m.line, m.col, m.kind, m.new))
    for n, m in enumerate(out):
        m.id = f"{Path(path).stem}:{m.line}:{m.col}:{m.kind}:{n}"
    return out


def sample(path: str, target: Target, cap: int, seed: int) -> tuple[int, list[Mutant]]:
    """How many candidates there are, and at most ``cap`` of them, chosen by ``seed``."""
    every = candidates(path, target)
    rng = random.Random(f"{seed}:{path}")
    chosen = every if len(every) <= cap else rng.sample(every, cap)
    chosen.sort(key=lambda m: (m.line, m.col))
    return len(every), chosen


def apply(source: str, m: Mutant) -> str:
    """``source`` with the mutant's segment replaced."""
    lines = source.encode().splitlines(keepends=True)
    head = b"".join(lines[: m.line - 1]) + lines[m.line - 1][: m.col]
    tail = lines[m.end_line - 1][m.end_col :] + b"".join(lines[m.end_line :])
    new = head + m.new.encode() + tail
    text = new.decode()
    ast.parse(text)  # a mutant is always valid Python
    return text


def copy_tree(dest: Path) -> None:
    ignore = shutil.ignore_patterns(
        ".git", ".venv", "__pycache__", ".hypothesis", "*.egg-info", ".mypy_cache", ".ruff_cache"
    )
    for item in ROOT.iterdir():
        if item.name in {".git", ".venv", ".hypothesis", ".mypy_cache", ".ruff_cache"}:
            continue
        if item.name.endswith(".egg-info"):
            continue
        if item.is_dir():
            shutil.copytree(item, dest / item.name, ignore=ignore, symlinks=True)
        else:
            shutil.copy2(item, dest / item.name)


#: Bytes of address space a test run may use: a mutant that loops while allocating (one made
#: a circle's octant never end) fails at this limit instead of filling the machine's memory.
MEMORY = 4 * 2**30


def _limit() -> None:  # pragma: no cover - runs in the child before pytest
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (MEMORY, MEMORY))


def pytest_run(tree: Path, args: list[str], timeout: float) -> tuple[str, float, str]:
    """``(outcome, seconds, first failure)``: outcome is passed, failed or timeout."""
    env = dict(os.environ, PYTHONPATH=str(tree), HYPOTHESIS_PROFILE="dev")
    cmd = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider", "-n", "0"]
    start = time.monotonic()
    proc = subprocess.Popen(
        [*cmd, *args],
        cwd=tree,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        start_new_session=True,
        preexec_fn=_limit,
    )
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return "timeout", time.monotonic() - start, ""
    seconds = time.monotonic() - start
    if proc.returncode == 0:
        return "passed", seconds, ""
    if proc.returncode == 5:
        return "empty", seconds, ""
    first = next((ln for ln in out.splitlines() if ln.startswith(("FAILED", "ERROR"))), "")
    return "failed", seconds, first or out.strip().splitlines()[-1:][0] if out.strip() else ""


def runs(path: str, target: Target) -> list[list[str]]:
    """The pytest runs of a module: its doctests and test files, then its golden topic."""
    tests = [t for t in target.tests if (ROOT / t).exists()]
    first = [path, *tests]
    return [first, ["tests/test_golden.py", "-k", target.golden]] if target.golden else [first]


def run_mutant(tree: Path, m: Mutant, target: Target, timeout: float) -> None:
    file = tree / m.path
    original = file.read_text()
    stat = file.stat()
    file.write_text(apply(original, m))
    # a modification time of its own: no compiled file of another version is ever read
    stamp = stat.st_mtime + 1000 + (hash(m.id) % 100000)
    os.utime(file, (stamp, stamp))
    shutil.rmtree(tree / ".hypothesis", ignore_errors=True)
    try:
        m.seconds = 0.0
        for args in runs(m.path, target):
            outcome, seconds, first = pytest_run(tree, args, timeout)
            m.seconds += seconds
            if outcome == "timeout":
                m.status = "timeout"
                return
            if outcome == "failed":
                m.status, m.killed_by = "killed", first
                return
        m.status = "survived"
    finally:
        file.write_text(original)
        os.utime(file, (stat.st_mtime, stat.st_mtime))
    for (path, where, new), why in EQUIVALENT.items():
        if m.status == "survived" and path == m.path and where in _context(m) and new == m.new:
            m.status, m.reason = "equivalent", why


def _context(m: Mutant) -> str:
    """The mutant's line and the two after it, each stripped, the mutated text in ⟦ ⟧ (how
    :data:`EQUIVALENT` names a mutant)."""
    lines = (ROOT / m.path).read_bytes().splitlines()
    first = lines[m.line - 1]
    if m.end_line == m.line:
        first = (
            first[: m.col]
            + "⟦".encode()
            + first[m.col : m.end_col]
            + "⟧".encode()
            + first[m.end_col :]
        )
    return "\n".join(ln.decode().strip() for ln in [first, *lines[m.line : m.line + 2]])


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def report(
    mutants: list[Mutant], totals: dict[str, int], out: Path, args: argparse.Namespace
) -> dict:
    per: dict[str, dict[str, int]] = {}
    for m in mutants:
        row = per.setdefault(m.path, {"candidates": totals.get(m.path, 0), "tried": 0})
        row["tried"] += 1
        row[m.status] = row.get(m.status, 0) + 1
    killed = sum(m.status in ("killed", "timeout") for m in mutants)
    counted = sum(m.status != "equivalent" for m in mutants)
    summary = {
        "seed": args.seed,
        "cap": args.cap,
        "mutants": len(mutants),
        "killed": sum(m.status == "killed" for m in mutants),
        "timeout": sum(m.status == "timeout" for m in mutants),
        "survived": sum(m.status == "survived" for m in mutants),
        "equivalent": sum(m.status == "equivalent" for m in mutants),
        "ratio": round(killed / counted, 4) if counted else None,
        "seconds": round(sum(m.seconds for m in mutants), 1),
    }
    data = {"summary": summary, "modules": per, "mutants": [asdict(m) for m in mutants]}
    out.with_suffix(".json").write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")
    md = [
        "# Mutation run",
        "",
        f"`python benchmarks/mutate.py --seed {args.seed} --cap {args.cap}`: "
        f"{summary['mutants']} mutants, {summary['killed']} killed, {summary['timeout']} "
        f"timed out (killed), {summary['survived']} survived, {summary['equivalent']} "
        f"equivalent (left out); kill ratio {killed}/{counted}"
        + (f" = {100 * killed / counted:.1f} %" if counted else "")
        + f"; {summary['seconds'] / 60:.1f} min of test runs.",
        "",
        "| module | candidates | tried | killed | timeout | survived | equivalent |",
        "|---|---|---|---|---|---|---|",
    ]
    for path, row in per.items():
        md.append(
            f"| {path} | {row['candidates']} | {row['tried']} | {row.get('killed', 0)} "
            f"| {row.get('timeout', 0)} | {row.get('survived', 0)} | {row.get('equivalent', 0)} |"
        )
    for title, status in (
        ("Survivors", "survived"),
        ("Equivalent", "equivalent"),
        ("Timeouts", "timeout"),
    ):
        chosen = [m for m in mutants if m.status == status]
        if chosen:
            md += [
                "",
                f"## {title}",
                "",
                "| id | file:line | mutation | reason |",
                "|---|---|---|---|",
            ]
            md += [
                f"| {m.id} | {m.path}:{m.line} | {_cell(m.describe())} | {_cell(m.reason)} |"
                for m in chosen
            ]
    out.with_suffix(".md").write_text("\n".join(md) + "\n")
    return summary


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=38)
    ap.add_argument("--cap", type=int, default=12, help="mutants a module at most")
    ap.add_argument("--module", action="append", default=[], help="only this module (repeatable)")
    ap.add_argument("--only", action="append", default=[], help="only this mutant id")
    ap.add_argument(
        "--rerun",
        type=Path,
        help="keep the killed of this report (.json), run the rest; the report has them all",
    )
    ap.add_argument("--timeout", type=float, default=120, help="seconds a pytest run at most")
    ap.add_argument(
        "--baseline", action="store_true", help="first run each module's tests unmutated"
    )
    ap.add_argument("--list", action="store_true", help="list the sampled mutants, run nothing")
    ap.add_argument("--out", type=Path, default=ROOT / "benchmarks" / "mutation-report")
    args = ap.parse_args(argv)
    modules = args.module or list(TARGETS)
    wanted = set(args.only)
    done: dict[str, Mutant] = {}  # the killed of --rerun's report, kept as they are
    if args.rerun:
        old = json.loads(args.rerun.read_text())
        done = {
            m["id"]: Mutant(**m) for m in old["mutants"] if m["status"] in ("killed", "timeout")
        }
    totals, mutants = {}, []
    for path in modules:
        totals[path], chosen = sample(path, TARGETS[path], args.cap, args.seed)
        mutants += [done.get(m.id, m) for m in chosen if not wanted or m.id in wanted]
    mutants += [done.get(m.id, m) for m in report_mutants(modules) if not wanted or m.id in wanted]
    todo = [m for m in mutants if m.id not in done]
    if args.list:
        for m in todo:
            print(f"{m.id}\t{m.path}:{m.line}\t{m.describe()}")
        print(f"{len(todo)} mutants of {sum(totals.values())} candidates", file=sys.stderr)
        return 0
    # a TERM (a stopped run) unwinds like Ctrl-C: the temporary tree is removed
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    with tempfile.TemporaryDirectory(prefix="scanconv-mutate-") as tmp:
        tree = Path(tmp)
        copy_tree(tree)
        for path in dict.fromkeys(m.path for m in todo) if args.baseline else ():
            for test in runs(path, TARGETS[path]):
                outcome, _, first = pytest_run(tree, test, args.timeout)
                if outcome != "passed":
                    print(f"unmutated {path}: {outcome} {first} ({test})", file=sys.stderr)
                    return 1
        for n, m in enumerate(todo, 1):
            run_mutant(tree, m, TARGETS[m.path], args.timeout)
            print(
                f"[{n}/{len(todo)}] {m.status:10} {m.seconds:6.1f}s {m.id} {m.describe()}",
                flush=True,
            )
            report([m for m in mutants if m.status], totals, args.out, args)
    summary = report(mutants, totals, args.out, args)
    print(json.dumps(summary), flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
