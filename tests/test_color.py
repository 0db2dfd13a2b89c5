"""``scanconv color``: conversions checked against published examples, round trips, the
true-colour breakdown and bad input.

Published examples (each test names its source):

* CMY: Isaac Leif, "RGB to CMY conversions" (slides, slideshare.net/IsaacLeif/rgb-to-cmy-
  conversions): green (0, 255, 0) -> CMY (1, 0, 1); Valspar "Blueprint" (42, 88, 159) ->
  (0.835, 0.655, 0.376).
* HSV, HSI and BT.601 luma: Wikipedia, "HSL and HSV", section "Examples" (the table of 19
  colours with H, H2, V, I, Y'601, S_HSV, S_HSI). Its H2 column is the hue of the chromaticity
  plane, which is what Gonzalez and Woods' arc-cosine formula gives (HSI's H). The table's
  RGB values are 3-decimal floats and its hex codes are those rounded to 8 bits, so a row
  is checked from its hex code to within the table's rounding (0.01 for a component, half
  a degree for a hue).
* HSI: Gonzalez and Woods, Digital Image Processing, section 6.2 (RGB to HSI); the CodeGuru
  thread "Implementing an Algorithm, Math Error" (2009) works pure green (0, 255, 0) to
  H = 120 degrees, S = 1, I = 85 on the 0..255 scale (1/3 on the unit scale).
* HSV formula with max, min and the 60-degree sectors: Smith, "Color gamut transform pairs"
  (SIGGRAPH 1978), as tabulated on the Wikipedia page above.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

import scanconv
from scanconv.algorithms import color as c
from scanconv.answers.image.color import color_solution

from .helpers import assert_refused, run

F = Fraction


def _unit(hexcode: str) -> tuple[Fraction, Fraction, Fraction]:
    r, g, b = (int(hexcode[i : i + 2], 16) for i in (1, 3, 5))
    return F(r, 255), F(g, 255), F(b, 255)


# --- published examples ---------------------------------------------------------------------------


def test_cmy_examples_of_leif_slides() -> None:
    assert c.rgb_to_cmy(*_unit("#00FF00")) == (1, 0, 1)
    cmy = c.rgb_to_cmy(F(42, 255), F(88, 255), F(159, 255))
    assert [round(float(v), 3) for v in cmy] == [0.835, 0.655, 0.376]


#: Wikipedia "HSL and HSV", Examples: hex, H (HSV hue), H2 (HSI hue), V, I, Y'601, S_HSV, S_HSI.
WIKIPEDIA_ROWS = [
    ("#BFBF00", 60.0, 60.0, 0.750, 0.500, 0.664, 1.000, 1.000),
    ("#008000", 120.0, 120.0, 0.500, 0.167, 0.293, 1.000, 1.000),
    ("#80FFFF", 180.0, 180.0, 1.000, 0.833, 0.850, 0.500, 0.400),
    ("#8080FF", 240.0, 240.0, 1.000, 0.667, 0.557, 0.500, 0.250),
    ("#A0A424", 61.8, 61.5, 0.643, 0.471, 0.581, 0.779, 0.699),
    ("#411BEA", 251.1, 250.0, 0.918, 0.426, 0.246, 0.887, 0.756),
    ("#1EAC41", 134.9, 133.8, 0.675, 0.349, 0.460, 0.828, 0.667),
    ("#F0C80E", 49.5, 50.5, 0.941, 0.593, 0.748, 0.944, 0.911),
    ("#B430E5", 283.7, 284.8, 0.897, 0.596, 0.423, 0.792, 0.686),
    ("#ED7651", 14.3, 13.2, 0.931, 0.570, 0.586, 0.661, 0.446),
    ("#FEF888", 56.9, 57.4, 0.998, 0.835, 0.931, 0.467, 0.363),
    ("#19CB97", 162.4, 163.4, 0.795, 0.495, 0.564, 0.875, 0.800),
    ("#362698", 248.3, 247.3, 0.597, 0.319, 0.219, 0.750, 0.533),
    ("#7E7EB8", 240.5, 240.4, 0.721, 0.570, 0.520, 0.316, 0.135),
]


@pytest.mark.parametrize("row", WIKIPEDIA_ROWS, ids=[r[0] for r in WIKIPEDIA_ROWS])
def test_hsv_hsi_and_luma_match_wikipedias_examples(row: tuple) -> None:
    hexcode, h, h2, v, i, luma, s_hsv, s_hsi = row
    rgb = _unit(hexcode)
    hsv, hsi = c.rgb_to_hsv(*rgb), c.rgb_to_hsi(*rgb)
    assert float(hsv.h) == pytest.approx(h, abs=0.5)
    assert float(hsv.v) == pytest.approx(v, abs=0.01)
    assert float(hsv.s) == pytest.approx(s_hsv, abs=0.01)
    assert float(hsi.h) == pytest.approx(h2, abs=0.5)
    assert float(hsi.i) == pytest.approx(i, abs=0.01)
    assert float(hsi.s) == pytest.approx(s_hsi, abs=0.01)
    assert float(c.grey_luma(*rgb)) == pytest.approx(luma, abs=0.01)
    assert float(c.grey_average(*rgb)) == pytest.approx(i, abs=0.01)  # the table's I: the mean


def test_pure_green_in_hsi_as_the_codeguru_thread_works_it() -> None:
    hsi = c.rgb_to_hsi(F(0), F(1), F(0))
    assert (hsi.h, hsi.s, hsi.i * 255) == (120, 1, 85)  # exact: arccos(-1/2) is 120 degrees


def test_rgb_51_102_153_is_exact_in_every_model() -> None:
    rgb = (F(1, 5), F(2, 5), F(3, 5))  # (51, 102, 153) / 255
    assert c.rgb_to_cmy(*rgb) == (F(4, 5), F(3, 5), F(2, 5))
    assert c.rgb_to_hsv(*rgb)[:3] == (210, F(2, 3), F(3, 5))
    assert c.rgb_to_hsi(*rgb)[:3] == (210, F(1, 2), F(2, 5))  # theta = 150 exactly
    assert c.grey_average(51, 102, 153) == 102
    assert c.grey_luma(F(51), F(102), F(153)) == F(92565, 1000)


# --- round trips ------------------------------------------------------------------------------------

LEVEL = st.integers(0, 255)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(LEVEL, LEVEL, LEVEL)
def test_rgb_to_cmy_and_hsv_and_back_is_exact(r: int, g: int, b: int) -> None:
    rgb = (F(r, 255), F(g, 255), F(b, 255))
    assert c.cmy_to_rgb(*c.rgb_to_cmy(*rgb)) == rgb
    hsv = c.rgb_to_hsv(*rgb)
    assert c.hsv_to_rgb(hsv.h, hsv.s, hsv.v) == rgb


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(LEVEL, LEVEL, LEVEL)
def test_rgb_to_hsi_and_back_is_within_the_stated_precision(r: int, g: int, b: int) -> None:
    rgb = (F(r, 255), F(g, 255), F(b, 255))
    hsi = c.rgb_to_hsi(*rgb)
    back = c.hsi_to_rgb(hsi.h, hsi.s, hsi.i)
    assert all(abs(float(x) - float(y)) < 1e-9 for x, y in zip(back, rgb, strict=True))
    # the hue as the answer prints it (3 decimals of a degree) still gives the 8-bit levels
    shown = F(round(float(hsi.h) * 1000), 1000)
    levels = [math.floor(float(v) * 255 + 0.5) for v in c.hsi_to_rgb(shown, hsi.s, hsi.i)]
    assert levels == [r, g, b]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@given(LEVEL, LEVEL, LEVEL)
def test_the_cli_round_trip_through_hsv_prints_the_input(r: int, g: int, b: int) -> None:
    hsv = json.loads(run("color", "rgb", str(r), str(g), str(b), "--to", "hsv", "-f", "json").out)
    h, s, v = (F(x).limit_denominator(10**6) for x in hsv["hsv"])
    back = json.loads(run("color", "hsv", str(h), str(s), str(v), "--to", "rgb", "-f", "json").out)
    assert back["given"] == {
        "H": float(h) if h.denominator > 1 else int(h),
        "S": float(s) if s.denominator > 1 else int(s),
        "V": float(v) if v.denominator > 1 else int(v),
    }
    assert back["hex"] == f"#{r:02X}{g:02X}{b:02X}"


# --- the answer --------------------------------------------------------------------------------------


def test_the_working_substitutes_the_numbers() -> None:
    text = run("color", "rgb", "51", "102", "153", "--to", "cmy", "hsv", "hsi", "-f", "plain").out
    for line in (
        "r = R / 255 = 51 / 255 = 0.2",
        "C = 1 - r = 1 - 0.2 = 0.8",
        "S = d / max = 0.4 / 0.6 = 2/3 ~ 0.667",
        "H = 240 + 60*(r - g) / d = 240 + 60*(0.2 - 0.4) / 0.4 = 210 deg",
        "theta = arccos(-0.3 / sqrt(0.12)) = 150 deg",
        "H = 360 deg - theta = 360 - 150 = 210 deg   (b > g)",
        "hex code = #336699",
        "bits per pixel = 3 x 8 = 24",
    ):
        assert line in text, line


def test_an_irrational_hue_is_given_to_three_decimals() -> None:
    sol = color_solution("rgb", [160, 164, 36], ["hsi"])
    theta = next(q for q in sol.derived if q.key == "hsi_theta")
    assert isinstance(theta.value, float)
    assert theta.text.endswith(f"≈ {theta.value:.3f}°")


def test_the_breakdown_with_other_depths() -> None:
    sol = color_solution("rgb", [31, 0, 16], [], bits=5)
    assert sol.data["hex"] == "0x7C10"  # 11111 00000 10000
    rows = list(sol.tables[-1].rows())
    assert [r[2] for r in rows] == ["11111", "00000", "10000"]
    assert sol.tables[-1].title.startswith("True-colour breakdown (15 bits per pixel")
    assert color_solution("rgb", [4095, 0, 1], [], bits=12).data["hex"] == "#FFF000001"


def test_grey_states_both_weightings() -> None:
    text = run("color", "rgb", "255", "0", "0", "--to", "grey", "-f", "plain").out
    assert "Y_avg = (R + G + B) / 3 = (255 + 0 + 0) / 3 = 85   (plain average)" in text
    assert "= 76.245   (ITU-R BT.601 luma)" in text


def test_unit_scale_and_non_rgb_input() -> None:
    unit = scanconv.color("rgb", "0.2", "0.4", "0.6", unit=True, to="hsv")
    assert unit.data["hsv"] == [210, F(2, 3), F(3, 5)]
    hsi = scanconv.color("hsi", 210, "1/2", "2/5", to="rgb")
    assert hsi.data["hex"] == "#336699"
    assert scanconv.color("cmy", "0.8", "0.6", "0.4", to="rgb").data["rgb"] == [
        F(1, 5),
        F(2, 5),
        F(3, 5),
    ]
    assert scanconv.color("grey", 128).data["hsv"] == [0, 0, F(128, 255)]


@pytest.mark.parametrize(
    ("argv", "word"),
    [
        (("rgb", "51", "102", "256"), "out of range"),
        (("rgb", "-1", "102", "25"), "out of range"),
        (("cmy", "1.5", "0", "0"), "out of range"),
        (("hsv", "0", "2", "1"), "out of range"),
        (("hsi", "0", "1", "1"), "outside the RGB cube"),
        (("rgb", "1", "2"), "takes 3 values"),
        (("grey", "1", "2"), "takes 1 value"),
        (("lab", "1", "2", "3"), "unknown colour model"),
        (("rgb", "1", "2", "3", "--to", "xyz"), "unknown colour model"),
        (("rgb", "1", "2", "3", "hsv"), "--to: a colour component must be a number"),
        (("rgb", "0.5", "2", "3"), "--unit: R = 0.5"),
        (("rgb", "1", "2", "3", "--bits", "0"), "1..16"),
    ],
)
def test_bad_colours_are_one_line_exit_2(argv: tuple[str, ...], word: str) -> None:
    r = run("color", *argv)
    assert_refused(r)
    assert word in r.err
