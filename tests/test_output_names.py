"""Files a command would lose or block on: two outputs of one answer naming one file, a
question file that is a FIFO or a device, and section names that are no section (attack
report N9, N11, N13). Each is refused before any work: one line, exit 2, nothing written."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from .helpers import run

LINE = ("line", "2", "2", "10", "6")


@pytest.mark.parametrize(
    ("flags", "second"),
    [
        (("-o", "{d}/f.svg", "--svg", "{d}/f.svg"), "--svg"),
        (("--svg", "{d}/s.svg", "--png", "{d}/./s.svg"), "--png"),
        (("-o", "{d}/a.md", "--png", "{d}/sub/../a.md"), "--png"),
    ],
)
def test_two_outputs_of_one_answer_may_not_name_one_file(tmp_path, flags, second):
    (tmp_path / "sub").mkdir()
    r = run(*LINE, *(f.format(d=tmp_path) for f in flags))
    assert r.code == 2 and r.out == "", r.err
    assert r.err.count("\n") == 1 and second in r.err and "the same file as" in r.err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sub"]  # nothing written


def test_an_existing_file_named_twice_is_left_as_it_was(tmp_path):
    target = tmp_path / "f.svg"
    target.write_text("mine")
    r = run(*LINE, "-o", str(target), "--svg", str(target))
    assert r.code == 2 and target.read_text() == "mine"


def test_distinct_outputs_are_all_written(tmp_path):
    r = run(*LINE, "-o", str(tmp_path / "a.md"), "--svg", str(tmp_path / "a.svg"))
    assert r.code == 0, r.err
    assert "<svg" in (tmp_path / "a.svg").read_text()
    assert "(10, 6)" in (tmp_path / "a.md").read_text()


@pytest.mark.parametrize("kind", ["fifo", "device"])
def test_a_question_file_that_is_no_regular_file_is_refused_at_once(tmp_path, kind):
    """Opening a FIFO blocks until a writer comes: it is refused before it is opened (a
    generous per-test timeout in pyproject's addopts turns a block into a failure)."""
    if kind == "fifo":
        path = tmp_path / "ff"
        os.mkfifo(path)
    else:
        path = Path("/dev/zero")
    r = run("sheet", str(path))
    assert r.code == 2 and r.out == ""
    assert r.err.strip().endswith(
        f"{path}: not a regular file (give - to read the questions from standard input)"
    )


@pytest.mark.parametrize("section", ["-1", "+1", "-7", "-14", "0", "9"])
def test_a_signed_or_out_of_range_number_is_not_a_section(section):
    r = run("exam", "-s", section)
    assert r.code == 2 and r.out == "" and "is not a section" in r.err


@pytest.mark.parametrize(
    ("section", "heading"), [("7", "14-mark"), ("14", "14-mark"), ("1", "Scan conversion")]
)
def test_a_section_by_number_or_slug_start(section, heading):
    r = run("exam", "-s", section, "-f", "plain")
    assert r.code == 0, r.err
    assert heading.lower() in r.out.lower()


@pytest.mark.parametrize("argv", [LINE, ("exam", "-s", "1"), ("circle", "5", "-f", "markdown")])
def test_text_is_never_written_under_a_pdf_name(tmp_path, argv):
    out = tmp_path / "a.pdf"
    r = run(*argv, "-o", str(out))
    assert r.code == 2 and r.out == "" and "not a PDF" in r.err and "--pdf" in r.err
    assert not out.exists()


@pytest.mark.external  # pdflatex
@pytest.mark.parametrize("command", ["sheet", "practice"])
def test_a_document_to_a_pdf_name_is_its_pdf(tmp_path, command):
    from .external import tool

    tool("pdflatex")
    out = tmp_path / "key.pdf"
    if command == "sheet":
        q = tmp_path / "q.txt"
        q.write_text("line 2 2 10 6\n")
        r = run("sheet", str(q), "-o", str(out))
    else:
        r = run("practice", "-t", "line", "-n", "1", "--seed", "1", "-o", str(out))
    assert r.code == 0, r.err
    assert r.out == "" and out.read_bytes().startswith(b"%PDF-")
