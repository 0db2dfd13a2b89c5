"""Every command, every class of bad input: exit 2, one line naming the problem, nothing else.

The commands are enumerated from the typer app (``tests/cli_vocabulary.py``), so a new command
is walked automatically, and :func:`test_every_command_has_a_vocabulary` fails until it has a
vocabulary entry. The classes: non-numeric, NaN, +-inf, empty, too few values, too many values,
out of range, wrong type, unknown option, unknown choice. Each run has a hard limit
(:func:`tests.helpers.run_limited`): a case that escaped its refusal cannot hang the sweep.
"""

from __future__ import annotations

import pytest

from .cli_vocabulary import ARGUMENTLESS, VOCABULARY, Argv, choices, commands, options
from .helpers import assert_refused, run_limited

pytestmark = pytest.mark.slow

COMMANDS = commands()

#: A bad value put in place of a number (or formula), and what the message must show of it.
REPLACEMENTS = [
    ("non-numeric", "abc", ("abc",)),
    ("NaN", "nan", ("nan",)),
    ("+inf", "inf", ("inf",)),
    ("-inf", "-inf", ("inf",)),
    ("empty", "", ("empty", "''")),
]


def _name(path: tuple[str, ...]) -> str:
    return " ".join(path)


def _case(path: tuple[str, ...], kind: str, argv: Argv, words: tuple[str, ...]) -> object:
    return pytest.param(path, argv, words, id=f"{_name(path)}: {kind}")


def _cases() -> list[object]:
    cases = []
    for path, command in COMMANDS:
        vocab = VOCABULARY.get(path)
        if vocab is None:  # reported by test_every_command_has_a_vocabulary
            continue
        for valid, slots in zip(vocab.valid, vocab.numbers, strict=True):
            for slot in slots:
                for kind, bad, words in REPLACEMENTS:
                    argv = (*valid[:slot], bad, *valid[slot + 1 :])
                    cases.append(_case(path, f"{kind} at {slot} of {valid[:3]}", argv, words))
        first = vocab.valid[0]
        cases.append(_case(path, "too few values", vocab.too_few[0], (vocab.too_few[1],)))
        cases.append(_case(path, "too many values", vocab.too_many[0], (vocab.too_many[1],)))
        cases.append(_case(path, "wrong type", vocab.wrong_type[0], (vocab.wrong_type[1],)))
        for i, (argv, word) in enumerate(vocab.out_of_range):
            cases.append(_case(path, f"out of range {i}", argv, (word,)))
        cases.append(_case(path, "unknown option", (*first, "--bogus"), ("--bogus",)))
        cases.append(_case(path, "unknown short option", (*first, "-Z"), ("-Z",)))
        for param in options(command):
            if choices(param):
                argv = (*first, param.opts[0], "zzz")
                cases.append(_case(path, f"unknown choice {param.opts[0]}", argv, ("'zzz'",)))
    return cases


def test_every_command_has_a_vocabulary():
    missing = [_name(path) for path, _ in COMMANDS if path not in VOCABULARY]
    assert not missing, f"add these commands to tests/cli_vocabulary.py VOCABULARY: {missing}"
    stale = [_name(path) for path in VOCABULARY if path not in dict(COMMANDS)]
    assert not stale, f"VOCABULARY names commands that no longer exist: {stale}"


def test_every_class_is_walked_for_every_command():
    """The vocabulary gives each command every class (a guard against an empty entry)."""
    for path, _ in COMMANDS:
        vocab = VOCABULARY.get(path)
        if vocab is None:
            continue
        assert vocab.valid and (all(vocab.numbers) or path in ARGUMENTLESS), path
        assert vocab.out_of_range or path in ARGUMENTLESS, path
        for valid, slots in zip(vocab.valid, vocab.numbers, strict=True):
            assert all(0 <= i < len(valid) for i in slots), (path, valid, slots)


@pytest.mark.parametrize("path", [p for p, _ in COMMANDS], ids=_name)
def test_the_valid_invocations_are_valid(path):
    """The base of every bad case is good, so each bad case fails for its one bad value."""
    vocab = VOCABULARY.get(path)
    if vocab is None:
        pytest.skip("no vocabulary (see test_every_command_has_a_vocabulary)")
    for argv in vocab.valid:
        r = run_limited(*path, *argv, "--format", "plain")
        assert r.code == 0, (argv, r.err)
        assert r.out


@pytest.mark.parametrize(("path", "argv", "words"), _cases())
def test_bad_input_is_exit_2_one_line_naming_it(path, argv, words):
    r = run_limited(*path, *argv)
    assert_refused(r)
    assert any(w.lower() in r.err.lower() for w in words), (words, r.err)
