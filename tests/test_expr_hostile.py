"""Hostile formulas are refused with bounded work AND bounded memory, in-process and in the CLI.

``tests/test_expr.py`` checks each refusal's message and work (Python calls); this file adds the memory
bound (tracemalloc in-process; a memory-capped subprocess through the CLI, with its peak
resident size), and the variants an attacker would try next for each refusal:
``__import__``, attribute access, lambdas, comprehensions, ``9**9**9``, very long and deeply
nested expressions.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
import tracemalloc

import pytest

from scanconv.core.expr import MAX_BRACKETS, MAX_DEPTH, MAX_LENGTH, compile_expr, parse_exact

from .helpers import python_calls

#: (kind of attack, formula, a word of the refusal)
HOSTILE = [
    ("__import__", "__import__('os').system('echo pwned')", "attribute access"),
    ("__import__", "__import__('os')", "'__import__' is not allowed"),
    ("__import__", "__builtins__", "unknown name"),
    ("__import__", "globals()", "'globals' is not allowed"),
    ("__import__", "exec('import os')", "'exec' is not allowed"),
    ("__import__", "compile('1', '', 'eval')", "'compile' is not allowed"),
    ("__import__", "getattr(t, 'real')", "'getattr' is not allowed"),
    ("attribute", "t.__class__.__mro__", "attribute access"),
    ("attribute", "().__class__.__bases__[0].__subclasses__()", "attribute access"),
    ("attribute", "sin.__self__", "attribute access"),
    ("attribute", "(1).real", "attribute access"),
    ("lambda", "lambda: 1", "lambda"),
    ("lambda", "(lambda: __import__('os'))()", "only calls of"),
    ("lambda", "(lambda t: t)(t)", "only calls of"),
    ("comprehension", "[t for t in range(10**9)]", "comprehensions"),
    ("comprehension", "sum(t for t in range(10**9))", "'sum' is not allowed"),
    ("comprehension", "{t: t for t in ()}", "comprehensions"),
    ("comprehension", "{t for t in ()}", "comprehensions"),
    ("power", "9**9**9", "exponent"),
    ("power", "9**9**9**9", "exponent"),
    ("power", "(9**9)**(9**9)", "exponent"),
    ("power", "2**(2**(2**(2**2)))", "exponent"),
    ("power", "t**-(9**9)", "exponent"),
    ("power", "10**100*10**100*10**100*10**100", "constant part"),
    ("long", "t" + "+t" * 1_000_000, "too long"),
    ("long", "9" * 10_000_000, "too long"),
    ("long", "t" + " " * MAX_LENGTH, "too long"),
    ("nested", "(" * 1_000_000 + "t" + ")" * 1_000_000, "too long"),
    ("nested", "(" * (MAX_BRACKETS + 1) + "t" + ")" * (MAX_BRACKETS + 1), "too deeply nested"),
    ("nested", "sin(" * (MAX_BRACKETS + 1) + "t" + ")" * (MAX_BRACKETS + 1), "too deeply nested"),
    ("nested", "-" * (MAX_LENGTH - 1) + "t", "too deeply nested"),
    ("nested", "+-" * (MAX_DEPTH // 2 + 10) + "t", "too deeply nested"),
    ("nested", "[" * (MAX_BRACKETS + 1), "too deeply nested"),
]
IDS = [f"{item}: {text[:30]!r}" for item, text, _ in HOSTILE]


def test_every_kind_of_attack_is_covered():
    items = {item for item, _, _ in HOSTILE}
    assert items == {
        "__import__",
        "attribute",
        "lambda",
        "comprehension",
        "power",
        "long",
        "nested",
    }


@pytest.mark.parametrize(("item", "text", "word"), HOSTILE, ids=IDS)
def test_refused_with_bounded_work_and_memory(item, text, word):
    compile_expr("t + 1", ("t",))  # warm up: the first call imports and caches
    tracemalloc.start()
    try:
        refusal, calls = python_calls(_refusal, text)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    message = str(refusal)
    assert word in message, message
    assert "\n" not in message and len(message) < 200
    assert calls < REFUSAL_CALLS, f"{calls} Python calls"
    assert peak < 4 * 2**20, f"{peak / 2**20:.1f} MiB"


REFUSAL_CALLS = 10_000
"""Bounded work, counted rather than timed (a busy machine must not fail a test): a refusal
makes at most about 2,000 Python calls today, and the peak memory bounds the work done in C."""


def _refusal(text: str) -> ValueError:
    with pytest.raises(ValueError) as info:
        compile_expr(text, ("t",))
    return info.value


def test_exact_evaluation_is_bounded_too():
    """A formula that passes the checks cannot blow up at evaluation time either."""
    tracemalloc.start()
    try:
        _, calls = python_calls(_evaluate_hostile)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert calls < REFUSAL_CALLS and peak < 4 * 2**20, (calls, peak)


def _evaluate_hostile() -> None:
    for text in ("(t**100)**100", "((t**99)**99)**99", "t**100*t**100*t**100*t**100"):
        with pytest.raises(ValueError, match="too large"):
            compile_expr(text, ("t",)).exact(t=2**11)
    # A constant whose exact value would pass MAX_BITS is kept as a float instead.
    primes = (3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73)
    assert isinstance(parse_exact("+".join(f"1/{p}**100" for p in primes)), float)


CHILD = textwrap.dedent(
    """
    import io, json, resource, sys
    from contextlib import redirect_stderr, redirect_stdout
    resource.setrlimit(resource.RLIMIT_AS, (1 << 30, 1 << 30))
    from scanconv.cli import main
    results = []
    for text in json.load(sys.stdin):
        out, err = io.StringIO(), io.StringIO()
        with redirect_stdout(out), redirect_stderr(err):
            code = main(["parametric", "custom", "--x", text, "--y", "t", "-f", "csv"])
        results.append([code, out.getvalue(), err.getvalue()])
    # VmHWM: this process's own peak (ru_maxrss keeps the forking parent's size across exec)
    try:
        status = open("/proc/self/status").read()
        peak = int(status.split("VmHWM:")[1].split()[0])
    except (OSError, IndexError, ValueError):
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    results.append(peak)
    print(json.dumps(results))
    """
)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_cli_refuses_them_all_within_1_gib_and_a_small_peak():
    """Through the command line, in a process capped at 1 GiB of address space: every formula
    is one line of error, exit 2, and the process's peak resident size stays small."""
    texts = [text for _, text, _ in HOSTILE if len(text) < 100_000]  # argv has its own limits
    # The peak is the command's own: without pytest-cov's subprocess tracing (its COV_CORE_*
    # variables), and read from VmHWM, which a large test process does not leak into.
    env = {k: v for k, v in os.environ.items() if not k.startswith("COV_CORE")}
    proc = subprocess.run(
        [sys.executable, "-c", CHILD],
        input=json.dumps(texts),
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    *results, max_rss_kib = json.loads(proc.stdout)
    for text, (code, out, err) in zip(texts, results, strict=True):
        assert code == 2 and out == "", (text[:40], code, err)
        assert err.startswith("scanconv: error: ") and err.count("\n") == 1, err
    assert max_rss_kib < 300 * 1024, f"peak resident size {max_rss_kib / 1024:.0f} MiB"
