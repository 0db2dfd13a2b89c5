"""The worked answer of a colour conversion: RGB, CMY, HSV, HSI and grey, each formula
written once (TeX) with this colour's numbers substituted, and the true-colour breakdown of
the RGB pixel (each channel's bits, the hex code, bits per pixel).

Scales (stated in every answer): RGB is given as integers ``0 .. 2^b - 1`` (``b`` bits per
channel, 8 by default: ``0 .. 255``) or, with ``unit``, as numbers in ``[0, 1]``; the working
normalises to ``r, g, b`` in ``[0, 1]``. CMY, saturation, value and intensity are in ``[0,
1]``, hue in degrees ``[0, 360)``. A grey level is on the RGB input scale. Values are exact
fractions where the model is rational; HSI's hue needs an arc cosine and is given to
:data:`.color_models.PLACES` decimals of a degree (exact where the angle is 0, 30, 60, 90, ... degrees).
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import cast

from ...algorithms import color as c
from ...algorithms.color import Value
from ...core.checks import InputError
from ...core.numeric import Number, fmt_short, round_half_up
from ...core.records import Solution, Table, Walk, heading
from ..methods import method
from ._shared import int_tex
from .color_models import RGB, ColorModel, Rgb, _triple, _Work

MAX_BITS = 16
"""Largest ``--bits`` per channel (48-bit colour)."""

ALIASES = {"gray": "grey", "greyscale": "grey", "grayscale": "grey"}


def model_name(name: str, param: str = "model") -> str:
    """A model's canonical name (``gray`` is ``grey``), or :class:`InputError`.

    >>> model_name("HSI"), model_name("gray")
    ('hsi', 'grey')
    """
    key = ALIASES.get(name.lower(), name.lower())
    if key not in c.MODELS:
        raise InputError(
            f"unknown colour model {name!r} (choose from {', '.join(c.MODELS)})", param
        )
    return key


# --- the true-colour breakdown ---------------------------------------------------------------------


def hex_code(levels: tuple[int, int, int], bits: int) -> str:
    """``#336699`` when a channel is whole hex digits (4, 8, 12 or 16 bits), else the packed
    pixel word ``R << 2b | G << b | B`` in hex.

    >>> hex_code((51, 102, 153), 8), hex_code((1, 2, 3), 5)
    ('#336699', '0x0443')
    """
    if bits % 4 == 0:
        return "#" + "".join(f"{v:0{bits // 4}X}" for v in levels)
    return f"0x{c.pack(levels, bits):0{-(-3 * bits // 4)}X}"


def _breakdown(w: _Work, levels: tuple[int, int, int], bits: int) -> tuple[Table, str]:
    digits = -(-bits // 4)
    hexcode = hex_code(levels, bits)
    w.say("breakdown", rf"\text{{True colour: {bits} bits per channel}}")
    for name, v in zip("RGB", levels, strict=True):
        w.add(
            f"bits_{name}",
            f"{v:0{bits}b}",
            rf"{name} = {v} = {v:0{bits}b}_2 = \text{{hex }} \mathrm{{{v:0{digits}X}}}",
        )
    w.add("hex", hexcode, rf"\text{{hex code}} = \text{{{hexcode.replace('#', chr(92) + '#')}}}")
    bpp = 3 * bits
    w.add("bits_per_pixel", bpp, rf"\text{{bits per pixel}} = 3 \times {bits} = {bpp}")
    w.add("colours", 1 << bpp, rf"\text{{colours}} = 2^{{{bpp}}} = {int_tex(1 << bpp)}")
    rows = tuple(
        (name, v, f"{v:0{bits}b}", f"{v:0{digits}X}") for name, v in zip("RGB", levels, strict=True)
    )
    return Table(
        f"True-colour breakdown ({bpp} bits per pixel, {hexcode})",
        (
            heading("channel", r"\text{channel}"),
            heading("value", r"\text{value}"),
            heading("binary", rf"\text{{bits ({bits})}}"),
            heading("hex", r"\text{hex}"),
        ),
        lambda: rows,
    ), hexcode


# --- the answer ---------------------------------------------------------------------------------------
def _rgb_levels(w: _Work, rgb: tuple[Value, ...], top: int) -> tuple[int, int, int]:
    """The channel levels of an RGB in [0, 1] (clamped floats; rounded half up), worked."""
    rgb = tuple(min(1, max(0, v)) if isinstance(v, float) else v for v in rgb)
    scaled = [v * top for v in rgb]
    r8, g8, b8 = (round_half_up(v) for v in scaled)
    exact = all(isinstance(v, Fraction) and v.denominator == 1 for v in scaled)
    w.add(
        "rgb_levels",
        (r8, g8, b8),
        rf"(R, G, B) = {top} \cdot (r, g, b) "
        + ("= " if exact else r"\approx ")
        + f"({r8}, {g8}, {b8})"
        + ("" if exact else r" \quad (\text{rounded half up})"),
    )
    return r8, g8, b8


def spec(name: str) -> ColorModel:
    """The model ``name`` (canonical: :func:`model_name`), as its method record names it."""
    return cast(ColorModel, method("color", name).load("spec"))


def _results(rows: list[tuple[str, str, str]]) -> Table:
    return Table(
        "Results",
        (
            heading("model", r"\text{model}"),
            heading("value", r"\text{value}"),
            heading("exact", r"\text{exact}"),
        ),
        lambda: tuple(rows),
    )


def _color_notes(
    scale: str, unit: bool, bits: int, given: ColorModel, targets: Sequence[ColorModel]
) -> list[str]:
    notes = [
        f"RGB is on the {scale} scale ({'values given as fractions of 1' if unit else f'{bits} bits per channel'}); "
        "the working normalises it to r, g, b in [0, 1]. CMY, S, V and I are in [0, 1], hue in "
        "degrees [0, 360).",
    ]
    for m in map(spec, c.MODELS):
        noted = m in targets if m.noted == "target" else m in (given, *targets)
        if m.note and noted and m.note not in notes:
            notes.append(m.note)
    return notes


def color_solution(
    model: str,
    values: Sequence[Number],
    targets: Sequence[str] = (),
    *,
    unit: bool = False,
    bits: int = 8,
) -> Solution:
    """Convert a colour given in ``model`` to each model of ``targets`` (default: every other
    one), with the working.

    >>> sol = color_solution("rgb", [51, 102, 153], ["cmy", "hsv", "hsi"])
    >>> [row[1] for row in sol.tables[0].rows()]
    ['(0.2, 0.4, 0.6)', '(0.8, 0.6, 0.4)', '(210, 0.667, 0.6)', '(210, 0.5, 0.4)']
    >>> print(sol.derived[-1].text)
    colours = 2²⁴ = 16,777,216
    """
    model = model_name(model)
    want = [model_name(t, "targets") for t in targets] or [m for m in c.MODELS if m != model]
    if not 1 <= bits <= MAX_BITS:
        raise InputError(f"bits per channel must be 1..{MAX_BITS}, got {bits}", "bits")
    top = (1 << bits) - 1
    source, targets_ = spec(model), [spec(t) for t in want]
    count = source.components
    if len(values) != count:
        raise InputError(
            f"{source.name} takes {count} value{'s' * (count > 1)}, got {len(values)}", "values"
        )
    w = _Work(top, unit)
    scale = w.scale
    given, rgb, levels = source.given(w, values)
    with_rgb = RGB in (source, *targets_)
    if levels is None and with_rgb:
        rgb = tuple(min(1, max(0, v)) if isinstance(v, float) else v for v in rgb)
        levels = _rgb_levels(w, rgb, top)
    rows: list[tuple[str, str, str]] = [(RGB.label, _triple(rgb), _triple(rgb, True))]
    data: dict[str, object] = dict(
        model=model, targets=want, scale=scale, rgb=list(rgb)
    )  # JSON keys
    for target, name in zip(targets_, want, strict=True):
        if target not in (RGB, source):
            out = target.convert(w, cast(Rgb, rgb))
            data[name] = list(out)
            rows.append((target.label, _triple(out), _triple(out, True)))
    tables = [_results(rows)]
    if levels is not None and with_rgb:
        breakdown, data["hex"] = _breakdown(w, levels, bits)
        tables.append(breakdown)
    shown = ", ".join(m.name for m in targets_ if m != source)
    values_text = ", ".join(fmt_short(Fraction(v)) for v in values)
    return Solution(
        primitive="color",
        algorithm=model,
        title=f"Colour {source.name} ({values_text}) to {shown or source.name}",
        given=tuple(given),
        derived=tuple(w.items),
        notes=tuple(_color_notes(scale, unit, bits, source, targets_)),
        walk=Walk(tables=tuple(tables)),
        data=data,
    )
