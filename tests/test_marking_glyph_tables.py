"""``check`` marks a character's other tables (scanconv.marking.table_models.GlyphBytesTable
and FontTableTable): a glyph packed into bytes row by row (each row's bits stand alone, its
hexadecimal and decimal follow from the row's own bits as written, in any usual spelling) and
a font table (each glyph's number, and its address from the row's own number). The students'
tables are written here by hand, the numbers in each docstring, not taken from scanconv."""

from __future__ import annotations

from pathlib import Path

from .helpers import run, run_process

L_Q = ("char", "bitmap", "L")
L_BYTES = """i,pixels,byte bits,hex,decimal
0,10000,10000000,0x80,128
1,10000,10000000,0x80,128
2,10000,10000000,0x80,128
3,10000,10000000,0x80,128
4,10000,10000000,0x80,128
5,10000,10000000,0x80,128
6,11111,11111000,0xF8,248
"""
FONT_Q = ("char", "storage", "96", "5", "7", "--char", "A", "--first", "32", "--base", "0x1000")
FONT = """glyph,character,byte address
0,' ',4096
1,'!',4103
2,'"',4110
33,'A',4327
95,code 127,4761
"""


def _check(tmp_path: Path, text: str, question: tuple[str, ...]) -> dict:
    import json

    path = tmp_path / "s.csv"
    path.write_text(text, encoding="utf-8")
    r = run("check", str(path), "--format", "json", "--", *question)
    assert r.code == 0 and r.err == "", r.err
    return json.loads(r.out)


def test_glyph_bytes_right_in_any_spelling(tmp_path: Path) -> None:
    """The 5 x 7 L, msb first: six rows 10000 -> 1000 0000 = 0x80 = 128, the last 11111 ->
    1111 1000 = 0xF8 = 248; hexadecimal as 80, 80h, $80 or 0x80 alike, bits in nibbles."""
    assert _check(tmp_path, L_BYTES, L_Q)["score"] == 7
    spelled = L_BYTES.replace("0,10000,10000000,0x80", "0,10000,1000 0000,80h")
    spelled = spelled.replace("1,10000,10000000,0x80", "1,10000,10000000,$80")
    spelled = spelled.replace("0xF8", "f8")
    data = _check(tmp_path, spelled, L_Q)
    assert (data["score"], data["out_of"]) == (7, 7), data["first_error"]


def test_glyph_bytes_a_slip_in_the_bits_is_charged_once(tmp_path: Path) -> None:
    """The last row's bits written 11110000 (a pixel dropped) and then read right as 0xF0 =
    240: the row is wrong for its bits only, the hex and decimal follow from them; a hex that
    is not the row's own bits (0x80 read as 0x08) is wrong."""
    slip = L_BYTES.replace("6,11111,11111000,0xF8,248", "6,11111,11110000,0xF0,240")
    data = _check(tmp_path, slip, L_Q)
    assert (data["score"], data["out_of"]) == (6, 7)
    assert data["first_error"].startswith("Row 7") and "byte bits wrong" in data["first_error"]
    assert "hex" not in data["first_error"].split(";")[0]
    misread = L_BYTES.replace("2,10000,10000000,0x80,128", "2,10000,10000000,0x08,128")
    data = _check(tmp_path, misread, L_Q)
    assert data["score"] == 6 and data["first_error"].startswith("Row 3 (")
    assert "hex wrong" in data["first_error"]


def test_glyph_bytes_lsb_first(tmp_path: Path) -> None:
    """lsb first the L's rows read backwards: 10000 -> 0000 0001 = 0x01 = 1, 11111 -> 0001
    1111 = 0x1F = 31; the msb table is then wrong in every row."""
    lsb = (L_BYTES.replace("10000000,0x80,128", "00000001,0x01,1")
           .replace("11111000,0xF8,248", "00011111,0x1F,31"))  # fmt: skip
    question = (*L_Q, "--bit-order", "lsb")
    assert _check(tmp_path, lsb, question)["score"] == 7
    assert _check(tmp_path, L_BYTES, question)["score"] == 0


def test_font_table_addresses_follow_the_students_glyph_number(tmp_path: Path) -> None:
    """96 glyphs of 5 x 7 in whole-byte rows (7 bytes a glyph) from 0x1000 = 4096, the first
    the space (code 32): 'A' is glyph 65 - 32 = 33 at 4096 + 33 x 7 = 4327, the last (95) at
    4761. A student who takes 'A' as glyph 34 and puts it at 4096 + 34 x 7 = 4334 is wrong once,
    for the number; an address not the row's own number's is wrong; hexadecimal addresses
    are read as the numbers they are."""
    assert _check(tmp_path, FONT, FONT_Q)["score"] == 5
    slip = _check(tmp_path, FONT.replace("33,'A',4327", "34,'A',4334"), FONT_Q)
    assert (slip["score"], slip["out_of"]) == (4, 5)
    assert (
        slip["first_error"].startswith("Row 4") and "byte address wrong" not in slip["first_error"]
    )
    wrong = _check(tmp_path, FONT.replace("33,'A',4327", "33,'A',4328"), FONT_Q)
    assert wrong["score"] == 4 and "byte address" in wrong["first_error"]
    hexed = FONT.replace("4096\n", "0x1000\n").replace("4327", "0x10E7")
    assert _check(tmp_path, hexed, FONT_Q)["score"] == 5


def test_the_packings_table_is_still_chosen_by_its_headings(tmp_path: Path) -> None:
    storage = "packing,glyph,bits,bytes\nrows,56,5376,672\ncolumns,40,3840,480\nbits,35,3360,420\n"
    assert _check(tmp_path, storage, FONT_Q)["score"] == 3


def test_check_in_a_process(tmp_path: Path) -> None:
    """``scanconv check FILE -- QUESTION`` as a student runs it: a score on stdout, exit 0."""
    path = tmp_path / "bytes.csv"
    path.write_text(L_BYTES.replace("0xF8,248", "0xF8,250"), encoding="utf-8")
    r = run_process("check", str(path), "--", *L_Q)
    assert r.code == 0 and "6/7" in r.out.replace(" ", ""), (r.out, r.err)


def test_any_cells_are_marked_or_refused_in_one_line(tmp_path: Path) -> None:
    """Whatever a student writes in these columns, a score or one line naming the problem."""
    odd = ["", "-", "0x", "zz", "1/0", "0xfffffffff", "1e30", "nan", "0001 1111 1", "$", "h"]
    for n, cell in enumerate(odd):
        for text, question in (
            (L_BYTES.replace("0x80,128", f"{cell},{cell}", 1), L_Q),
            (L_BYTES.replace("10000000,0x80", f"{cell},0x80", 1), L_Q),
            (FONT.replace("33,'A',4327", f"{cell},'A',{cell}"), FONT_Q),
        ):
            path = tmp_path / f"s{n}.csv"
            path.write_text(text, encoding="utf-8")
            r = run("check", str(path), "--", *question)
            assert r.code in (0, 2) and "Traceback" not in r.err, (cell, r.err)
            assert r.code == 0 or (r.out == "" and len(r.err.strip().splitlines()) == 1)
