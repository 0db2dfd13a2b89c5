"""A worksheet printed: every word at 7 pt or more, read back from the PDF with
``pdftotext -bbox`` (the symmetry and Cohen-Sutherland headings were once set at about
2 pt), and the row labels and given values filled in."""

from __future__ import annotations

import re
import subprocess

import pytest

from scanconv.cli.sheet import answer_questions, read_questions
from scanconv.render.documents.sheet import sheet_document

from .external import tool, typeset

pytestmark = [pytest.mark.external, pytest.mark.slow]

QUESTIONS = (
    "clip line 7 9 11 4 --window 4 4 10 8\n"
    "circle 5\n"
    "ellipse 8 6\n"
    "transform 0 0 4 0 4 3 --rotate 90 --about 2 1\n"
)


def _words(pdf) -> list[tuple[str, float, float]]:
    """Each word of the PDF with its box's width and height (pt)."""
    out = subprocess.run(
        [tool("pdftotext"), "-bbox", str(pdf), "-"], capture_output=True, text=True, check=True
    ).stdout
    found = []
    for m in re.finditer(
        r'<word xMin="([\d.]+)" yMin="([\d.]+)" xMax="([\d.]+)" yMax="([\d.]+)">(.*?)</word>', out
    ):
        x0, y0, x1, y1 = map(float, m.groups()[:4])
        found.append((m.group(5), x1 - x0, y1 - y0))
    return found


def test_every_word_of_a_worksheet_is_legible(tmp_path):
    sheet = read_questions(QUESTIONS, "q.txt")
    answered = answer_questions(sheet.questions, sheet.source)
    tex = sheet_document(sheet, answered, "worksheet", "latex", standalone=True)
    done = typeset(tmp_path, tex, passes=3)
    assert done.code == 0, done.log[-2000:]
    words = _words(done.pdf)
    assert len(words) > 100
    small = []
    for word, w, h in words:
        if len(word) < 3 or not re.search("[A-Za-z]", word):
            continue  # a digit or a subscript: its box says little about its size
        size = w if h > w else h  # a heading on its side: its box's width is its height
        if size < 6.0:  # pdftotext boxes 7 pt text (a subscript of 10 pt) at about 6.2 pt
            small.append((word, round(size, 1)))
    assert small == []
    text = " ".join(w for w, _, _ in words)
    assert "P1" in text and "(7," in text  # the given points are printed
