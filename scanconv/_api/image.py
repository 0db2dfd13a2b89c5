"""The Python API: image representation (``scanconv storage``, ``quantize``, ``sample``, ``image ramp``). See :mod:`scanconv._api`."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..core import lazy
from ..core.choices import (
    ColorDepthName,
    OriginName,
    ReconName,
)
from ..display import answers
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
    from ..algorithms import sample as algorithms_sample
else:
    algorithms_sample = lazy.module("scanconv.algorithms.sample")

if TYPE_CHECKING:
    from ..answers import quantize as answers_quantize
    from ..answers import ramp as answers_ramp
    from ..answers import sample as answers_sample
    from ..answers import storage as answers_storage
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_quantize = lazy.module("scanconv.answers.quantize")
    answers_ramp = lazy.module("scanconv.answers.ramp")
    answers_sample = lazy.module("scanconv.answers.sample")
    answers_storage = lazy.module("scanconv.answers.storage")


@answers
def storage(
    m: NumberLike,
    n: NumberLike,
    *,
    levels: NumberLike | None = None,
    bits: NumberLike | None = None,
    binary: bool = False,
    color: ColorDepthName | None = None,
    frames: NumberLike = 1,
) -> Solution:
    """The storage of an ``m`` x ``n`` image (``scanconv storage``): give exactly one of
    ``levels``, ``bits``, ``binary`` or ``color="rgb24"``.

    >>> storage(1024, 768, levels=256).data["sizes"]["KiB"]
    Fraction(768, 1)
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
    bits: NumberLike,
    value_range: tuple[NumberLike, NumberLike] | None = None,
    *,
    integer: bool = True,
    recon: ReconName = "midpoint",
) -> Solution:
    """The quantization table for ``bits`` bits over ``value_range`` (``scanconv quantize``):
    integer inputs ``LO..HI``, or with ``integer=False`` real ones in ``[LO, HI]``; ``recon`` is
    ``"midpoint"`` or ``"lower"``.

    >>> [row[-1] for row in quantize(2, (0, 255)).tables[0].rows()]
    [32, 96, 160, 224]
    """
    return answers_quantize.quantize_solution(
        _number(bits, "bits"),
        None if value_range is None else _pair(value_range, "value_range"),
        integer=integer,
        recon=_choice(recon, "recon"),
    )


@answers
def sample(
    expr: str,
    size: str | int | tuple[int, int],
    levels: NumberLike,
    *,
    domain: tuple[FormulaLike, FormulaLike, FormulaLike, FormulaLike] | None = None,
    value_range: tuple[FormulaLike, FormulaLike] | None = None,
    origin: OriginName = "bottom-left",
) -> Solution:
    """Sample ``f(x, y) = expr`` on an M x N grid and quantize it to ``levels`` levels
    (``scanconv sample``). ``size`` is ``"MxN"``, ``M`` or ``(M, N)``; ``domain`` is
    ``(X0, X1, Y0, Y1)``; ``value_range`` the range of f mapped onto the levels.

    >>> next(iter(sample("x + y", "8x8", 8).tables[0].rows()))
    (0, 4, 4, 5, 5, 6, 6, 7, 7)
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
def ramp(size: str | int | tuple[int, int] = "8", levels: NumberLike = 8) -> Solution:
    """The notes' grayscale ramp, ``i + j`` folded back at ``L - 1`` (``scanconv image ramp``).

    >>> next(iter(ramp(8, 8).tables[0].rows()))
    (0, 0, 1, 2, 3, 4, 5, 6, 7)
    """
    m, n = _size(size)
    return answers_ramp.ramp_solution(m, n, _number(levels, "levels"))
