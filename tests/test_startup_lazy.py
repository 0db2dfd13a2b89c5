"""The one lazy-loading mechanism (:mod:`scanconv.core.lazy`) and the start-up shortcuts that
must not change a result: the fast stub reader, the pattern-free ASCII transliteration and
the integer shortcut of the number parser, each against the general code it stands in for."""

import importlib
import re
import subprocess
import sys
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.core import lazy
from scanconv.core.numeric import parse_number
from scanconv.core.working import _FROM_SUB, _FROM_SUP, _sub_ascii, _sup_ascii, ascii_text

STUBBED = ("scanconv", "scanconv._api", "scanconv.questions")


@pytest.mark.parametrize("package", STUBBED)
def test_the_fast_stub_reader_reads_what_ast_reads(package):
    init_file = importlib.import_module(package).__file__
    text = lazy._stub_text(init_file)
    exports, listed = lazy._stub_tree(package, text)
    assert lazy.stub_exports(package, init_file) == exports
    assert len(exports) > 5
    assert set(listed) - {"__version__"} <= set(exports)


def test_a_stub_line_the_fast_reader_cannot_read_falls_back_to_ast(tmp_path):
    init = tmp_path / "pkg" / "__init__.py"
    init.parent.mkdir()
    init.write_text("")
    init.with_suffix(".pyi").write_text("from .a import (\n    b as b,\n    c as c,\n)\n")
    assert lazy.stub_exports("pkg", str(init)) == {"b": ("pkg.a", "b"), "c": ("pkg.a", "c")}


@pytest.mark.parametrize("package", STUBBED)
def test_every_listed_name_loads(package):
    module = importlib.import_module(package)
    for name in module.__all__:
        assert getattr(module, name) is not None


def test_a_private_or_unknown_name_is_an_attribute_error_without_reading_the_stub():
    import scanconv

    with pytest.raises(AttributeError, match="has no attribute '_nope'"):
        scanconv._nope  # noqa: B018
    with pytest.raises(AttributeError, match="has no attribute 'nope'"):
        scanconv.nope  # noqa: B018


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_lazy_module_is_imported_on_first_read_only():
    code = (
        "import sys\n"
        "from scanconv.core import lazy\n"
        "m = lazy.module('scanconv.algorithms.storage')\n"
        "print('scanconv.algorithms.storage' in sys.modules, repr(m))\n"
        "m.__file__\n"
        "print('scanconv.algorithms.storage' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split("\n")[:2] == [
        "False <lazy module 'scanconv.algorithms.storage'>",
        "True",
    ]


def test_a_lazy_pattern_is_the_compiled_pattern():
    words = lazy.pattern(r"(\w+)-(\w+)", re.I)
    assert words.sub(r"\2 \1", "a-B c-d") == "B a d c"
    assert words.pattern == r"(\w+)-(\w+)" and words.flags & re.I


# --- ascii_text: as the patterns it replaced ---------------------------------------------------

_UNSAFE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]")
_SUB_RUN = re.compile("[" + "".join(_FROM_SUB) + "]+")
_SUP_RUN = re.compile("[" + "".join(_FROM_SUP) + "]+")


def _by_patterns(s: str) -> str:
    """ascii_text as it was written with regular expressions (the reference)."""
    from scanconv.core.working import _ASCII

    if s.isascii():
        return s if s.isprintable() else _UNSAFE.sub("?", s)

    def sub(m: re.Match[str]) -> str:
        run = "".join(_FROM_SUB[c] for c in m.group())
        return _sub_ascii(run, m.string[m.start() - 1 : m.start()])

    def sup(m: re.Match[str]) -> str:
        return _sup_ascii("".join(_FROM_SUP[c] for c in m.group()), "")

    s = _SUP_RUN.sub(sup, _SUB_RUN.sub(sub, s))
    out = []
    for i, ch in enumerate(s):
        word = ch if ch.isascii() else _ASCII.get(ch, "?")
        if len(word) > 1 and word.isalpha() and s[i + 1 : i + 2].isalpha():
            word += " "
        out.append(word)
    return _UNSAFE.sub("?", "".join(out))


_ALPHABET = "".join(_FROM_SUB) + "".join(_FROM_SUP) + "pxy12 +-=()ΔεθΣ·≤\x1b\u202e\x7f\t"


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=400, deadline=None)
@given(st.text(alphabet=_ALPHABET, max_size=24))
def test_ascii_text_is_what_the_patterns_gave(s):
    assert ascii_text(s) == _by_patterns(s)


def test_ascii_text_examples():
    assert ascii_text("xₖ₊₁ = 2ⁿ⁻¹, p₀\x1b") == "x_{k+1} = 2^(n-1), p0?"


# --- parse_number: the integer shortcut ----------------------------------------------------------

_NUMBER = re.compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d{1,3})?|[+-]?\d+/\d+")


def _outcome(text: str) -> object:
    try:
        return parse_number(text)
    except ValueError as err:
        return str(err)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=400, deadline=None)
@given(st.text(alphabet="0123456789+-./eE \u2212\u0662\u00b2x", max_size=8))
def test_the_integer_shortcut_accepts_what_the_pattern_accepts(text):
    s = text.strip().replace("\u2212", "-")
    outcome = _outcome(text)
    if s and len(s) <= 40 and _NUMBER.fullmatch(s) is None:
        assert isinstance(outcome, str)  # refused, as the pattern refuses it
    elif s and re.fullmatch(r"[+-]?\d+", s):
        assert outcome == Fraction(s) or "out of range" in str(outcome)


# --- the program freezes its start-up; an in-process call does not -------------------------------


def test_an_in_process_run_leaves_the_callers_collector_alone(capsys):
    import gc

    from scanconv.cli import main

    before = gc.get_freeze_count()
    assert main(["line", "0", "0", "3", "1", "--format", "csv"]) == 0
    assert gc.get_freeze_count() == before
    assert capsys.readouterr().out.startswith("k,")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_program_freezes_what_its_start_up_made():
    code = (
        "import gc, sys\n"
        "from scanconv.cli import main\n"
        "sys.argv = ['scanconv', 'line', '0', '0', '3', '1', '--format', 'csv']\n"
        "status = main()\n"
        "print(status, gc.get_freeze_count() > 1000, file=sys.stderr)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stderr.split() == ["0", "True"]
    assert out.stdout.startswith("k,")


@pytest.mark.slow  # a subprocess
def test_the_program_starts_with_the_collector_off_and_runs_with_it_on():
    # run() turns the collector off for the imports and the command's build (start-up makes
    # only objects that live until exit); main() freezes them and turns it back on, so an
    # answer's own garbage is still collected.
    code = (
        "import gc, sys\n"
        "import scanconv.cli.entry as entry\n"
        "seen = []\n"
        "built = entry._command_for\n"
        "entry._command_for = lambda argv: (seen.append(gc.isenabled()), built(argv))[1]\n"
        "from scanconv.__main__ import run\n"
        "sys.argv = ['scanconv', 'line', '0', '0', '3', '1', '--format', 'csv']\n"
        "status = run()\n"
        "print(status, seen, gc.isenabled(), file=sys.stderr)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stderr.split() == ["0", "[False]", "True"]
    assert out.stdout.startswith("k,")


def test_a_lazy_module_reads_its_module_live(monkeypatch):
    from scanconv.core import numeric

    stand_in = lazy._LazyModule("scanconv.core.numeric")
    assert stand_in.COORD_LIMIT == numeric.COORD_LIMIT
    monkeypatch.setattr(numeric, "COORD_LIMIT", 7)
    assert stand_in.COORD_LIMIT == 7


def test_every_ascii_form_is_ascii():
    """ascii_text's one-table path relies on it (a form left non-ASCII would become ``?``)."""
    from scanconv.core.working import _ASCII

    assert all(word.isascii() and word for word in _ASCII.values())
