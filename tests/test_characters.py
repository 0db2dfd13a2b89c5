"""Character generation (scanconv.algorithms.characters, scanconv.answers.primitives.characters)."""

from __future__ import annotations

from itertools import pairwise

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.characters import (
    FONT_5X7,
    STROKES,
    draw_bitmap,
    draw_strokes,
    row_bytes,
    storage,
)
from scanconv.answers.primitives.characters import (
    bitmap_solution,
    font_storage_solution,
    stroke_solution,
)
from scanconv.core.checks import InputError


def test_font_storage_by_hand() -> None:
    # 128 glyphs of 5 x 7: rows padded to a byte: 7 bytes a glyph = 896 bytes; packed: 35 bits
    # a glyph, 4480 bits = 560 bytes; by columns: 5 bytes a glyph = 640 bytes
    assert storage(128, 5, 7).total_bits == 896 * 8
    assert storage(128, 5, 7, "bits").total_bits == 560 * 8
    assert storage(128, 5, 7, "columns").total_bits == 640 * 8
    # 256 glyphs of 9 x 14 (VGA text): rows of 2 bytes: 28 bytes a glyph = 7168 bytes
    assert storage(256, 9, 14).total_bits == 7168 * 8
    assert font_storage_solution(128, 5, 7).data["bits"] == 7168


def test_every_glyph_is_5_by_7() -> None:
    assert all(len(g) == 7 and all(len(r) == 5 and set(r) <= {"0", "1"} for r in g)
               for g in FONT_5X7.values())  # fmt: skip


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=60)
@given(char=st.sampled_from(sorted(FONT_5X7)), scale=st.integers(1, 4), x0=st.integers(-5, 5))
def test_a_scaled_bitmap_has_scale_squared_pixels_per_bit(char, scale, x0) -> None:
    rows = FONT_5X7[char]
    steps = list(draw_bitmap(rows, x0, 0, scale))
    pixels = [p for s in steps for p in s.extra[2]]
    bits = sum(r.count("1") for r in rows)
    assert len(steps) == bits and len(set(pixels)) == bits * scale * scale
    # the top row's set bits land on the top band of pixels
    top = max(p[1] for p in pixels)
    assert top == (len(rows) * scale) - 1


def test_bitmap_by_hand() -> None:
    # "L" at scale 1: the left column (7 bits) and the bottom row (4 more): 11 pixels
    sol = bitmap_solution("L")
    assert len(list(sol.pixels())) == 11
    assert (0, 6) in set(sol.pixels()) and (4, 0) in set(sol.pixels())


@pytest.mark.parametrize("char", sorted(STROKES))
def test_strokes_are_connected_lines(char) -> None:
    for s in draw_strokes(char, 0, 0, 2):
        (a, b, c, d), pixels = s.extra
        assert pixels[0] in ((a, b), (c, d)) and pixels[-1] in ((a, b), (c, d))
        for p, q in pairwise(pixels):
            assert max(abs(p[0] - q[0]), abs(p[1] - q[1])) == 1


def test_stroke_answer() -> None:
    sol = stroke_solution("T", scale=2)
    assert sol.data["segments"] == [[0, 12, 8, 12], [4, 12, 4, 0]]


@pytest.mark.parametrize(
    ("call", "param"),
    [
        (lambda: storage(0, 5, 7), "count"),
        (lambda: storage(1, 5, 7, "diagonal"), "packing"),
        (lambda: bitmap_solution("?"), "char"),
        (lambda: bitmap_solution("x", rows=["10", "1"]), "rows"),
        (lambda: stroke_solution("O"), "char"),
        (lambda: stroke_solution("T", scale=99), "scale"),
    ],
)
def test_bad_input_names_its_parameter(call, param) -> None:
    with pytest.raises(InputError) as info:
        call()
    assert info.value.param == param


def test_the_glyph_as_bytes_by_hand() -> None:
    """The notes' 5 x 7 'A', each row padded with 0 on the right to a byte, the leftmost
    pixel the most significant bit: 01110000 = 64 + 32 + 16 = 112 = 0x70, 10001000 = 128 + 8
    = 136 = 0x88, 11111000 = 248 = 0xF8."""
    sol = bitmap_solution("A")
    assert sol.data["bytes"] == [[0x70], [0x88], [0x88], [0xF8], [0x88], [0x88], [0x88]]
    table = sol.tables[0]
    assert [c.role for c in table.columns] == ["label", "given", "working", "answer", "answer"]
    first = next(iter(table.rows()))
    assert first == (0, "01110", "01110000", "0x70", "112")
    # the least significant bit first: 01110 is 0 + 2 + 4 + 8 = 14
    assert bitmap_solution("A", bit_order="lsb").data["bytes"][0] == [14]


@settings(deadline=None, max_examples=200)
@given(
    rows=st.lists(st.text("01", min_size=1, max_size=20), min_size=1, max_size=8),
    order=st.sampled_from(["msb", "lsb"]),
)
def test_the_bytes_hold_each_pixel_once(rows, order) -> None:
    """Byte j of a row holds pixels 8j .. 8j + 7, pixel p at the weight 2^(7 - p) (msb) or
    2^p (lsb), the padding 0; and the bytes read back give the row."""
    width = max(len(r) for r in rows)
    glyph = [r.ljust(width, "0") for r in rows]
    for r, packed in zip(glyph, row_bytes(glyph, order), strict=True):
        assert len(packed.values) == -(-width // 8)
        for j, value in enumerate(packed.values):
            pixels = [int(r[8 * j + p]) if 8 * j + p < width else 0 for p in range(8)]
            weights = [2 ** (7 - p) if order == "msb" else 2**p for p in range(8)]
            assert value == sum(b * w for b, w in zip(pixels, weights, strict=True))
        back = "".join(
            (format(v, "08b") if order == "msb" else format(v, "08b")[::-1]) for v in packed.values
        )
        assert back[:width] == r


def test_the_font_table_by_hand() -> None:
    """128 glyphs of 8 x 8 from 0x1000: 'A' (code 65) is glyph 65, at 0x1000 + 65 x 8 =
    0x1208; 96 glyphs of 5 x 7 packed bits from the space (code 32): 'A' is glyph 33, at bit
    33 x 35 = 1155 = byte 144, bit 3."""
    sol = font_storage_solution(128, 8, 8, char="A", base=0x1000)
    assert sol.derived[-1].value == 0x1208
    rows = list(sol.tables[-1].rows())
    assert (65, "'A'", "4096 + 65*64/8", "4616 (0x1208)") in rows
    assert rows[-1][0] == 127  # the last glyph
    packed = font_storage_solution(96, 5, 7, "bits", char="A", first=32)
    assert packed.derived[-2].value == 33
    assert packed.derived[-1].text.endswith("144 (0x90), bit 3")


@settings(deadline=None, max_examples=200)
@given(
    count=st.integers(1, 300),
    w=st.integers(1, 24),
    h=st.integers(1, 24),
    packing=st.sampled_from(["rows", "columns", "bits"]),
    base=st.integers(0, 1 << 16),
    data=st.data(),
)
def test_a_glyphs_address_inverts_to_the_glyph(count, w, h, packing, base, data) -> None:
    """Each glyph starts where the one before ends: (address - base) / bytes a glyph is the
    glyph's number (bits, with packed bits), and the font ends at base + the font's size."""
    index = data.draw(st.integers(0, count - 1))
    sol = font_storage_solution(count, w, h, packing, char=chr(index), base=base)
    per = sol.data["per_glyph"]
    address = sol.derived[-1].value
    bit = int(sol.derived[-1].text.rsplit("bit ", 1)[1]) if ", bit " in sol.derived[-1].text else 0
    assert (address * 8 + bit - base * 8) == index * per
    assert base * 8 + count * per == base * 8 + sol.data["bits"]


@pytest.mark.parametrize(
    ("kwargs", "param"),
    [({"char": "é"}, "char"), ({"char": "A", "first": 66}, "char"), ({"base": -1}, "base")],
)
def test_a_glyph_outside_the_font_is_refused(kwargs, param) -> None:
    with pytest.raises(InputError) as err:
        font_storage_solution(96, 5, 7, first=kwargs.pop("first", 32), **kwargs)
    assert err.value.param == param
