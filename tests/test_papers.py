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
    assert len(doc["questions"]) == 12
    assert doc["total_marks"] == 10 + 10 + 10 + 8 + 8 + 4 + 4 + 4 + 2 + 2 + 2 + 2
    assert doc["questions"][11]["answer"]["index"] == 1016  # ISRO CS 2014
    lookup = doc["questions"][7]["answer"]
    assert lookup["lookups"] == [1] and lookup["output"] == [1]
    # Stanford CS248 1996: 300 dpi at 10, 60, 150 cells per inch -> 901, 26, 5 levels
    assert [q["answer"]["levels"] for q in doc["questions"][8:11]] == [901, 26, 5]


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
