"""Frame-buffer arithmetic (scanconv.answers.image.framebuffer) against the textbook exercises
(Hearn & Baker, Computer Graphics C Version, 2nd ed., exercises 2-1 to 2-7), worked by hand."""

from __future__ import annotations

from fractions import Fraction

import pytest

from scanconv.answers.image.framebuffer import framebuffer_solution
from scanconv.core.checks import InputError


def _value(sol, key):
    return {q.key: q.value for q in sol.derived}[key]


@pytest.mark.parametrize(
    ("w", "h", "bits", "nbytes"),
    [
        (640, 480, 12, 460_800),  # 640 * 480 * 12 / 8
        (640, 480, 24, 921_600),
        (1280, 1024, 12, 1_966_080),
        (1280, 1024, 24, 3_932_160),
        (2560, 2048, 24, 15_728_640),
    ],
)
def test_frame_buffer_sizes(w, h, bits, nbytes) -> None:
    sol = framebuffer_solution(w, h, bits)
    assert _value(sol, "size_bits") == nbytes * 8
    rows = dict(sol.tables[0].rows())
    assert rows["bytes"] == str(nbytes)


@pytest.mark.parametrize(
    ("w", "h", "bits", "rate", "seconds"),
    [
        (640, 480, 12, 10**5, Fraction(36864, 1000)),  # 3,686,400 bits / 1e5 = 36.864 s
        (1280, 1024, 24, 10**6, Fraction(3145728, 100000)),  # 31,457,280 / 1e6 = 31.45728 s
        (640, 480, 24, 10**5, Fraction(73728, 1000)),
    ],
)
def test_load_time(w, h, bits, rate, seconds) -> None:
    assert _value(framebuffer_solution(w, h, bits, rate=rate), "load_time") == seconds


def test_pixel_access_time_non_interlaced_and_interlaced() -> None:
    # 1280 x 1024 at 60 frames/s: 78,643,200 pixels/s, 1/78,643,200 s ~ 12.7 ns a pixel
    sol = framebuffer_solution(1280, 1024, 8, refresh=60)
    assert _value(sol, "pixel_rate") == 78_643_200
    assert _value(sol, "pixel_time") == Fraction(1, 78_643_200)
    # interlaced at 60 fields/s: 30 whole frames/s, each pixel twice as long
    sol = framebuffer_solution(1280, 1024, 8, refresh=60, interlaced=True)
    assert _value(sol, "frames_per_second") == 30
    assert _value(sol, "pixel_time") == Fraction(1, 39_321_600)


def test_look_up_table() -> None:
    # 8 bits per pixel into a LUT of 24-bit entries: 256 entries, 6144 bits, 2^24 colours
    sol = framebuffer_solution(512, 512, 8, lut=24)
    assert _value(sol, "lut_entries") == 256
    assert _value(sol, "lut_bits") == 256 * 24
    assert _value(sol, "palette") == 2**24
    assert _value(sol, "colours") == 256


@pytest.mark.parametrize(
    ("kwargs", "param"),
    [
        ({"width": 0, "height": 480, "bits": 8}, "width"),
        ({"width": 640, "height": Fraction(961, 2), "bits": 8}, "height"),
        ({"width": 640, "height": 480, "bits": 65}, "bits"),
        ({"width": 640, "height": 480, "bits": 8, "rate": 0}, "rate"),
        ({"width": 640, "height": 480, "bits": 8, "lut": 100}, "lut"),
    ],
)
def test_bad_input_names_its_parameter(kwargs, param) -> None:
    with pytest.raises(InputError) as info:
        framebuffer_solution(**kwargs)
    assert info.value.param == param
