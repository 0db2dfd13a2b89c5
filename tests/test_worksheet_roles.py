"""A worksheet fills in what a question gives and leaves what it asks: each row's label and
given values (a point's name and coordinates, the points a transform is applied to) are
printed, every answer and working cell is left blank (the P1/P2 row labels were once
empty)."""

from __future__ import annotations

import re

import pytest

from .helpers import run

QUESTIONS = "clip line 7 9 11 4 --window 4 4 10 8\ntransform 0 0 4 0 4 3 --rotate 90 --about 2 1\n"


@pytest.fixture
def worksheet(tmp_path):
    def make(fmt: str) -> str:
        q = tmp_path / "q.txt"
        q.write_text(QUESTIONS)
        r = run("sheet", str(q), "--worksheet", "-f", fmt)
        assert r.code == 0, r.err
        return r.out

    return make


def test_the_plain_worksheet_gives_the_points_and_asks_the_rest(worksheet):
    text = worksheet("plain")
    assert re.search(r"^\s*P1\s+\(7, 9\)\s+_+\s+_+", text, re.M)  # the code bits asked
    assert re.search(r"^1\s+P1 \(7, 9\)\s+_+", text, re.M)  # the end point given, code asked
    assert re.search(r"^\s*P3\s+\(4, 3\)\s+_+\s+_+\s+_+$", text, re.M)
    for answer in ("1000", "7.8", "5.25", "(3, -1)", "= 3"):
        assert answer not in text


def test_the_markdown_worksheet_too(worksheet):
    text = worksheet("markdown")
    assert re.search(r"\|\s*P2\s*\|\s*\(11, 4\)\s*\|\s*\|", text)
    assert "7.8" not in text and "0010" not in text
