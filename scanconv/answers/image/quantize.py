"""The worked answer of quantization: the table of levels (decimal value, binary code, gray-level
name) and, over an input range, each level's inputs and reconstruction value."""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction
from itertools import chain
from typing import Any

from ...algorithms.image_limits import check_bits
from ...algorithms.quantize import Quantizer
from ...algorithms.storage import bits_per_pixel
from ...core.numeric import Number, fmt_paren, fmt_short
from ...core.records import Quantity, Solution, Table, Walk, heading, worked
from ._shared import int_tex, int_text

GRAY_NAMES: dict[int, tuple[str, ...]] = {
    1: ("Black", "White"),
    2: ("Black", "Dark Gray", "Light Gray", "White"),
    3: (
        "Black",
        "Very Dark Gray",
        "Dark Gray",
        "Gray",
        "Light Gray",
        "Very Light Gray",
        "Almost White",
        "White",
    ),
}
"""Gray-level names by bits: 3 bits are the notes' table; 1 and 2 bits name the same ends."""


def gray_name(k: int, levels: int) -> str:
    """The name of gray level ``k`` of ``levels``: the notes' names for 8 levels.

    1 to 3 bits use :data:`GRAY_NAMES`; more levels are ``Black``, ``Gray k/(L-1)`` and
    ``White``.

    >>> gray_name(6, 8), gray_name(1, 4), gray_name(5, 16), gray_name(15, 16)
    ('Almost White', 'Dark Gray', 'Gray 5/15', 'White')
    """
    names = GRAY_NAMES.get(bits_per_pixel(levels))
    if names is not None and len(names) == levels:
        return names[k]
    if k == 0:
        return "Black"
    if k == levels - 1:
        return "White"
    return f"Gray {k}/{levels - 1}"


def quantization_rows(bits: int, quantizer: Quantizer | None = None) -> Iterator[tuple[Any, ...]]:
    """The rows of the quantization table of ``bits`` bits: one per level, in order.

    Each row is ``(k, binary code, gray-level name)``, plus ``(from, to, reconstruction)``
    with a quantizer.

    Notes
    -----
    ``L = 2**bits`` levels ``0 .. L - 1``; the code is ``k`` in ``bits`` binary digits. Names
    are the notes' for 3 bits (:data:`GRAY_NAMES`), see :func:`gray_name`.

    Examples
    --------
    The notes' 3-bit table, with the 8-bit inputs 0 .. 255 (Δ = 32, midpoints):

    >>> q = Quantizer.make(0, 255, 8)
    >>> for row in quantization_rows(3, q):
    ...     print(*row, sep=" | ")
    0 | 000 | Black | 0 | 31 | 16
    1 | 001 | Very Dark Gray | 32 | 63 | 48
    2 | 010 | Dark Gray | 64 | 95 | 80
    3 | 011 | Gray | 96 | 127 | 112
    4 | 100 | Light Gray | 128 | 159 | 144
    5 | 101 | Very Light Gray | 160 | 191 | 176
    6 | 110 | Almost White | 192 | 223 | 208
    7 | 111 | White | 224 | 255 | 240
    """
    levels = 1 << bits
    # quantization_rows(3) -> (0, '000', 'Black'), (1, '001', 'Very Dark Gray'), ... (7, '111', 'White')
    # 2^24 rows at most: the columns are made by C-level map/zip over shared prefixes, the
    # values those of gray_name and format(k, "0{bits}b") (tests/test_image_quantize_table.py)
    rows = zip(range(levels), _codes(bits), _gray_names(levels), strict=True)
    if quantizer is None:
        return rows
    return map(tuple.__add__, rows, quantizer.cells())


def _codes(bits: int) -> Iterator[str]:
    """``format(k, f"0{bits}b")`` for ``k = 0 .. 2**bits - 1``: a prefix of the high bits
    before each of the 2^12 low-bit suffixes.

    >>> list(_codes(2)), list(_codes(14))[4097]
    (['00', '01', '10', '11'], '01000000000001')
    """
    low = min(bits, 12)
    suffixes = [format(j, f"0{low}b") for j in range(1 << low)]
    if low == bits:
        return iter(suffixes)
    high = bits - low
    return chain.from_iterable(
        map(format(h, f"0{high}b").__add__, suffixes) for h in range(1 << high)
    )


def _gray_names(levels: int) -> Iterator[str]:
    """:func:`gray_name` of ``k = 0 .. levels - 1``, levels a power of two: decimal ``k`` as
    a prefix of its thousands before each of the suffixes ``000/L-1 .. 999/L-1``.

    >>> list(_gray_names(4)), list(_gray_names(4096))[1000:1002]
    (['Black', 'Dark Gray', 'Light Gray', 'White'], ['Gray 1000/4095', 'Gray 1001/4095'])
    """
    names = GRAY_NAMES.get(bits_per_pixel(levels))
    if names is not None and len(names) == levels:
        return iter(names)
    last = levels - 1
    tail = f"/{last}"
    blocks = last // 1000  # thousands 1 .. blocks - 1 are whole
    suffixes = [f"{j:03d}{tail}" for j in range(1000 if blocks else 0)]
    return chain(
        ("Black",),
        map(f"Gray {{}}{tail}".format, range(1, min(last, 1000))),
        chain.from_iterable(map(f"Gray {h}".__add__, suffixes) for h in range(1, blocks)),
        map(f"Gray {{}}{tail}".format, range(max(blocks * 1000, 1000), last)),
        ("White",),
    )


def quantize_solution(
    bits: Number,
    value_range: tuple[Number | float, Number | float] | None = None,
    *,
    integer: bool = True,
    recon: str = "midpoint",
) -> Solution:
    """The quantization table for ``bits`` bits, optionally over an input range.

    Examples
    --------
    >>> sol = quantize_solution(2, (0, 255))
    >>> for q in sol.derived:
    ...     print(q.text)
    L = 2^B = 2² = 4 levels, 0 to 3
    Δ = (HI - LO + 1) / L = (255 - 0 + 1) / 4 = 64
    level = ⌊(v - LO) / Δ⌋ = ⌊(v - 0) / 64⌋
    rₖ = LO + (k + 1/2)·Δ = 0 + (k + 1/2)·64
    >>> [row[-1] for row in sol.tables[0].rows()]
    [32, 96, 160, 224]
    """
    B = check_bits(bits)
    L = 1 << B
    derived = [
        worked(
            "L",
            L,
            f"L = 2^B = 2^{{{B}}} = {int_tex(L)} \\text{{ levels, 0 to }} {int_tex(L - 1)}",
        )
    ]
    notes: list[str] = []
    if B in GRAY_NAMES and B != 3:
        notes.append(
            "Gray-level names: the notes name the 3-bit levels only; these names keep its ends "
            "(Black, White) and its Dark Gray / Light Gray."
        )
    elif B not in GRAY_NAMES:
        notes.append(
            "Gray-level names: the notes name the 3-bit levels only; level k of L is named "
            f"Gray k/{L - 1} here, with 0 Black and {L - 1} White."
        )
    columns = [
        heading("decimal", r"\text{Decimal value}", role="label"),
        heading("binary", f"\\text{{Binary ({B} bits)}}"),
        heading("gray_level", r"\text{Gray level}"),
    ]
    q = None
    if value_range is not None:
        q = Quantizer.make(value_range[0], value_range[1], L, integer=integer, recon=recon)
        derived.extend(_quantizer_working(q))
        notes.append(_quantizer_note(q))
        edges = None if q.integer else _places(q.lo, q.step)
        columns += [
            heading("from", r"\text{from}", edges),
            heading("to", r"\text{to}", edges),
            heading(
                "reconstruction",
                r"\text{reconstruction } r_k",
                _places(q.reconstruction(0), q.step),
            ),
        ]
    names = {1: "Binary", 2: "2-bit", 3: "3-bit"}
    return Solution(
        primitive="image",
        algorithm="quantize",
        title=f"{names.get(B, f'{B}-bit')} quantization ({int_text(L)} gray levels)",
        given=(worked("B", B, f"B = {B} \\text{{ bits}}"),),
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(
            tables=(Table("Quantization table", tuple(columns), lambda: quantization_rows(B, q)),)
        ),
        data={}
        if q is None
        else {"range": [q.lo, q.hi], "input": "integer" if q.integer else "real"}
        | {"reconstruction": q.recon},
    )


def _places(*values: Number) -> int | None:
    """Decimals that show every value of ``lo + k·step`` exactly (at most 6, else 3).

    ``None`` when they are all integers.

    >>> _places(0, Fraction(1, 16)), _places(16, 32), _places(Fraction(1, 3))
    (4, None, 3)
    """
    places = 0
    for v in values:
        q = Fraction(v)
        p = next((p for p in range(7) if (q * 10**p).denominator == 1), None)
        if p is None:
            return 3
        places = max(places, p)
    return places or None


def _quantizer_working(q: Quantizer) -> list[Quantity]:
    lo, hi, step = fmt_short(q.lo), fmt_paren(q.hi), fmt_paren(q.step)
    plus1 = " + 1" if q.integer else ""
    o = q.offset
    off = rf"(k + \tfrac{{{o.numerator}}}{{{o.denominator}}})" if o else "k"
    return [
        worked(
            "step",
            q.step,
            f"\\Delta = \\frac{{HI - LO{plus1}}}{{L}} = \\frac{{{hi} - {fmt_paren(q.lo)}"
            f"{plus1}}}{{{q.levels}}} = {fmt_short(q.step)}",
        ),
        worked(
            "level",
            None,
            f"\\text{{level}} = \\lfloor (v - LO) / \\Delta \\rfloor = \\lfloor (v - "
            f"{fmt_paren(q.lo)}) / {step} \\rfloor"
            + ("" if q.integer else f", \\text{{ at most }} L - 1 = {q.levels - 1}"),
        ),
        worked(
            "reconstruction", None, f"r_k = LO + {off} \\cdot \\Delta = {lo} + {off} \\cdot {step}"
        ),
    ]


def _quantizer_note(q: Quantizer) -> str:
    if q.integer:
        inputs = (
            f"Inputs are the integers {fmt_short(q.lo)} .. {fmt_short(q.hi)}; "
            "'from' and 'to' are the first and last input of each level."
        )
    else:
        inputs = (
            f"Inputs are real values in [{fmt_short(q.lo)}, {fmt_short(q.hi)}]; level k takes "
            f"[from, to), the top level also takes {fmt_short(q.hi)}."
        )
    if q.offset:  # the midpoint
        rule = (
            "the midpoint of the level's cell [LO + kΔ, LO + (k + 1)Δ) (reconstructing at the "
            "lower end would give LO + kΔ)"
        )
    else:
        rule = (
            "the lower end LO + kΔ of the level's cell (the default reconstruction is its "
            "midpoint, LO + (k + 1/2)Δ)"
        )
    return f"{inputs} Reconstruction value: {rule}."
