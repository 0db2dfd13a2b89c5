"""N1: the LaTeX renderer's math-cell test, and the student-table patterns, in one pass.

``render/mappings/latex.py`` sets a table cell in math mode when it is one of scanconv's numbers or
points (:func:`~scanconv.render.mappings.latex.math_cell`). Its pattern was
``(?=[-(0-9])(?:[-+*/(), ]|[0-9]+(?:\\.[0-9]+)?|sqrt|[a-z]{1,2}(?![a-z.]))+``: the ``[0-9]+``
inside the outer ``+`` could split a run of *n* digits in 2^(n-1) ways, so a transform with
six-digit coordinates, a sheet holding it, and a student file named with 32 digits never
finished as LaTeX. Here:

* the matcher accepts exactly the cells the old pattern accepted (the old pattern itself on
  short strings, where its backtracking is cheap, and a scanner written here on long ones);
* its work is bounded by its structure, not by a clock: every quantifier inside the repeated
  group takes the whole of its run of characters (one way to match), and at any place of a
  cell at most one piece matches, so the backtracking matcher tries each place once;
* the attack's commands end (run under :func:`~tests.helpers.run_limited`, a CPU-time guard
  against a hang, not a speed test).

The same goes for the student-table patterns of ``marking/student_table.py`` that ran over a
student's file with overlapping runs of spaces (``^\\s*\\|?\\s*`` over blank lines, a pixel's
``\\s*[,;\\s]\\s*``, the brackets of a first line): the old and new patterns agree on every short
string, and the files that hung ``check`` are marked or refused at once.
"""

from __future__ import annotations

import itertools
import re
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.marking import student_table
from scanconv.render.mappings import latex
from tests.helpers import run_limited

if sys.version_info >= (3, 11):
    from re import _constants as sre_constants
    from re import _parser as sre_parse
else:  # pragma: no cover - Python 3.10
    import sre_constants
    import sre_parse

OLD_MATH_CELL = re.compile(
    r"(?=[-(0-9])(?:[-+*/(), ]|[0-9]+(?:\.[0-9]+)?|sqrt|[a-z]{1,2}(?![a-z.]))+"
)
"""The pattern before the fix: the definition of the cells that are math (its accept set is
what the goldens were written with), exponential on a long run of digits."""

DIGITS = "0123456789"
LETTERS = "abcdefghijklmnopqrstuvwxyz"


def reference_math_cell(text: str) -> bool:
    """The cells the old pattern accepts, by a scanner over runs of characters.

    A cell starts with a digit, ``-`` or ``(``; it is operators (``-+*/(), ``), runs of digits
    and dots, and runs of letters. A run of digits and dots is numbers written one after
    another: no dot at either end, no two dots together, and at least two digits between two
    dots (``1.23.4`` is ``1.2`` then ``3.4``; ``1.2.3`` is no numbers). A run of letters is any
    number of ``sqrt`` then at most two letters, and a name (the two letters) is not followed
    by a dot."""
    if not text or text[0] not in "-(" + DIGITS:
        return False
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c in "-+*/(), ":
            i += 1
            continue
        j = i
        if c in DIGITS:
            while j < n and (text[j] in DIGITS or text[j] == "."):
                j += 1
            pieces = text[i:j].split(".")
            if "" in pieces or any(len(p) < 2 for p in pieces[1:-1]):
                return False
        elif c in LETTERS:
            while j < n and text[j] in LETTERS:
                j += 1
            run, k = text[i:j], 0
            while run.startswith("sqrt", k):
                k += 4
            if len(run) - k > 2 or (len(run) > k and text[j : j + 1] == "."):
                return False
        else:
            return False
        i = j
    return True


def test_reference_on_the_cells_scanconv_writes() -> None:
    """The scanner itself, on hand-picked cells (the doctest's and the report's)."""
    yes = ["-3", "2.500", "34/27", "(3, -4)", "(0.500, 1.000)", "-1 + 3*sqrt(2)/2"]
    yes += ["(xc + x, yc - y)", "1.23.4", "2x", "(sqrtab)", "0.798636*123456"]
    no = ["", "x", "0\\input{x}.csv", "0(abc).csv", "0 a.csv", "1.2.3", "5.", "0..1", "0xs."]
    no += ["0.798636*123456 + 1000000 = 704816.213401", "0" * 32 + ".csv", "0sqr", "0A"]
    assert [reference_math_cell(c) for c in yes] == [True] * len(yes)
    assert [reference_math_cell(c) for c in no] == [False] * len(no)
    for cell in yes + no:
        if len(cell) <= 16:  # the old pattern ends in time on short cells only
            assert (OLD_MATH_CELL.fullmatch(cell) is not None) == (cell in yes), cell


ALPHABET = DIGITS[:3] + ".-+*/(), sqrtxyc=A\\{}_"
PIECES = ["0", "7", "12", "3.5", ".", "-", "(", ")", ", ", " + ", "*", "/", "sqrt", "x", "yc"]
PIECES += ["abc", "sq", "=", " ", "A", "\\", ".csv"]
CELLS = st.one_of(
    st.text(ALPHABET, max_size=14),
    st.lists(st.sampled_from(PIECES), max_size=8).map("".join),
)


@pytest.mark.slow
@settings(max_examples=1500, deadline=None)
@given(CELLS)
def test_math_cell_accepts_what_the_old_pattern_accepted(text: str) -> None:
    """On short cells (where its backtracking is cheap) the old pattern is the definition."""
    old = OLD_MATH_CELL.fullmatch(text) is not None
    assert latex.math_cell(text) == old == reference_math_cell(text)


@pytest.mark.slow
def test_math_cell_every_short_string() -> None:
    """Every string of up to five characters over the characters that matter agrees."""
    for n in range(6):
        for chars in itertools.product("01.-(sqrt x", repeat=n):
            text = "".join(chars)
            assert latex.math_cell(text) == (OLD_MATH_CELL.fullmatch(text) is not None), text


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from([*PIECES, "123456", "0" * 40, "9.87654321"]), max_size=60))
def test_math_cell_agrees_with_the_scanner_on_long_cells(pieces: list[str]) -> None:
    """Long cells (too long for the old pattern) against the scanner written here."""
    text = "".join(pieces)
    assert latex.math_cell(text) == reference_math_cell(text)


# --- the work is bounded by the pattern's structure -------------------------------------------

_REPEATS = (sre_constants.MAX_REPEAT, sre_constants.MIN_REPEAT)


def _chars(node: tuple[object, object]) -> frozenset[str]:
    """The characters (of the first 256) a one-character node matches."""
    op, av = node
    if op is sre_constants.LITERAL:
        return frozenset(chr(av))  # type: ignore[arg-type]
    if op is sre_constants.IN:
        out: set[str] = set()
        for item_op, item_av in av:  # type: ignore[attr-defined]
            if item_op is sre_constants.LITERAL:
                out.add(chr(item_av))
            elif item_op is sre_constants.RANGE:
                out.update(chr(c) for c in range(item_av[0], item_av[1] + 1))
            else:
                raise AssertionError(f"not a plain character set: {node}")
        return frozenset(out)
    raise AssertionError(f"not one character: {node}")


def _unambiguous_repeats(items: list[tuple[object, object]], inside: bool) -> list[str]:
    """What breaks the rule in a parsed pattern: a quantifier inside another quantifier must
    be over one character set and followed at once by a negative lookahead excluding that
    set, so that it takes all of its run (matches in one way only)."""
    faults = []
    for i, (op, av) in enumerate(items):
        if op in _REPEATS:
            body = av[2]  # type: ignore[index]
            if inside:
                after = items[i + 1] if i + 1 < len(items) else None
                ok = len(body) == 1 and after is not None and after[0] is sre_constants.ASSERT_NOT
                if ok:
                    direction, look = after[1]  # type: ignore[misc]
                    ok = direction == 1 and len(look) == 1 and _chars(body[0]) <= _chars(look[0])
                if not ok:
                    faults.append(f"a quantifier {body} inside a quantifier can end early")
            faults += _unambiguous_repeats(list(body), True)
        elif op is sre_constants.SUBPATTERN:
            faults += _unambiguous_repeats(list(av[-1]), inside)  # type: ignore[index]
        elif op is sre_constants.BRANCH:
            for branch in av[1]:  # type: ignore[index]
                faults += _unambiguous_repeats(list(branch), inside)
    return faults


def test_old_pattern_breaks_the_rule() -> None:
    """The rule sees the defect (so the next test can fail)."""
    assert _unambiguous_repeats(list(sre_parse.parse(OLD_MATH_CELL.pattern)), False)


def test_math_cell_pattern_takes_every_run_whole() -> None:
    """The product's pattern: each quantifier under the repeated group matches one way."""
    tree = list(sre_parse.parse(latex._MATH_CELL.pattern))
    assert _unambiguous_repeats(tree, False) == []
    assert latex._MATH_CELL.pattern == "(?=[-(0-9])(?:" + "|".join(latex.MATH_TOKENS) + ")+"


@pytest.mark.slow
@settings(max_examples=800, deadline=None)
@given(CELLS)
def test_at_most_one_piece_matches_at_any_place(text: str) -> None:
    """At every place of a cell at most one piece (:data:`~scanconv.render.mappings.latex.MATH_TOKENS`)
    matches: with each piece matching in one way, the backtracking matcher has one choice at
    each place, so it tries each place of the cell once (its work grows with the length)."""
    tokens = [re.compile(t) for t in latex.MATH_TOKENS]
    for pos in range(len(text)):
        assert sum(t.match(text, pos) is not None for t in tokens) <= 1, (text, pos)


def test_lookbehind_sees_before_the_start() -> None:
    """``match(text, pos)`` lets the decimal point's lookbehind see the characters before
    ``pos`` (the test above relies on it)."""
    point = re.compile(latex.MATH_TOKENS[2])
    assert point.match("1.2.3", 3) is None and point.match("12.3", 2) is not None


ADVERSARIAL = [
    "0" * 10_000 + "=",
    "0" * 10_000 + ".csv",
    "1" * 10_000 + "A",
    "(" + "12." * 4_000 + "x",
    "0" + "1.23" * 3_000 + ".",
    "0 " + "sqrt" * 3_000 + "abc",
    "0" + "ab " * 4_000 + "abc",
    "-" + "9" * 10_000 + "." + "9" * 10_000 + "\\",
]


@pytest.mark.parametrize("text", ADVERSARIAL, ids=lambda t: f"{t[:6]!r}..{t[-4:]!r}")
def test_long_adversarial_cells_are_refused(text: str) -> None:
    """Runs of 10,000 digits followed by a character that fails: refused (the old pattern
    would try 2^9999 splits), and the scanner agrees."""
    assert latex.math_cell(text) is False
    assert reference_math_cell(text) is False
    assert latex.math_cell(text[:-1]) == reference_math_cell(text[:-1])


# --- the attack's commands end ----------------------------------------------------------------

TRANSFORM = ["transform", "123456", "654321", "--rotate", "37"]
TRANSFORM += ["--translate", "1000000", "2000000"]


@pytest.mark.slow
def test_big_transform_as_latex_ends() -> None:
    """``transform 123456 654321 --rotate 37 --translate 1000000 2000000 -f latex`` never
    ended; its working cells (with an ``=``) are text, its points math."""
    result = run_limited(*TRANSFORM, "-f", "latex")
    assert result.code == 0, result.err
    assert "$(704816.213401, 2596861.978796)$" in result.out
    # the points table is set in parts (no scaling below 7 pt): the working is a text cell
    assert "P1 & 0.798636*123456 + (-0.601815)*654321 + 1000000 = 704816.213401 \\\\" in result.out


@pytest.mark.slow
def test_big_transform_in_a_sheet_ends(tmp_path: Path) -> None:
    """The same question as a sheet line, written as a LaTeX key (``--pdf`` goes through the
    same renderer)."""
    questions = tmp_path / "qt.txt"
    questions.write_text(" ".join(TRANSFORM) + "\n", encoding="utf-8")
    key = tmp_path / "key.tex"
    result = run_limited("sheet", str(questions), "-o", str(key))
    assert result.code == 0, result.err
    assert "$(704816.213401, 2596861.978796)$" in key.read_text(encoding="utf-8")


@pytest.mark.slow
def test_digit_named_student_file_in_a_latex_batch_ends(tmp_path: Path) -> None:
    """A student file named with 32 digits hung ``check --batch -f latex`` for minutes; its
    name is text, not math."""
    folder = tmp_path / "cr"
    folder.mkdir()
    (folder / ("0" * 32 + ".csv")).write_text("k,p_k,x,y\n0,0,2,2\n", encoding="utf-8")
    out = tmp_path / "s.tex"
    batch = ["check", "--batch", str(folder), "-f", "latex", "-o", str(out)]
    result = run_limited(*batch, "--", "line", "2", "2", "10", "6")
    assert result.code == 0, result.err
    text = out.read_text(encoding="utf-8")
    assert "0" * 32 + ".csv" in text and "$" + "0" * 32 not in text


# --- the student-table patterns -------------------------------------------------------------

OLD_SEPARATOR = re.compile(r"^\s*\|?\s*:?-+:?\s*\|", re.MULTILINE)
OLD_PIPE_LINE = re.compile(r"^\s*\|", re.MULTILINE)
OLD_PAIR = re.compile(r"[(\[]?\s*([^,;\s()\[\]]+)\s*[,;\s]\s*([^,;\s()\[\]]+)\s*[)\]]?")


def _old_unbracketed(line: str) -> str:
    return re.sub(r"[(\[][^)\]]*[)\]]", "", line)


@pytest.mark.slow
@pytest.mark.parametrize(
    ("old", "name", "alphabet"),
    [(OLD_SEPARATOR, "_SEPARATOR", " \n|-:\tx"), (OLD_PIPE_LINE, "_PIPE_LINE", " \n|\tx\r")],
    ids=["separator", "pipe-line"],
)
def test_markdown_detection_unchanged(old: re.Pattern[str], name: str, alphabet: str) -> None:
    """Whether a file holds a Markdown table: the same answer as the old pattern on every
    string of up to six characters over the characters that matter."""
    new = getattr(student_table, name)
    for n in range(7):
        for chars in itertools.product(alphabet, repeat=n):
            text = "".join(chars)
            assert (old.search(text) is None) == (new.search(text) is None), repr(text)


@pytest.mark.slow
def test_pair_pattern_unchanged() -> None:
    """A pixel cell's two numbers: the same groups as the old pattern on every string of up
    to six characters."""
    for n in range(7):
        for chars in itertools.product("( 1,;\t)[", repeat=n):
            text = "".join(chars)
            old, new = OLD_PAIR.fullmatch(text), student_table._PAIR.fullmatch(text)
            assert (old and old.groups()) == (new and new.groups()), repr(text)


@pytest.mark.slow
def test_unbracketed_unchanged() -> None:
    """The first line without its bracketed groups: as the old substitution, on every short
    string (up to seven characters) over brackets and a letter."""
    for n in range(8):
        for chars in itertools.product("(])[x", repeat=n):
            text = "".join(chars)
            assert student_table._unbracketed(text) == _old_unbracketed(text), repr(text)


HOSTILE_FILES = {
    "blank-lines.dat": "k,p_k,x,y\n" + "\n" * 3000 + "0,0,2,2\n",
    "spaced-lines.dat": "k,p_k,x,y\n" + " \n" * 50_000 + "0,0,2,2\n",
    "brackets.dat": "k,p_k,x,y" + "(" * 200_000 + "\n0,0,2,2\n",
    "spaced-pixel.csv": 'k,p_k,"(x, y)"\n0,0,"(2' + " " * 100_000 + 'x)"\n',
}


@pytest.mark.slow
@pytest.mark.parametrize("name", HOSTILE_FILES)
def test_hostile_student_files_end(tmp_path: Path, name: str) -> None:
    """Files that held ``check`` for minutes (3,000 blank lines took over a minute, a first
    line of 200,000 brackets and a pixel with 100,000 spaces longer): marked or refused in
    one line, under the CPU guard."""
    path = tmp_path / name
    path.write_text(HOSTILE_FILES[name], encoding="utf-8")
    result = run_limited("check", str(path), "-f", "plain", "--", "line", "2", "2", "10", "6")
    assert result.code in (0, 2), result.err
    if result.code == 2:
        assert result.out == "" and result.err.count("\n") == 1, result.err
    else:
        assert "Marking" in result.out


def test_markdown_separator_found_in_blank_lines() -> None:
    """The detection still finds a separator row after runs of blank lines and spaces."""
    text = "\n" * 5000 + "  | k | x |\n  |---|:--:|\n"
    assert student_table._SEPARATOR.search(text) is not None
    assert student_table._SEPARATOR.search("\n" * 5000 + " " * 5000) is None


# --- the MathML converter's text edges --------------------------------------------------------

OLD_TEXT_EDGES = re.compile(r"\\text\{( *)([^{}]*?)( *)\}")


def _old_keep_spaces(m: re.Match[str]) -> str:
    before = "\\ " if m.group(1) else ""
    after = "\\ " if m.group(3) else ""
    return before + "\\text{" + m.group(2) + "}" + after


@pytest.mark.slow
def test_text_edges_unchanged() -> None:
    """``render/html/mathml.py``'s ``\\text{...}`` edges (``( *)([^{}]*?)( *)`` was cubic in a run
    of spaces): the same TeX as the old substitution on every string of up to six pieces."""
    from scanconv.render.html import mathml

    for n in range(7):
        for pieces in itertools.product([" ", "a", "{", "}", "\\text{"], repeat=n):
            tex = "".join(pieces)
            old = OLD_TEXT_EDGES.sub(_old_keep_spaces, tex)
            assert mathml._TEXT_EDGES.sub(mathml._keep_spaces, tex) == old, repr(tex)


def test_text_edges_long_run_of_spaces() -> None:
    """A ``\\text{`` with 100,000 spaces and no closing brace is left as it is (the old
    pattern tried every split of the spaces)."""
    from scanconv.render.html import mathml

    tex = "\\text{" + " " * 100_000 + "x"
    assert mathml._TEXT_EDGES.sub(mathml._keep_spaces, tex) == tex
    assert mathml._TEXT_EDGES.sub(mathml._keep_spaces, tex + " }") == "\\ \\text{x}\\ "
