"""check --batch marks every readable file and says why it left another out (attack report
D7, D9, D10, D14): a link out of the folder is never followed, a name that is not UTF-8 or
holds control characters is shown safely, an unreadable table is one row, not the end of the
class; check -o never overwrites the student's own file (D5)."""

from __future__ import annotations

import csv
import io
import os
import shutil
from pathlib import Path

import pytest

from .helpers import run

DATA = Path(__file__).parent / "data" / "check"
QUESTION = ("--", "line", "2", "2", "10", "6")


@pytest.fixture
def klass(tmp_path: Path) -> Path:
    folder = tmp_path / "class"
    folder.mkdir()
    shutil.copy(DATA / "slip.csv", folder / "alice.csv")
    (folder / "bob.csv").write_bytes(b"\x00\x01\x02")  # not a table
    secret = tmp_path / "secret.txt"
    secret.write_text("k,x,y\n0,secret-token-123,1\n")
    (folder / "carol.csv").symlink_to(secret)
    shutil.copy(DATA / "slip.csv", folder / "dan\x1b[31mRED\x1b]0;T\x07.csv")
    shutil.copy(DATA / "slip.csv", os.path.join(os.fsencode(folder), b"caf\xe9.csv"))
    return folder


def _rows(out: str) -> dict[str, list[str]]:
    return {r[0]: r for r in csv.reader(io.StringIO(out))}


def test_every_file_has_a_row_and_the_class_is_marked(klass: Path) -> None:
    r = run("check", "--batch", str(klass), *QUESTION)
    assert r.code == 0, r.err
    rows = _rows(r.out)
    assert rows["alice.csv"][1:3] == ["7", "8"]
    assert rows["bob.csv"][1] == "" and "not marked" in rows["bob.csv"][3]
    assert "link" in rows["carol.csv"][3]
    assert "secret-token" not in r.out + r.err
    assert "\x1b" not in r.out and "\x07" not in r.out
    assert "caf\ufffd.csv" in rows  # the name's byte that is not UTF-8, shown as U+FFFD
    r.out.encode("utf-8")  # every name can be written


@pytest.mark.parametrize("fmt", ["json", "markdown", "plain"])
def test_every_format_writes_the_sheet(klass: Path, fmt: str) -> None:
    r = run("check", "--batch", str(klass), "-f", fmt, *QUESTION)
    assert r.code == 0, r.err
    assert "\x1b" not in r.out and "secret-token" not in r.out


def test_the_output_may_not_be_the_students_file(tmp_path: Path) -> None:
    answer = tmp_path / "alice.csv"
    shutil.copy(DATA / "slip.csv", answer)
    before = answer.read_bytes()
    r = run("check", str(answer), "-o", str(answer), *QUESTION)
    assert r.code == 2 and r.out == "" and len(r.err.strip().splitlines()) == 1
    assert answer.read_bytes() == before


@pytest.mark.parametrize("how", ["same", "dotted", "hard link", "symlink", "new file inside"])
def test_the_batch_output_may_not_be_a_students_file(tmp_path: Path, how: str) -> None:
    """A score sheet named as a submission of the batch (by any name) or written into the
    folder marked is refused before any marking, every submission left as it was (N4)."""
    folder = tmp_path / "cb"
    folder.mkdir()
    shutil.copy(DATA / "slip.csv", folder / "a.csv")
    before = (folder / "a.csv").read_bytes()
    out = {
        "same": folder / "a.csv",
        "dotted": tmp_path / "cb" / ".." / "cb" / "a.csv",
        "hard link": tmp_path / "hl.csv",
        "symlink": tmp_path / "sl.csv",
        "new file inside": folder / "scores.csv",
    }[how]
    if how == "hard link":
        os.link(folder / "a.csv", out)
    elif how == "symlink":
        out.symlink_to(folder / "a.csv")
    r = run("check", "--batch", str(folder), "-o", str(out), *QUESTION)
    assert r.code == 2 and r.out == "" and len(r.err.strip().splitlines()) == 1, r.err
    assert "--output" in r.err
    assert (folder / "a.csv").read_bytes() == before
    assert sorted(p.name for p in folder.iterdir()) == ["a.csv"]


def test_the_batch_output_beside_the_folder_is_written(tmp_path: Path) -> None:
    folder = tmp_path / "cb"
    folder.mkdir()
    shutil.copy(DATA / "slip.csv", folder / "a.csv")
    r = run("check", "--batch", str(folder), "-o", str(tmp_path / "scores.csv"), *QUESTION)
    assert r.code == 0, r.err
    assert _rows((tmp_path / "scores.csv").read_text())["a.csv"][1:3] == ["7", "8"]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_messages_stay_one_short_line(tmp_path: Path) -> None:
    """A heading of 20,000 columns, a JSON number of 5,000 digits: one line naming the file."""
    wide = tmp_path / "wide.csv"
    wide.write_text(",".join(f"c{i}" for i in range(20_000)) + "\n" + ",".join("1" * 20_000) + "\n")
    r = run("check", str(wide), *QUESTION)
    assert r.code == 2 and len(r.err) < 1000 and "wide.csv" in r.err and "more" in r.err
    digits = tmp_path / "digits.json"
    digits.write_text('{"steps": [{"k": 0, "p": ' + "9" * 5000 + ', "pixel": [2, 2]}]}')
    r = run("check", str(digits), *QUESTION)
    assert r.code == 2 and "digits.json" in r.err and len(r.err) < 1000, r.err
    # in scanconv's words (D16), not Python's ("Exceeds the limit (4300 digits) ...")
    assert "a number of 5,000 digits" in r.err and "Exceeds" not in r.err
