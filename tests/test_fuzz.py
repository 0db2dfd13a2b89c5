"""Fuzz the CLI: random argument vectors from each command's vocabulary, mixed with junk.

Whatever the arguments, ``scanconv.cli.main`` returns (nothing escapes it), prints no
traceback, and exits 0, 1 or 2; a refusal (2) prints nothing on stdout and one line on stderr.

Each example starts from one of the command's quick valid invocations and is mutated: option
pieces (with choices, small plausible values or junk) inserted, tokens replaced by junk or
dropped. Numbers are kept small, or beyond every limit, so that a valid run stays quick. File
options always point into a temporary directory, and the runs happen in it.

Each run has a hard limit (:func:`tests.helpers.run_limited`): a draw that escapes a work
budget fails with its command line instead of hanging the suite. The long fuzz, each run a
process limited in time and memory, is ``benchmarks/fuzz.py``.

``SCANCONV_FUZZ_EXAMPLES`` sets the total number of examples (default 100, spread over the
commands, at least 10 each); ``SCANCONV_FUZZ_EXAMPLES=3000 pytest tests/test_fuzz.py`` is a
long run in-process. The suite's share is kept small (it was 30 a command and 200 edge calls,
a sixth of the suite's time): the depth is the long fuzz's, run before a release.
"""

from __future__ import annotations

import contextlib
import os
import re
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .cli_vocabulary import VOCABULARY, Vocab, choices, commands, file_options, options
from .helpers import run_limited

pytestmark = pytest.mark.slow

COMMANDS = commands()  # every registered command, including those added since
EXAMPLES = int(os.environ.get("SCANCONV_FUZZ_EXAMPLES", "100"))
MIN_PER_COMMAND = 10
"""The budget: at least this many examples for each command, however many there are (the
edge sweep below reaches every validator's edges deterministically; the random draws add
junk around them; ``benchmarks/fuzz.py`` draws 2,000)."""
PER_COMMAND = max(MIN_PER_COMMAND, EXAMPLES // max(1, len(COMMANDS)))

#: A command the vocabulary does not know yet: fuzzed from its options and junk alone.
UNKNOWN = Vocab(
    valid=((),),
    numbers=((),),
    out_of_range=(),
    too_few=((), ""),
    too_many=((), ""),
    wrong_type=((), ""),
)

#: Values at the edges every validator draws: zero, one, signs, halves, the magnitude limit.
BOUNDARY = (
    *("0", "1", "-1", "2", "-2", "3", "1/2", "-1/2", "0.5", "1e-9", "-0", "0/1"),
    *("1000000000", "-1000000000", "1000000001", "999999999.5", "4096", "4097", "100001"),
    *("16777216", "16777217", "24", "25", "100", "101", "10000", "10001", "2000", "2001"),
)

#: Junk that means something to a parser: dashes, non-finite and out-of-range numbers, unicode
#: look-alikes, separators, option-looking tokens.
SPECIAL = (
    *("-", "--", "", " ", ":", ",", "=", "'", '"', "\\", "\x00", "\t"),
    *("nan", "-nan", "NaN", "inf", "-inf", "+inf", "Infinity", "-Infinity", "1e999", "-1e999"),
    *("1e10", "-1e10", "1e-999", "99999999999999999999", "9" * 41, "1/0", "0/0", "-0", "0x10"),
    *("1_0", "1,5", "½", "\u2212" + "3", "𝟙", "é", "∞", "NaN%", "1e", ".", "e", "pi", "2*pi"),
    *("--help", "-h", "--bogus", "-Z", "--no-grid", "--grid", "--explain", "--format", "-f"),
    *("--samples", "-n", "--at", "--center", "--levels", "-L", "--size", "--range", "--bits"),
    *("--degree", "--knots", "--t-range", "--move", "--x", "--y", "--radius", "--a", "--b"),
    *("__import__('os')", "().__class__", "9**9**9", "(" * 60 + "t" + ")" * 60, "t" * 600),
)
SMALL_NUMBERS = st.integers(-16, 16).map(str) | st.sampled_from(
    ("0.5", "-2.5", "1/3", "-7/4", "1e1", "0.125", "3.", ".5")
)
BEYOND_LIMITS = (st.integers(10**9 + 1, 10**40) | st.integers(-(10**40), -(10**9) - 1)).map(str)
_FILE_OPTION = re.compile(r"^(-o|--output|--svg|--png)")


def _safe_text(text: str) -> bool:
    """No junk may name a file option: their values are set by :func:`_place_files`."""
    return not _FILE_OPTION.match(text)


TEXT = st.text(alphabet=st.characters(blacklist_categories=("Nd", "Cs")), max_size=10).filter(
    _safe_text
)
JUNK = st.sampled_from(SPECIAL) | TEXT | BEYOND_LIMITS | SMALL_NUMBERS


def _option_piece(param: Any, vocab: Vocab) -> st.SearchStrategy[list[str]]:
    """An option with its values: choices, the vocabulary's plausible values, or junk."""
    names = [*param.opts, *param.secondary_opts]
    name = st.sampled_from(names)
    if getattr(param, "is_flag", False):
        return name.map(lambda n: [n])
    plausible = choices(param) or vocab.small.get(param.opts[0], ())
    value = st.sampled_from(plausible) | SMALL_NUMBERS | JUNK if plausible else SMALL_NUMBERS | JUNK
    count = max(1, param.nargs)
    return st.tuples(name, st.lists(value, min_size=count, max_size=count)).map(
        lambda nv: [nv[0], *nv[1]]
    )


def _piece(command: Any, vocab: Vocab) -> st.SearchStrategy[list[str]]:
    files = set(file_options(command))
    pieces = [
        _option_piece(p, vocab)
        for p in options(command)
        if p.opts[0] not in files and p.opts[0] != "--help"
    ]
    file_piece = st.sampled_from(sorted(files)).map(lambda o: [o, "FILE"]) if files else None
    positional = st.sampled_from(vocab.positional) if vocab.positional else SMALL_NUMBERS
    alternatives = [*pieces, positional.map(lambda t: [t]), JUNK.map(lambda t: [t])]
    if file_piece is not None:
        alternatives.append(file_piece)
    return st.one_of(alternatives)


@st.composite
def _argv(draw: Any, command: Any, vocab: Vocab) -> list[str]:
    which = draw(st.integers(0, len(vocab.valid) - 1))
    argv = list(vocab.valid[which])
    numbers = [
        i for i in (vocab.numbers[which] if which < len(vocab.numbers) else ()) if i < len(argv)
    ]
    for _ in range(draw(st.integers(0, 4))):
        action = draw(st.sampled_from(("insert", "replace", "drop", "append", "edge", "edge")))
        live = [i for i in numbers if i < len(argv)]  # (drops may have shortened argv)
        if action == "edge" and live:  # a number of a valid call at a validator's edge
            argv[draw(st.sampled_from(live))] = draw(st.sampled_from(BOUNDARY))
        elif action == "edge":
            continue
        elif action in ("insert", "append") or not argv:
            where = len(argv) if action == "append" else draw(st.integers(0, len(argv)))
            argv[where:where] = draw(_piece(command, vocab))
        elif action == "replace":
            argv[draw(st.integers(0, len(argv) - 1))] = draw(JUNK)
        else:
            del argv[draw(st.integers(0, len(argv) - 1))]
    return argv


def _place_files(argv: list[str], files: set[str], directory: Path, tag: int) -> list[str]:
    """Point every file option into ``directory`` (a new file, a missing folder or the folder)."""
    out: list[str] = []
    skip = False
    for i, token in enumerate(argv):
        if skip:
            skip = False
            continue
        out.append(token)
        if token in files:
            kind = tag % 3
            target = (
                directory / f"f{tag}-{i}.out"
                if kind == 0
                else directory / "missing" / "x.out"
                if kind == 1
                else directory
            )
            out.append(str(target))
            skip = i + 1 < len(argv)
    return out


@contextlib.contextmanager
def _inside(directory: Path) -> Iterator[None]:
    old = Path.cwd()
    os.chdir(directory)
    try:
        yield
    finally:
        os.chdir(old)


def test_every_command_is_fuzzed_from_its_vocabulary():
    """A command added without an entry in tests/cli_vocabulary.py is still fuzzed (from its
    options and junk), but only its vocabulary's valid calls reach its validators' edges."""
    missing = [" ".join(path) for path, _ in COMMANDS if path not in VOCABULARY]
    assert not missing, f"add these commands to tests/cli_vocabulary.py VOCABULARY: {missing}"
    assert {path for path, _ in COMMANDS} >= set(VOCABULARY) - {("check", "batch")}


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("path", [p for p, _ in COMMANDS], ids=" ".join)
def test_random_argument_vectors_never_escape_main(path, tmp_path_factory):
    command = dict(COMMANDS)[path]
    vocab = VOCABULARY.get(path, UNKNOWN)
    files = set(file_options(command))
    directory = tmp_path_factory.mktemp("fuzz")

    @settings(
        max_examples=PER_COMMAND,
        deadline=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
    )
    @given(argv=_argv(command, vocab), tag=st.integers(0, 2))
    def check(argv: list[str], tag: int) -> None:
        argv = _place_files(argv, files, directory, tag)
        with _inside(directory):
            r = run_limited(*path, *argv)  # an exception escaping main fails the test here
        assert "Traceback" not in r.err, (argv, r.err)
        assert r.code in (0, 1, 2), (argv, r.code, r.err)
        if r.code in (1, 2):
            assert r.err.startswith("scanconv: error: ") and r.err.count("\n") == 1, (argv, r.err)
        if r.code == 2:
            assert r.out == "", (argv, r.out[:300], r.err)

    check()


#: The small edges of the edge sweep: a valid call stays quick with any of them in any slot.
EDGES = ("0", "-1", "1", "2", "1/2", "-1/2", "0.5", "7", "16", "101", "-0")
MAX_SWEEP = 50
"""The sweep's budget per command: at most this many runs (a seeded sample if there are more)."""


def _sweep(path: tuple[str, ...]) -> list[list[str]]:
    import random

    vocab = VOCABULARY.get(path)
    if vocab is None:
        return []
    argvs = [
        [*valid[:slot], edge, *valid[slot + 1 :]]
        for valid, slots in zip(vocab.valid, vocab.numbers, strict=False)
        for slot in slots
        if slot < len(valid)
        for edge in EDGES
        if edge != valid[slot]
    ]
    if len(argvs) > MAX_SWEEP:
        argvs = random.Random(" ".join(path)).sample(argvs, MAX_SWEEP)
    return argvs


@pytest.mark.no_cover  # repeats covered lines: tracing tripled its CPU
@pytest.mark.parametrize("path", [p for p, _ in COMMANDS], ids=" ".join)
def test_each_number_of_a_valid_call_at_each_edge_never_escapes_main(path, tmp_path):
    """Every number slot of every valid call, one at a time, at each small edge: what reaches
    a command's validators without junk around it. An exception a validator lets escape (an
    ``IndexError`` for an index one beyond the points, a ``ZeroDivisionError`` for a zero
    step) fails here."""
    for argv in _sweep(path):
        with _inside(tmp_path):
            r = run_limited(*path, *argv)
        assert "Traceback" not in r.err, (argv, r.err)
        assert r.code in (0, 1, 2), (argv, r.code, r.err)
        if r.code in (1, 2):
            assert r.err.startswith("scanconv: error: ") and r.err.count("\n") == 1, (argv, r.err)
        if r.code == 2:
            assert r.out == "", (argv, r.out[:300], r.err)


NAMES = sorted({part for path, _ in COMMANDS for part in path})


@settings(max_examples=max(10, EXAMPLES // 15), deadline=None)
@given(argv=st.lists(st.sampled_from(NAMES) | JUNK, max_size=6))
def test_random_words_at_the_top_level_never_escape_main(argv):
    """No command, an unknown one, a group without its subcommand, options before it."""
    r = run_limited(*argv)
    assert "Traceback" not in r.err
    assert r.code in (0, 2), (argv, r.code, r.err)
    if r.code == 2:
        assert r.out == "" and r.err.count("\n") == 1, (argv, r.err)
