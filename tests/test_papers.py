"""The past-paper bank (scanconv/data/papers.txt): every question answers, and the numbers the
papers ask for come out."""

from __future__ import annotations

import json
from pathlib import Path

import scanconv.data

from .helpers import run

BANK = Path(scanconv.data.__file__).with_name("papers.txt")


def test_every_question_of_the_bank_answers(tmp_path: Path) -> None:
    out = tmp_path / "bank.json"
    r = run("sheet", str(BANK), "-f", "json", "-o", str(out))
    assert r.code == 0, r.err
    doc = json.loads(out.read_text())
    assert len(doc["questions"]) == 7 + 3
    assert doc["total_marks"] == 10 + 10 + 10 + 8 + 8 + 4 + 4 + 8 + 4 + 4


def test_every_question_names_its_source() -> None:
    """Each question's wording (or the section it is in) names a paper or says it is a
    worked example, and the section names a university or a worked example."""
    wording, section = "", ""
    for line in BANK.read_text().splitlines():
        if line.startswith("section:"):
            section = line
        elif line.startswith(">"):
            wording = line
        elif line and not line.startswith(("#", "title:")):
            said = wording + " " + section
            assert any(k in said for k in ("MU ", "VTU ", "SPPU ", "worked example")), line


def test_the_published_clipping_and_font_answers_come_out() -> None:
    """Rosetta Code's clipped polygon (its ten points, with (100, 200) on the edge kept too);
    font8x8's 'A' as 0x0C 0x1E 0x33 0x33 0x3F 0x33 0x33 0x00 (lsb first); the raw 8 x 16
    font's 4096 bytes and 'A' at 0x410."""
    r = run("sheet", str(BANK), "-f", "plain")
    assert r.code == 0, r.err
    assert "(100, 350/3), (125, 100), (275, 100), (300, 350/3)" in r.out
    assert "(175, 300), (125, 300), (100, 250), (100, 200)" in r.out
    hexes = [line.split()[3] for line in r.out.splitlines() if line.strip()[:1].isdigit()
             and len(line.split()) == 5 and line.split()[3].startswith("0x")]  # fmt: skip
    assert hexes == ["0x0C", "0x1E", "0x33", "0x33", "0x3F", "0x33", "0x33", "0x00"]
    assert "4096 bytes" in r.out and "65 x 128/8 = 1040 (0x410)" in r.out
