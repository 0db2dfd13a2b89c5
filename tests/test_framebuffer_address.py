"""A pixel's address in the frame buffer (and the pixel at an address), the refresh time's
share in retrace, the frame rate a pixel time gives and a screen's resolution from its inches:
published worked examples and properties against formulas written here."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from scanconv.algorithms import framebuffer as fb
from scanconv.answers.image.framebuffer import framebuffer_solution
from scanconv.core.checks import InputError


def test_the_hypergraph_example() -> None:
    # G. S. Owen, SIGGRAPH HyperGraph, "Setting a pixel": 640 x 480, 8 bits a pixel,
    # addr(340, 150) = addr(0, 0) + 150 * 640 + 340 = base + 96,340.
    data = framebuffer_solution(640, 480, 8, pixel=(340, 150), base=5000).data
    assert data["address"] == 5000 + 96340 and data["index"] == 96340


def test_the_isro_2014_question() -> None:
    # ISRO Scientist CS 2014 (testbook.com's solution): a frame buffer addressed in row-major
    # order, pixels (0, 0) to (100, 100), one bit a pixel, from 0: pixel (6, 10) is at
    # 10 * 101 + 6 = 1016.
    data = framebuffer_solution(101, 101, 1, pixel=(6, 10)).data
    assert data["index"] == 1016
    assert framebuffer_solution(101, 101, 1, address=Fraction(1016, 8)).data["pixel_at"] == (6, 10)


def test_hearn_and_bakers_retrace_exercise() -> None:
    # Hearn & Baker's chapter-2 exercise: 1280 x 1024, non-interlaced at 60 Hz, horizontal
    # retrace 5 us, vertical retrace 500 us: (1024 * 5 us + 500 us) * 60 = 0.3372 of the time.
    data = framebuffer_solution(
        1280, 1024, 1, refresh=60, hretrace=Fraction(5, 10**6), vretrace=Fraction(5, 10**4)
    ).data
    assert data["retrace_fraction"] == Fraction(3372, 10000)
    assert data["line_time"] == Fraction(1, 1024 * 60)


def test_the_xfree86_fbdev_timing_example() -> None:
    # XFree86 3.3.6 fbdev HOWTO, section 6: a 28.37516 MHz dot clock (35.242 ns a pixel),
    # 640 x 480, horizontal retrace 272 pixel times, vertical retrace 49 lines of 912 pixel
    # times: (480 + 49) * 32.141 us = 17.002 ms, about 58.815 Hz.
    tp = 1 / Fraction("28.37516e6")
    data = framebuffer_solution(
        640, 480, 8, pixel_time=tp, hretrace=272 * tp, vretrace=49 * 912 * tp
    ).data
    assert data["frame_rate"] == Fraction("28.37516e6") / (529 * 912)
    assert round(float(data["frame_rate"]), 3) == 58.815


def test_resolution_from_a_screens_inches() -> None:
    # Hearn & Baker's 8 x 10 inch screen at 100 pixels per inch, 6 bits a pixel:
    # 1000 x 800 pixels, 4,800,000 bits = 600,000 bytes.
    data = framebuffer_solution(10, 8, 6, dpi=100).data
    assert data["resolution"] == (1000, 800) and data["pixel_count"] == 800000
    assert data["size_bits"] == 4800000


def _by_formula(x, y, w, h, b, base, major, row0, count) -> Fraction:
    """The byte address as the published form writes it, each convention spelt out."""
    c = int(count)
    col, row = x - c, y - c
    if row0 == "bottom":
        row = h - 1 - row
    k = row * w + col if major == "row" else col * h + row
    return base + Fraction(k * b, 8)


@st.composite
def _buffers(draw):
    w, h = draw(st.integers(1, 300)), draw(st.integers(1, 300))
    count = draw(st.sampled_from(["0", "1"]))
    c = int(count)
    x, y = draw(st.integers(c, w - 1 + c)), draw(st.integers(c, h - 1 + c))
    conventions = {
        "major": draw(st.sampled_from(["row", "column"])),
        "row0": draw(st.sampled_from(["top", "bottom"])),
        "count": count,
    }
    return (
        x,
        y,
        w,
        h,
        draw(st.sampled_from([1, 2, 4, 6, 8, 12, 16, 24, 32])),
        draw(st.integers(0, 10**6)),
        conventions,
    )


@given(_buffers())
def test_a_pixels_address_is_the_formula_and_inverts_to_the_pixel(case) -> None:
    x, y, w, h, b, base, conventions = case
    a = fb.address(x, y, w, h, b, base, **conventions)
    assert a.byte == _by_formula(x, y, w, h, b, base, *conventions.values())
    assert base <= a.byte < base + Fraction(w * h * b, 8)
    assert fb.pixel_of(a.byte, w, h, b, base, **conventions) == (x, y)


@given(
    w=st.integers(1, 2000),
    h=st.integers(1, 2000),
    f=st.integers(25, 120),
    th=st.integers(0, 5),
    tv=st.integers(0, 500),
)
def test_the_times_per_line_and_pixel_make_up_the_frame(w, h, f, th, tv) -> None:
    """With retraces t_h, t_v (microseconds): H lines of W pixel times and t_h, then t_v, take
    1/f exactly; the pixel time found gives back the frame rate."""
    t_h, t_v = Fraction(th, 10**6), Fraction(tv, 10**6)
    if (h * t_h + t_v) * f >= 1:
        return
    data = framebuffer_solution(w, h, 1, refresh=f, hretrace=t_h or None, vretrace=t_v or None).data
    if th or tv:
        tp = data["pixel_time_traced"]
        assert h * (w * tp + t_h) + t_v == Fraction(1, f)
        assert data["retrace_fraction"] == (h * t_h + t_v) * f
        back = framebuffer_solution(
            w, h, 1, pixel_time=tp, hretrace=t_h or None, vretrace=t_v or None
        ).data
        assert back["frame_rate"] == f
    else:
        assert data["pixel_time"] * w * h * f == 1


@pytest.mark.parametrize(
    ("kwargs", "param"),
    [
        ({"pixel": (640, 0)}, "pixel"),
        ({"pixel": (0, 0), "conventions": {"count": "1"}}, "pixel"),
        ({"address": Fraction(1, 2)}, "address"),
        ({"address": 640 * 480}, "address"),
        ({"refresh": 60, "vretrace": Fraction(1, 50)}, "hretrace"),
        ({"refresh": 60, "hretrace": Fraction(1, 10**6), "interlaced": True}, "interlaced"),
        ({"conventions": {"major": "diagonal"}, "pixel": (0, 0)}, "major"),
    ],
)
def test_bad_questions_name_their_parameter(kwargs, param) -> None:
    with pytest.raises(InputError) as info:
        framebuffer_solution(640, 480, 8, **kwargs)
    assert info.value.param == param
