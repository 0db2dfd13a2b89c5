"""``scanconv color``: colour-model conversions with the working (RGB, CMY, HSV, HSI, grey),
declared by its library function (:func:`scanconv._api.color_theory.color`)."""

from __future__ import annotations

from .application import app
from .declared import command

command(
    app,
    ("color",),
    help="""Convert a colour between RGB, CMY, HSV, HSI and grey, formulas worked with its numbers.

    The RGB answer adds the true-colour breakdown: each channel's bits, the hex code, bits
    per pixel.
    Example: scanconv color rgb 51 102 153 --to cmy hsv hsi
    """,
)
