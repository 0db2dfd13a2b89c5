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
