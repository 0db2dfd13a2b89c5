"""The Python API: image representation (``scanconv storage``, ``quantize``, ``sample``, ``image ramp``). See :mod:`scanconv._api`."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

from ..core import lazy
from ..core.checks import InputError
from ..core.declare import Arg, Opt
from ..display import answers
from .params import BITS, SIZE
from .values import (
    FormulaLike,
    NumberLike,
    _choice,
    _formulas,
    _number,
    _numbers,
    _optional,
    _pair,
    _size,
)

if TYPE_CHECKING:
    from ..algorithms import quantize as algorithms_quantize
    from ..algorithms import sample as algorithms_sample
    from ..core.choices import (
        ColorDepthName,
        InputKindName,
        OriginName,
        ReconName,
    )
else:
    algorithms_quantize = lazy.module("scanconv.algorithms.quantize")
    algorithms_sample = lazy.module("scanconv.algorithms.sample")

if TYPE_CHECKING:
    from ..answers.image import quantize as answers_quantize
    from ..answers.image import ramp as answers_ramp
    from ..answers.image import sample as answers_sample
    from ..answers.image import storage as answers_storage
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_quantize = lazy.module("scanconv.answers.image.quantize")
    answers_ramp = lazy.module("scanconv.answers.image.ramp")
    answers_sample = lazy.module("scanconv.answers.image.sample")
    answers_storage = lazy.module("scanconv.answers.image.storage")


@answers
def storage(
    m: Annotated[
        NumberLike, Arg("M, the first size (1024 in 1024 x 768; 1024x768 works too).", "M")
    ],
    n: Annotated[NumberLike, Arg("N, the second size (768 in 1024 x 768).", "N")],
    *,
    levels: Annotated[
        NumberLike | None, Opt("--levels", "-L", help="Gray levels L (k = ceil(log2 L)).")
    ] = None,
    bits: Annotated[NumberLike | None, BITS] = None,
    binary: Annotated[bool, Opt("--binary", help="Binary image: 1 bit per pixel.")] = False,
    color: Annotated[
        ColorDepthName | None,
        Opt("--color", help="Colour image: rgb24 = 24 bits.", choices=("rgb24",)),
    ] = None,
    frames: Annotated[
        NumberLike,
        Opt("--frames", help="Number of frames F (default 1).", show_default=False),
    ] = 1,
) -> Solution:
    """The storage an M x N image (or F frames of it) needs: ``M x N x k x F`` bits
    (``scanconv storage``).

    Parameters
    ----------
    m, n : number
        The image's size, M x N pixels.
    levels : int, optional
        L gray levels: ``k = ceil(log2 L)`` bits a pixel.
    bits : int, optional
        B bits a pixel: ``k = B``, ``L = 2**B``.
    binary : bool, default False
        A binary image, ``k = 1``.
    color : {"rgb24"}, optional
        24-bit colour, ``k = 24``. Give exactly one of ``levels``, ``bits``, ``binary``,
        ``color``.
    frames : int, default 1
        F frames (a video).

    Returns
    -------
    Answer
        The working and ``.data["sizes"]``: bits, bytes, KB and MB (powers of 1000), KiB and MiB
        (powers of 1024), exact.

    Examples
    --------
    >>> sizes = storage(1024, 768, levels=256).data["sizes"]
    >>> sizes["bits"], sizes["KiB"], sizes["MiB"]
    (6291456, Fraction(768, 1), Fraction(3, 4))
    >>> storage(640, 480, color="rgb24", frames=25).data["sizes"]["MB"]
    Fraction(576, 25)
    """
    return answers_storage.storage_solution(
        *_numbers(m=m, n=n),
        levels=_optional(levels, "levels"),
        bits=_optional(bits, "bits"),
        binary=binary,
        color=None if color is None else _choice(color, "color"),
        frames=_number(frames, "frames"),
    )


@answers
def quantize(
    bits: Annotated[NumberLike, BITS],
    value_range: Annotated[
        tuple[NumberLike, NumberLike] | None,
        Opt(
            "--range",
            metavar="LO HI",
            help="Input range: add each level's inputs and reconstruction value.",
        ),
    ] = None,
    *,
    kind: Annotated[
        InputKindName,
        Opt(
            "--input",
            help="integer: the inputs are the integers LO..HI (8-bit: --range 0 255); "
            "real: any value in [LO, HI].",
            choices=("integer", "real"),
        ),
    ] = "integer",
    recon: Annotated[
        ReconName,
        Opt(
            "--recon",
            help="Reconstruction value: the midpoint of each level's cell or its lower end.",
            choices=("midpoint", "lower"),
        ),
    ] = "midpoint",
    integer: bool | None = None,
) -> Solution:
    """The quantization table for ``bits`` bits over a range of values (``scanconv quantize``).

    Parameters
    ----------
    bits : int
        B bits: ``2**B`` levels.
    value_range : (lo, hi), optional
        The input range: integers ``lo .. hi``, or with ``kind="real"`` real values in
        ``[lo, hi]``; without one the table lists the levels and their codes only.
    kind : {"integer", "real"}, default "integer"
        Integer inputs (each level a range of whole numbers) or real ones (half-open intervals).
    recon : {"midpoint", "lower"}, default "midpoint"
        Each level's reconstruction value: the middle of its interval, or its lower end.
    integer : bool, optional
        The earlier spelling of ``kind`` (``integer=False`` is ``kind="real"``); given, it
        decides.

    Returns
    -------
    Answer
        One row per level: ``decimal, binary, gray_level``, and with a range ``from, to,
        reconstruction``.

    Examples
    --------
    >>> for row in quantize(2, (0, 255)).tables[0].rows():
    ...     print(*row)
    0 00 Black 0 63 32
    1 01 Dark Gray 64 127 96
    2 10 Light Gray 128 191 160
    3 11 White 192 255 224
    >>> [row[-1] for row in quantize(2, (0, 1), kind="real", recon="lower").tables[0].rows()]
    [0, Fraction(1, 4), Fraction(1, 2), Fraction(3, 4)]
    """
    return answers_quantize.quantize_solution(
        _number(bits, "bits"),
        None if value_range is None else _pair(value_range, "value_range"),
        integer=_input_kind(kind) == "integer" if integer is None else bool(integer),
        recon=_choice(recon, "recon"),
    )


def _input_kind(kind: str) -> str:
    """What a quantizer's inputs are, checked: ``"integer"`` or ``"real"``."""
    text = _choice(kind, "kind")
    if text not in algorithms_quantize.INPUTS:
        choices = ", ".join(algorithms_quantize.INPUTS)
        raise InputError(f"unknown input kind {text!r} (choose from {choices})", "kind")
    return text


@answers
def sample(
    expr: Annotated[str, Arg("f(x, y), e.g. 'x + y' or 'sin(x)*cos(y)'.", "EXPR")],
    size: Annotated[str | int | tuple[int, int], SIZE],
    levels: Annotated[NumberLike, Opt("--levels", "-L", help="Gray levels L.")],
    *,
    domain: Annotated[
        tuple[FormulaLike, FormulaLike, FormulaLike, FormulaLike] | None,
        Opt(
            "--domain",
            metavar="X0 X1 Y0 Y1",
            help="Sample x from X0 to X1 and y from Y0 to Y1 (default: 0..N-1, 0..M-1).",
            kind="text",
        ),
    ] = None,
    value_range: Annotated[
        tuple[FormulaLike, FormulaLike] | None,
        Opt(
            "--range",
            metavar="LO HI",
            help="Range of f quantized onto the levels (default: the samples' min and max).",
            kind="text",
        ),
    ] = None,
    origin: Annotated[
        OriginName,
        Opt(
            "--origin",
            help="Row 0 is the top: bottom-left: y up (row 0 is y1); top-left: y down.",
            choices=("bottom-left", "top-left"),
        ),
    ] = "bottom-left",
) -> Solution:
    """Sample ``f(x, y) = expr`` on an M x N grid and quantize the samples to L levels
    (``scanconv sample``).

    Parameters
    ----------
    expr : str
        The function of x and y (:mod:`scanconv.core.expr`: ``"x + y"``, ``"sin(x) * y"``).
    size : str, int or (M, N)
        The grid: ``"MxN"``, ``M`` (square) or ``(M, N)``; M rows, N columns.
    levels : int
        L, the number of levels.
    domain : (X0, X1, Y0, Y1) of numbers or formulas, optional
        The sampled rectangle; default ``(0, N - 1, 0, M - 1)``, one sample per pixel at integer
        coordinates.
    value_range : (lo, hi) of numbers or formulas, optional
        The values mapped onto the levels; default the smallest and largest sample (samples
        outside a range given are clamped).
    origin : {"bottom-left", "top-left"}, default "bottom-left"
        Row 0 at the top with y up (``y_i = Y1 - i Δy``), or y down (``y_i = Y0 + i Δy``).

    Returns
    -------
    Answer
        The table of levels, row i by column j; ``level = min(floor((f - f_min) L /
        (f_max - f_min)), L - 1)``.

    Examples
    --------
    >>> for row in list(sample("x + y", "4x4", 4).tables[0].rows()):
    ...     print(*row)
    0 2 2 3 3
    1 1 2 2 3
    2 0 1 2 2
    3 0 0 1 2
    >>> next(iter(sample("x + y", "4x4", 4, origin="top-left").tables[0].rows()))
    (0, 0, 0, 1, 2)
    """
    m, n = _size(size)
    sampled = algorithms_sample.sample_levels(
        expr,
        m,
        n,
        _number(levels, "levels"),
        domain=None if domain is None else _formulas(domain, "domain", 4),
        value_range=None if value_range is None else _formulas(value_range, "value_range", 2),
        origin=_choice(origin, "origin"),
    )
    return answers_sample.sample_solution(sampled)


@answers
def ramp(
    size: Annotated[str | int | tuple[int, int], SIZE] = "8",
    levels: Annotated[
        NumberLike, Opt("--levels", "-L", help="Gray levels L (default 8).", show_default=False)
    ] = 8,
) -> Solution:
    """The notes' grayscale ramp: ``f(i, j) = i + j`` folded back at L - 1
    (``scanconv image ramp``).

    Parameters
    ----------
    size : str, int or (M, N), default "8"
        The image: ``"MxN"``, ``M`` (square) or ``(M, N)``.
    levels : int, default 8
        L gray levels.

    Returns
    -------
    Answer
        The table ``f(i, j) = s`` if ``s <= L - 1`` else ``2(L - 1) - s``, where
        ``s = (i + j) mod 2(L - 1)``.

    Examples
    --------
    >>> for row in list(ramp(4, 4).tables[0].rows()):
    ...     print(*row)
    0 0 1 2 3
    1 1 2 3 2
    2 2 3 2 1
    3 3 2 1 0
    """
    m, n = _size(size)
    return answers_ramp.ramp_solution(m, n, _number(levels, "levels"))
