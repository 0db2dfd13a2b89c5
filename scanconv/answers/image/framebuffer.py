"""The worked answer of frame-buffer arithmetic: the buffer's size for a resolution and bits
per pixel, its bit planes and colours, a colour look-up table's size and the colours it gives,
the time to load a frame at a transfer rate, and the time a pixel gets at a refresh rate
(interlaced or not). Exact arithmetic; sizes in bytes, KB/MB (1000) and KiB/MiB (1024)."""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction
from typing import Any

from ...algorithms.storage import sizes
from ...core.checks import InputError, check_positive
from ...core.numeric import Number, fmt_short, normalize
from ...core.records import Quantity, Solution, Table, Walk, heading, worked
from ._shared import int_tex
from .storage import size_text

MAX_BITS = 64
"""The most bits per pixel (or per look-up-table entry) worked."""


def _whole(v: Number, what: str, param: str, top: int | None = None) -> int:
    n = check_positive(v, what, param=param)
    if top is not None and n > top:
        raise InputError(f"{what} must be at most {top}, got {n}", param)
    return n


def _positive(v: Number, what: str, param: str) -> Number:
    if v <= 0:
        raise InputError(f"{what} must be positive, got {fmt_short(v)}", param)
    return normalize(v)


def _tex(s: str) -> str:
    return s.replace("≈", "\\approx").replace(",", "{,}")


def _is(s: str) -> str:
    """``= 12`` or ``\\approx 12.7`` (a value from :func:`size_text`), as TeX."""
    return _tex(s) if s.startswith("≈") else f"= {_tex(s)}"


def _time_text(seconds: Fraction) -> str:
    """``= 10.49 \\, s`` or ``\\approx 12.716 \\, ns``: a time in the unit that reads best
    (s, ms, µs or ns; exact when it terminates), as TeX."""
    units = (("s", 1), ("ms", 10**3), ("\\mu s", 10**6), ("ns", 10**9))
    for unit, scale in units:
        if seconds * scale >= 1 or unit == "ns":
            return f"{_is(size_text(seconds * scale))} \\, \\mathrm{{{unit}}}"
    raise AssertionError("unreachable")


def _size_table(bits: int) -> Table:
    rows = tuple((unit, size_text(v, cell=True)) for unit, v in sizes(bits).items())
    return Table(
        "Frame-buffer size",
        (heading("unit", r"\text{unit}", role="label"), heading("size", r"\text{size}")),
        lambda: rows,
    )


def _lut(b: int, lut: int) -> list[Quantity]:
    entries = 1 << b
    lut_bits = entries * lut
    return [
        worked(
            "lut_entries", entries, f"\\text{{LUT entries}} = 2^b = 2^{{{b}}} = {int_tex(entries)}"
        ),
        worked(
            "lut_bits",
            lut_bits,
            f"\\text{{LUT size}} = 2^b \\times w = {int_tex(entries)} \\times {lut} = "
            f"{int_tex(lut_bits)} \\text{{ bits}} = {_tex(size_text(Fraction(lut_bits, 8)))} "
            "\\text{ bytes}",
        ),
        worked(
            "palette",
            1 << lut,
            f"\\text{{palette}} = 2^w = 2^{{{lut}}} = {int_tex(1 << lut)} "
            f"\\text{{ colours, }} {int_tex(entries)} \\text{{ at a time}}",
        ),
    ]


def _load(total: int, rate: Number) -> Quantity:
    seconds = Fraction(total) / Fraction(rate)
    return worked(
        "load_time",
        normalize(seconds),
        f"\\text{{load time}} = \\text{{size}} / R = {int_tex(total)} / "
        f"{int_tex(int(rate)) if rate == int(rate) else fmt_short(rate)} "
        f"{_time_text(seconds)}",
    )


def _refresh(w: int, h: int, refresh: Number, interlaced: bool) -> list[Quantity]:
    frames = Fraction(refresh) / 2 if interlaced else Fraction(refresh)
    rate = w * h * frames
    per_pixel = 1 / rate
    how = (
        f"\\text{{interlaced: }} {fmt_short(refresh)} \\text{{ fields/s}} = "
        f"{fmt_short(frames)} \\text{{ frames/s}}"
        if interlaced
        else f"\\text{{non-interlaced: }} {fmt_short(frames)} \\text{{ frames/s}}"
    )
    return [
        worked("frames_per_second", normalize(frames), how),
        worked(
            "pixel_rate",
            normalize(rate),
            f"\\text{{pixels/s}} = W \\times H \\times f = {w} \\times {h} \\times "
            f"{fmt_short(frames)} {_is(size_text(rate))}",
        ),
        worked(
            "pixel_time",
            normalize(per_pixel),
            f"\\text{{time per pixel}} = 1 / {_tex(size_text(rate))} {_time_text(per_pixel)}",
        ),
    ]


def framebuffer_solution(
    width: Number,
    height: Number,
    bits: Number,
    *,
    lut: Number | None = None,
    rate: Number | None = None,
    refresh: Number | None = None,
    interlaced: bool = False,
) -> Solution:
    """Frame-buffer arithmetic for a ``width`` x ``height`` raster of ``bits`` bits per pixel:
    ``lut`` the bits of a look-up-table entry, ``rate`` a transfer rate in bits per second,
    ``refresh`` the refresh rate in Hz (fields per second when ``interlaced``).

    >>> sol = framebuffer_solution(1280, 1024, 8, lut=24, rate=10**6, refresh=60)
    >>> for q in sol.derived:
    ...     print(q.text)
    size = W × H × b = 1280 × 1024 × 8 = 10,485,760 bits = 1,310,720 bytes
    bit planes = b = 8, colours = 2ᵇ = 256
    LUT entries = 2ᵇ = 2⁸ = 256
    LUT size = 2ᵇ × w = 256 × 24 = 6144 bits = 768 bytes
    palette = 2ʷ = 2²⁴ = 16,777,216 colours, 256 at a time
    load time = size / R = 10,485,760 / 1,000,000 = 10.48576 s
    non-interlaced: 60 frames/s
    pixels/s = W × H × f = 1280 × 1024 × 60 = 78,643,200
    time per pixel = 1 / 78,643,200 ≈ 12.716 ns
    """
    w = _whole(width, "the width", "width")
    h = _whole(height, "the height", "height")
    b = _whole(bits, "bits per pixel", "bits", MAX_BITS)
    total = w * h * b
    derived = [
        worked(
            "size_bits",
            total,
            f"\\text{{size}} = W \\times H \\times b = {w} \\times {h} \\times {b} = "
            f"{int_tex(total)} \\text{{ bits}} = {_tex(size_text(Fraction(total, 8)))} "
            "\\text{ bytes}",
        ),
        worked(
            "colours",
            1 << b,
            f"\\text{{bit planes}} = b = {b}, \\text{{ colours}} = 2^b = {int_tex(1 << b)}",
        ),
    ]
    if lut is not None:
        derived += _lut(b, _whole(lut, "bits per LUT entry", "lut", MAX_BITS))
    if rate is not None:
        derived.append(_load(total, _positive(rate, "the transfer rate", "rate")))
    if refresh is not None:
        hz = _positive(refresh, "the refresh rate", "refresh")
        derived += _refresh(w, h, hz, interlaced)
    data: dict[str, Any] = {q.key: q.value for q in derived}

    def given() -> Iterator[Quantity]:
        yield worked("W", w, f"W \\times H = {w} \\times {h}")
        yield worked("b", b, f"b = {b} \\text{{ bits per pixel}}")
        if lut is not None:
            yield worked("w", lut, f"w = {fmt_short(lut)} \\text{{ bits per LUT entry}}")
        if rate is not None:
            yield worked("R", rate, f"R = {fmt_short(rate)} \\text{{ bits/s}}")
        if refresh is not None:
            yield worked("f", refresh, f"f = {fmt_short(refresh)} \\text{{ Hz}}")

    return Solution(
        primitive="framebuffer",
        algorithm="arithmetic",
        title=f"Frame buffer: {w} x {h}, {b} bits per pixel",
        given=tuple(given()),
        derived=tuple(derived),
        notes=(
            "KB and MB are 1000 and 1000^2 bytes, KiB and MiB 1024 and 1024^2 bytes: published "
            "answers use either, so both are given.",
            "A bit plane holds one bit of every pixel: b bits per pixel take b planes.",
        ),
        walk=Walk(tables=(_size_table(total),)),
        data=data,
    )
