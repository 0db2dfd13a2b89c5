"""The worked answer of frame-buffer arithmetic: the buffer's pixel count and size for a
resolution and bits per pixel (or a screen's size in inches at a resolution in dots per inch),
its bit planes and colours, a colour look-up table's size and the colours it gives, the time
to load a frame at a transfer rate, the time a scan line and a pixel get at a refresh rate
(interlaced or not) and the share of it spent in horizontal and vertical retrace, the frame
rate a pixel time gives, and the address of a pixel in the buffer (and the pixel at an
address), its conventions named (:data:`scanconv.algorithms.framebuffer.ADDRESS_KNOBS`).
Exact arithmetic; sizes in bytes, KB/MB (1000) and KiB/MiB (1024)."""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction
from typing import Any

from ...algorithms import framebuffer as fb
from ...algorithms.storage import sizes
from ...core.checks import InputError, check_positive
from ...core.numeric import Number, fmt_short, normalize
from ...core.records import Quantity, Solution, Table, Walk, heading, worked
from ._shared import int_tex
from .storage import size_text

MAX_BITS = 64
"""The most bits per pixel (or per look-up-table entry) worked."""

MAX_SIDE = 10**6
"""The most pixels across or down a frame buffer worked (the screen's size times its dpi)."""


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
            "line_time",
            normalize(1 / (h * frames)),
            f"\\text{{time per scan line}} = 1 / (H \\times f) = 1 / {_tex(size_text(h * frames))} "
            f"{_time_text(1 / (h * frames))}",
        ),
        worked(
            "pixel_time",
            normalize(per_pixel),
            f"\\text{{time per pixel}} = 1 / {_tex(size_text(rate))} {_time_text(per_pixel)}",
        ),
    ]


def _resolution(
    width: Number, height: Number, dpi: Number | None
) -> tuple[int, int, list[Quantity]]:
    """The pixels across and down: given, or a screen's inches times its dots per inch (whole
    pixels: rounded down)."""
    if dpi is None:
        w, h = _whole(width, "the width", "width"), _whole(height, "the height", "height")
        if max(w, h) > MAX_SIDE:
            raise InputError(f"a side of at most {MAX_SIDE:,} pixels is worked", "width")
        return w, h, []
    d = _positive(dpi, "the resolution (dpi)", "dpi")
    wi, hi = _positive(width, "the width", "width"), _positive(height, "the height", "height")
    w, h = int(Fraction(wi) * Fraction(d)), int(Fraction(hi) * Fraction(d))
    if min(w, h) < 1 or max(w, h) > MAX_SIDE:
        raise InputError(
            f"{fmt_short(wi)} x {fmt_short(hi)} in at {fmt_short(d)} dpi is {w} x {h} pixels: "
            f"1 .. {MAX_SIDE:,} a side are worked",
            "dpi",
        )
    return (
        w,
        h,
        [
            worked(
                "resolution",
                (w, h),
                f"W = {fmt_short(wi)} \\text{{ in}} \\times {fmt_short(d)} \\text{{ dpi}} = {w}, \\; "
                f"H = {fmt_short(hi)} \\text{{ in}} \\times {fmt_short(d)} \\text{{ dpi}} = {h}",
            )
        ],
    )


def _address(
    w: int,
    h: int,
    b: int,
    pixel: tuple[int, int] | None,
    at: Number | None,
    base: int,
    conventions: dict[str, str],
) -> list[Quantity]:
    """The address of ``pixel`` and the pixel at address ``at``, with the numbers substituted."""
    out: list[Quantity] = []
    c = int(conventions["count"])
    xs = f"(x - {c})" if c else "x"
    ys = f"(y - {c})" if c else "y"
    y0 = ys if conventions["row0"] == "top" else f"(H - 1 - {ys})"
    index = f"{y0} W + {xs}" if conventions["major"] == "row" else f"{xs} H + {y0}"
    if pixel is not None:
        a = fb.address(
            *pixel,
            w,
            h,
            b,
            base,
            major=conventions["major"],
            row0=conventions["row0"],
            count=conventions["count"],
        )
        out.append(
            worked(
                "index",
                a.k,
                f"k = {index} = "
                + (
                    f"{a.y0} \\times {w} + {a.x0}"
                    if conventions["major"] == "row"
                    else f"{a.x0} \\times {h} + {a.y0}"
                )
                + f" = {int_tex(a.k)}",
            )
        )
        byte = normalize(a.byte)
        inside = (
            "" if a.bit_in_byte == 0 else f" \\text{{ (byte {int(a.byte)}, bit {a.bit_in_byte})}}"
        )
        out.append(
            worked(
                "address",
                byte,
                f"\\text{{address}} = \\text{{base}} + k \\cdot b / 8 = {base} + {int_tex(a.k)} "
                f"\\cdot {b} / 8 = {_tex(fmt_short(byte)) if byte != int(byte) else int_tex(int(byte))}"
                f"{inside} \\text{{ (bit {int_tex(a.bit)})}}",
            )
        )
    if at is not None:
        x, y = fb.pixel_of(
            Fraction(at),
            w,
            h,
            b,
            base,
            major=conventions["major"],
            row0=conventions["row0"],
            count=conventions["count"],
        )
        k = int((Fraction(at) - base) * 8) // b
        out.append(
            worked(
                "pixel_at",
                (x, y),
                f"k = (\\text{{address}} - \\text{{base}}) \\cdot 8 / b = ({fmt_short(at)} - {base}) "
                f"\\cdot 8 / {b} = {int_tex(k)} \\to (x, y) = ({x}, {y})",
            )
        )
    return out


def _address_table(k: int, b: int, base: int) -> Table:
    """The pixel's address as a table a student writes and ``check`` marks: its index k, its
    bit offset k b from the buffer's start, its byte address base + floor(k b / 8) and, when a
    pixel is less than a byte, the bit inside that byte (k b mod 8)."""
    byte, bit = divmod(k * b, 8)
    rows: tuple[tuple[str, int], ...] = (
        ("k", k),
        ("bit offset", k * b),
        ("byte address", base + byte),
    )
    if b % 8:
        rows += (("bit in byte", bit),)
    return Table(
        "The pixel's address",
        (heading("quantity", r"\text{quantity}", role="label"), heading("value", r"\text{value}")),
        lambda: rows,
    )


def _retrace(
    w: int, h: int, refresh: Number, hr: Number | None, vr: Number | None
) -> list[Quantity]:
    """The refresh time's share spent in retrace, and the scan line's and the pixel's time
    without it (a non-interlaced frame of H lines, each W pixels and a horizontal retrace)."""
    th, tv, f = Fraction(hr or 0), Fraction(vr or 0), Fraction(refresh)
    share = (h * th + tv) * f
    if share >= 1:
        raise InputError(
            f"the retraces take {fmt_short(share)} of the refresh time (at most 1)", "hretrace"
        )
    line = (1 / f - tv) / h
    pixel = (line - th) / w
    return [
        worked(
            "retrace_fraction",
            normalize(share),
            f"\\text{{retrace share}} = (H \\cdot t_h + t_v) \\cdot f = ({h} \\cdot {fmt_short(th)} + "
            f"{fmt_short(tv)}) \\cdot {fmt_short(f)} = {fmt_short(normalize(share))}",
        ),
        worked(
            "line_time_traced",
            normalize(line),
            f"\\text{{scan line (with its retrace)}} = (1 / f - t_v) / H {_time_text(line)}",
        ),
        worked(
            "pixel_time_traced",
            normalize(pixel),
            f"\\text{{time per pixel (retrace excluded)}} = (\\text{{line}} - t_h) / W {_time_text(pixel)}",
        ),
    ]


def _frame_rate(w: int, h: int, tp: Number, hr: Number | None, vr: Number | None) -> Quantity:
    """The frame rate a pixel time gives: ``1 / (H (W t_p + t_h) + t_v)``."""
    th, tv = Fraction(hr or 0), Fraction(vr or 0)
    frame = fb.frame_time(w, h, Fraction(tp), th, tv)
    rate = 1 / frame
    return worked(
        "frame_rate",
        normalize(rate),
        f"f = 1 / (H (W t_p + t_h) + t_v) = 1 / ({h} ({w} \\cdot {fmt_short(tp)} + {fmt_short(th)}) + "
        f"{fmt_short(tv)}) {_is(size_text(rate))} \\text{{ Hz}}",
    )


def _size_lines(w: int, h: int, b: int) -> list[Quantity]:
    """The pixel count, the size and the bit planes, with the numbers substituted."""
    total = w * h * b
    return [
        worked(
            "pixel_count",
            w * h,
            f"\\text{{pixels}} = W \\times H = {w} \\times {h} = {int_tex(w * h)}",
        ),
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


def _timing(
    w: int,
    h: int,
    refresh: Number | None,
    interlaced: bool,
    hretrace: Number | None,
    vretrace: Number | None,
    pixel_time: Number | None,
) -> tuple[list[Quantity], Number | None, Number | None]:
    """The refresh times, the retrace share and the frame rate a pixel time gives, as asked;
    and the retrace times checked."""
    out: list[Quantity] = []
    hr = (
        None if hretrace is None else _positive(hretrace, "the horizontal retrace time", "hretrace")
    )
    vr = None if vretrace is None else _positive(vretrace, "the vertical retrace time", "vretrace")
    if refresh is not None:
        hz = _positive(refresh, "the refresh rate", "refresh")
        out += _refresh(w, h, hz, interlaced)
        if hr is not None or vr is not None:
            if interlaced:
                raise InputError(
                    "retrace times are worked for a non-interlaced display", "interlaced"
                )
            out += _retrace(w, h, hz, hr, vr)
    if pixel_time is not None:
        out.append(_frame_rate(w, h, _positive(pixel_time, "the pixel time", "pixel_time"), hr, vr))
    return out, hr, vr


def _notes(named: dict[str, str] | None) -> tuple[str, ...]:
    """The notes: the units, the bit planes and (``named``: an address asked) its conventions."""
    return (
        "KB and MB are 1000 and 1000^2 bytes, KiB and MiB 1024 and 1024^2 bytes: published "
        "answers use either, so both are given.",
        "A bit plane holds one bit of every pixel: b bits per pixel take b planes.",
        *(
            ()
            if named is None
            else (
                f"Address conventions: {named['major']}-major, y = 0 the "
                f"{named['row0']} scan line, x and y counted from {named['count']}; "
                "byte address = base + k * b / 8.",
            )
        ),
    )


def framebuffer_solution(
    width: Number,
    height: Number,
    bits: Number,
    *,
    lut: Number | None = None,
    rate: Number | None = None,
    refresh: Number | None = None,
    interlaced: bool = False,
    dpi: Number | None = None,
    pixel: tuple[int, int] | None = None,
    address: Number | None = None,
    base: int = 0,
    conventions: dict[str, str] | None = None,
    hretrace: Number | None = None,
    vretrace: Number | None = None,
    pixel_time: Number | None = None,
) -> Solution:
    """Frame-buffer arithmetic for a ``width`` x ``height`` raster of ``bits`` bits per pixel:
    ``lut`` the bits of a look-up-table entry, ``rate`` a transfer rate in bits per second,
    ``refresh`` the refresh rate in Hz (fields per second when ``interlaced``); ``dpi``: the
    width and height are a screen's inches; ``pixel`` the pixel whose address is wanted (and
    ``address`` the address whose pixel is), from ``base``, by the ``conventions`` (major,
    row0, count); ``hretrace`` and ``vretrace`` the retrace times in seconds, ``pixel_time``
    the time a pixel gets (the frame rate follows).

    >>> sol = framebuffer_solution(1280, 1024, 8, lut=24, rate=10**6, refresh=60)
    >>> for q in sol.derived:
    ...     print(q.text)
    pixels = W × H = 1280 × 1024 = 1,310,720
    size = W × H × b = 1280 × 1024 × 8 = 10,485,760 bits = 1,310,720 bytes
    bit planes = b = 8, colours = 2ᵇ = 256
    LUT entries = 2ᵇ = 2⁸ = 256
    LUT size = 2ᵇ × w = 256 × 24 = 6144 bits = 768 bytes
    palette = 2ʷ = 2²⁴ = 16,777,216 colours, 256 at a time
    load time = size / R = 10,485,760 / 1,000,000 = 10.48576 s
    non-interlaced: 60 frames/s
    pixels/s = W × H × f = 1280 × 1024 × 60 = 78,643,200
    time per scan line = 1 / (H × f) = 1 / 61,440 ≈ 16.276 μs
    time per pixel = 1 / 78,643,200 ≈ 12.716 ns
    """
    w, h, derived = _resolution(width, height, dpi)
    b = _whole(bits, "bits per pixel", "bits", MAX_BITS)
    total = w * h * b
    derived += _size_lines(w, h, b)
    if lut is not None:
        derived += _lut(b, _whole(lut, "bits per LUT entry", "lut", MAX_BITS))
    if rate is not None:
        derived.append(_load(total, _positive(rate, "the transfer rate", "rate")))
    named = {**dict.fromkeys(fb.ADDRESS_KNOBS, ""), **(conventions or {})}
    named = {k: v or fb.ADDRESS_KNOBS[k][0] for k, v in named.items()}
    derived += _address(w, h, b, pixel, address, base, named)
    timing, hr, vr = _timing(w, h, refresh, interlaced, hretrace, vretrace, pixel_time)
    derived += timing
    data: dict[str, Any] = {q.key: q.value for q in derived}

    def given() -> Iterator[Quantity]:
        if dpi is not None:
            yield worked(
                "inches",
                (width, height),
                f"{fmt_short(width)} \\times {fmt_short(height)} \\text{{ in at }} {fmt_short(dpi)} \\text{{ dpi}}",
            )
        else:
            yield worked("W", w, f"W \\times H = {w} \\times {h}")
        yield worked("b", b, f"b = {b} \\text{{ bits per pixel}}")
        if lut is not None:
            yield worked("w", lut, f"w = {fmt_short(lut)} \\text{{ bits per LUT entry}}")
        if rate is not None:
            yield worked("R", rate, f"R = {fmt_short(rate)} \\text{{ bits/s}}")
        if refresh is not None:
            yield worked("f", refresh, f"f = {fmt_short(refresh)} \\text{{ Hz}}")
        if pixel is not None:
            yield worked(
                "pixel", pixel, f"(x, y) = ({pixel[0]}, {pixel[1]}), \\text{{ base}} = {base}"
            )
        if address is not None:
            yield worked("A", address, f"\\text{{address}} = {fmt_short(address)}")
        for key, name, t in (("t_h", "t_h", hr), ("t_v", "t_v", vr), ("t_p", "t_p", pixel_time)):
            if t is not None:
                yield worked(key, t, f"{name} = {fmt_short(t)} \\text{{ s}}")

    tables: tuple[Table, ...] = (_size_table(total),)
    if pixel is not None:
        tables += (_address_table(data["index"], b, base),)
        data |= {"b": b, "base": base}
    return Solution(
        primitive="framebuffer",
        algorithm="arithmetic",
        title=f"Frame buffer: {w} x {h}, {b} bits per pixel",
        given=tuple(given()),
        derived=tuple(derived),
        notes=_notes(named if pixel is not None or address is not None else None),
        walk=Walk(tables=tables),
        data=data,
    )
