"""Answers whose tables are too wide for the page, printed: every word at 7 pt or more.

These answers' tables were once scaled down to the text width (``\\resizebox``: a symmetry
table's headings at about 2 pt) or set in ``\\tiny`` (5 pt); a wide typewriter picture was
set in ``\\tiny`` too. Each is typeset with pdflatex and read back with ``pdftotext -bbox``,
as a reader of the paper sees it: every word's box is as tall as 7 pt type sets it (about
6.2 pt; 5 pt type gives about 4.4), its width where it is set on its side, and the log has no
overfull box.
"""

from __future__ import annotations

import re

import pytest

from scanconv.core.records import Column
from scanconv.render.mappings import latex

from .external import overfull, typeset
from .helpers import run
from .test_print_layout import PREAMBLE
from .test_worksheet_print import _words

pytestmark = [pytest.mark.external, pytest.mark.slow]

WIDE = (
    ("circle", "5"),  # the 8-way symmetry table: nine point columns
    ("circle", "10", "--method", "midpoint"),
    ("polygon", "1", "1", "9", "1", "9", "7", "5", "3", "1", "7"),  # the scan lines' AET
    ("transform", "0", "0", "1", "1", "5", "2", "--rotate", "45", "--about", "-1", "-1"),
    ("clip", "line", "7", "9", "11", "4", "--window", "4", "4", "10", "8"),
    ("char", "stroke", "T", "--scale", "2"),
    ("theory", "symmetric-dda"),
)

SMALLEST = 6.0
"""The least box height of a word set at 7 pt (pdftotext boxes 7 pt text at about 6.2 pt)."""


def _small_words(pdf) -> list[tuple[str, float]]:
    small = []
    for word, w, h in _words(pdf):
        if len(word) < 3 or not re.search("[A-Za-z]", word):
            continue  # a digit or a subscript: its box says little about its size
        size = w if h > w else h  # a heading on its side: its box's width is its height
        if size < SMALLEST:
            small.append((word, round(size, 1)))
    return small


@pytest.mark.parametrize("args", WIDE, ids=" ".join)
def test_a_wide_table_prints_at_7_pt_or_more(tmp_path, args) -> None:
    done = run(*args, "--format", "latex")
    assert done.code == 0, done.err
    assert "\\resizebox" not in done.out and "\\tiny" not in done.out
    typed = typeset(tmp_path, PREAMBLE + done.out + "\n\\end{document}\n", passes=2)
    assert typed.code == 0, typed.log[-2000:]
    assert overfull(typed.log) == []
    assert len(_words(typed.pdf)) > 30
    assert _small_words(typed.pdf) == []


def test_a_table_no_column_pair_fits_is_set_at_7_pt_with_its_headings_on_their_sides(
    tmp_path,
) -> None:
    """A made-up table whose first column and one other do not fit side by side upright
    (once set in ``\\tiny``): at 7 pt, its long headings rotated, nothing past the margin."""
    heading = "a very long heading of many words that will not fit across"
    columns = [Column(f"c{i}", heading, "\\text{" + heading + "}") for i in range(2)]
    rows = [["(1, 2)", "(3, 4)"], ["(5, 6)", "(7, 8)"]]
    parts = latex.split_columns(columns, rows)
    assert [layout for _, layout in parts] == [("\\scriptsize", True)]
    tex = "".join(latex._tables("Wide", columns, lambda: iter(rows)))
    assert tex.count("\\rotatebox{90}") == 2
    typed = typeset(tmp_path, PREAMBLE + latex.NEED + tex + "\n\\end{document}\n")
    assert typed.code == 0, typed.log[-2000:]
    assert overfull(typed.log) == []
    assert _small_words(typed.pdf) == []


def test_a_typewriter_picture_wider_than_the_page_is_set_in_strips(tmp_path) -> None:
    """A picture 200 characters wide (once set in ``\\tiny``, 5 pt): in strips of at most
    92 characters at 7 pt, each strip keeping the axis labels of its rows."""
    rows = [f"{y} | " + "".join("#" if (x + y) % 3 else "." for x in range(200)) for y in range(3)]
    tex = "".join(latex._verbatim(rows))
    assert "\\tiny" not in tex
    pictures = re.findall(r"\\begin\{verbatim\}\n(.*?)\\end\{verbatim\}", tex, re.DOTALL)
    assert len(pictures) == 3  # 196 columns of picture in strips of 88
    for picture in pictures:
        lines = picture.splitlines()
        assert [ln[:4] for ln in lines] == ["0 | ", "1 | ", "2 | "]
        assert max(len(ln) for ln in lines) <= 92
    assert "".join(p.splitlines()[1][4:] for p in pictures) == rows[1][4:]
    typed = typeset(tmp_path, PREAMBLE + latex.NEED + tex + "\n\\end{document}\n")
    assert typed.code == 0, typed.log[-2000:]
    assert overfull(typed.log) == []
