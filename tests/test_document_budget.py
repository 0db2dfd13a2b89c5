"""A document is weighed by what its outputs hold: a GIFT quiz (each blank a question carrying
the stem and the working: attack report N6, 373 MB for a sheet the budget accepted) and a PDF
(pdflatex's passes: N15, five minutes and then exit 1) are refused before they are written,
with the line of the question that takes the total past the limit."""

from __future__ import annotations

import pytest

from .helpers import python_calls, run


def _sheet(tmp_path, n: int):
    """n questions ``line 0 0 79 k``: 80 steps each (one row per x from 0 to 79)."""
    path = tmp_path / "q.txt"
    path.write_text("".join(f"line 0 0 79 {i % 40 + 1}\n" for i in range(n)))
    return path


def _first_over(limit: int, rows_each: int = 80) -> int:
    """The question (line) whose rows take the running total past ``limit``."""
    return limit // rows_each + 1


@pytest.mark.slow  # 126 questions answered before the refusal
def test_a_gift_quiz_is_weighed_by_its_blanks(tmp_path):
    q = _sheet(tmp_path, 1000)
    out = tmp_path / "quiz.gift"
    r, calls = python_calls(run, "sheet", str(q), "-o", str(out))
    assert r.code == 2 and r.out == "" and not out.exists()
    assert r.err.count("\n") == 1
    line = _first_over(10_000)  # 126: 126 x 80 = 10,080 rows
    assert f"q.txt:{line}:" in r.err and "10,080 table rows" in r.err
    assert "gift" in r.err and "at most 10,000" in r.err
    assert calls < 3_000_000  # writing it took hundreds of millions


@pytest.mark.slow  # 10,080 rows written
@pytest.mark.parametrize("fmt", ["markdown", "moodle"])
def test_the_same_sheet_in_another_format_is_weighed_by_the_document_limit(tmp_path, fmt):
    """125 questions (10,000 rows) are a whole GIFT quiz; the same file with one more is
    refused only as GIFT."""
    q = _sheet(tmp_path, 126)
    out = tmp_path / ("s.md" if fmt == "markdown" else "s.xml")
    r = run("sheet", str(q), "-o", str(out), "-f", fmt)
    assert r.code == 0, r.err
    assert out.stat().st_size > 0


@pytest.mark.slow  # a 7 MB quiz file
def test_a_gift_quiz_at_the_limit_is_written(tmp_path):
    q = _sheet(tmp_path, 125)
    out = tmp_path / "quiz.gift"
    r = run("sheet", str(q), "-o", str(out))
    assert r.code == 0, r.err
    text = out.read_text()
    assert text.count("::") // 2 > 125 * 80  # a question per blank


@pytest.mark.slow  # 4,000 rows written without --pdf
def test_a_pdf_is_weighed_before_pdflatex_runs(tmp_path, monkeypatch):
    """Refused with the line of the question, no file, and pdflatex never started."""
    import subprocess

    started = []
    real = subprocess.run

    def spy(*args, **kwargs):
        started.append(args)
        return real(*args, **kwargs)

    monkeypatch.setattr(subprocess, "run", spy)
    q = _sheet(tmp_path, 50)
    pdf, md = tmp_path / "p.pdf", tmp_path / "p.md"
    r = run("sheet", str(q), "--pdf", str(pdf), "-o", str(md))
    assert r.code == 2 and r.out == "" and r.err.count("\n") == 1
    assert f"q.txt:{_first_over(3_000)}:" in r.err and "PDF" in r.err  # 38 x 80 = 3,040
    assert not pdf.exists() and not md.exists() and started == []
    r = run("sheet", str(q), "-o", str(md))  # without --pdf: the document's own limit
    assert r.code == 0, r.err
