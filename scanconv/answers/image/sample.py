"""The worked answer of sampling and quantizing ``f(x, y)``: the sample spacing, the sampled
rows, the quantization step and the matrix of levels, from
:func:`~scanconv.algorithms.sample.sample_levels`."""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction

from ...algorithms.sample import Sampled
from ...core.numeric import Number, fmt, fmt_short, normalize, paren
from ...core.records import Plot, Quantity, ShadedMatrix, Solution, Table, Walk, worked
from ...core.working import tex_text
from ._shared import matrix_columns, picture_note
from .storage import storage_quantity


def _num(v: Number | float) -> tuple[str, bool]:
    """A value for the working and whether it is exact: a short decimal, or 3 decimals.

    >>> _num(Fraction(7, 4)), _num(2 / 3)
    (('1.75', True), ('0.667', False))
    """
    q = Fraction(v)
    s = fmt_short(q)
    return (fmt(q), False) if "/" in s else (s, True)


def _show(v: Number | float) -> str:
    return _num(v)[0]


def _paren_show(v: Number | float) -> str:
    return paren(_show(v))


def _rel(*values: Number | float) -> str:
    """``=`` if every value shows exactly, else ``\\approx``.

    >>> _rel(1, Fraction(1, 2)), _rel(Fraction(1, 3))
    ('=', '\\\\approx')
    """
    return "=" if all(_num(v)[1] for v in values) else r"\approx"


def _sample_given(s: Sampled, shown: str) -> tuple[Quantity, ...]:
    M, N = s.levels.shape
    x0, x1, y0, y1 = s.domain
    return (
        worked("f", shown, f"f(x, y) = \\texttt{{{tex_text(shown)}}}"),
        worked("M", M, f"M = {M} \\text{{ rows}}"),
        worked("N", N, f"N = {N} \\text{{ columns}}"),
        worked("L", s.L, f"L = {s.L} \\text{{ levels}}"),
        worked(
            "domain",
            (x0, x1, y0, y1),
            f"x \\in [{_show(x0)}, {_show(x1)}], y \\in [{_show(y0)}, {_show(y1)}]",
        ),
    )


def _grid_derived(s: Sampled) -> tuple[Quantity, ...]:
    """The sample spacing and where sample (i, j) lies."""
    M, N = s.levels.shape
    x0, x1, y0, y1 = s.domain
    top = "y down" if s.origin == "top-left" else "y up"
    y_rule = "y_0 + i \\cdot \\Delta y" if s.origin == "top-left" else "y_1 - i \\cdot \\Delta y"
    return (
        _spacing("x", x0, x1, N, "N"),
        _spacing("y", y0, y1, M, "M"),
        worked(
            "x_j",
            None,
            f"x_j = x_0 + j \\cdot \\Delta x,\\ j = 0 \\ldots {N - 1} "
            "\\text{ (columns, left to right)}",
        ),
        worked(
            "y_i",
            None,
            f"y_i = {y_rule},\\ i = 0 \\ldots {M - 1} \\text{{ (row 0 at the top, {top})}}",
        ),
    )


def _range_quantity(s: Sampled) -> Quantity:
    """f's range: over the samples, or as given (with where the samples lie)."""
    q = s.quantizer
    if not s.range_given:
        M, N = s.levels.shape
        samples = f"{M * N:,}"
        noun = "sample" if M * N == 1 else "samples"
        return worked(
            "f_range",
            (s.f_min, s.f_max),
            f"f_{{\\min}} {_rel(s.f_min)} {_show(s.f_min)},\\ f_{{\\max}} {_rel(s.f_max)} "
            f"{_show(s.f_max)} \\text{{ (over the {samples.replace(',', '{,}')} {noun})}}",
        )
    assert q is not None
    return worked(
        "f_range",
        (q.lo, q.hi),
        f"f_{{\\min}} = {_show(q.lo)},\\ f_{{\\max}} = {_show(q.hi)} \\text{{ (given; "
        f"the samples lie in }} [{_show(s.f_min)}, {_show(s.f_max)}])",
    )


def _step_quantities(s: Sampled) -> tuple[Quantity, ...]:
    """The quantization step and the level rule (none when f is constant)."""
    q = s.quantizer
    if q is None:
        return ()
    lo_s, hi_s, step = _paren_show(q.lo), _paren_show(q.hi), _show(q.step)
    trel = _rel(q.lo, q.hi, q.step)
    return (
        worked(
            "step",
            q.step,
            f"\\Delta = \\frac{{f_{{\\max}} - f_{{\\min}}}}{{L}} = \\frac{{{hi_s} - {lo_s}}}"
            f"{{{s.L}}} {trel} {step}",
        ),
        worked(
            "level",
            None,
            r"\text{level} = \min(\lfloor (f - f_{\min}) / \Delta \rfloor, L - 1)",
        ),
    )


def _sample_notes(s: Sampled, left_out: str | None) -> tuple[str, ...]:
    """Samples clamped, levels left as float64, a constant f, a picture left out."""
    q = s.quantizer
    notes = []
    if s.range_given and s.clipped:
        assert q is not None
        notes.append(
            f"{s.clipped:,} samples lie outside [{_show(q.lo)}, {_show(q.hi)}] and are "
            "clamped to level 0 or L − 1."
        )
    if s.unchecked:
        notes.append(
            f"{s.unchecked:,} samples lie within float64 rounding of a level boundary and keep "
            "their float64 level (checking that many exactly is beyond the work budget)."
        )
    if q is None:
        notes.append(f"f is constant ({_show(s.f_min)}) on the grid: every sample is level 0.")
    if left_out:
        notes.append(left_out)
    return tuple(notes)


def sample_solution(s: Sampled) -> Solution:
    """Sampling and quantization of ``f(x, y)`` as a worked answer, from
    :func:`~scanconv.algorithms.sample.sample_levels`.

    >>> from scanconv.algorithms.sample import sample_levels
    >>> sol = sample_solution(sample_levels("x + y", 8, 8, 8))
    >>> for q in sol.derived[4:]:
    ...     print(q.text)
    fₘᵢₙ = 0, fₘₐₓ = 14 (over the 64 samples)
    Δ = (fₘₐₓ - fₘᵢₙ) / L = (14 - 0) / 8 = 1.75
    level = min(⌊(f - fₘᵢₙ) / Δ⌋, L - 1)
    storage = M × N × ⌈log₂ L⌉ = 8 × 8 × 3 = 192 bits = 24 bytes
    >>> next(iter(sol.tables[0].rows()))
    (0, 4, 4, 5, 5, 6, 6, 7, 7)
    """
    M, N = s.levels.shape
    L = s.L
    shown = " ".join(s.expr.split())
    derived = (
        *_grid_derived(s),
        _range_quantity(s),
        *_step_quantities(s),
        storage_quantity(M, N, L),
    )
    left_out = picture_note(M, N)
    levels_m = s.levels

    def rows() -> Iterator[tuple[int, ...]]:
        # sample "x + y" 8x8 L=8 -> (0, 4 4 5 5 6 6 7 7), (1, 3 4 4 5 5 6 6 7), ...
        for i in range(M):
            yield (i, *levels_m[i].tolist())

    return Solution(
        primitive="image",
        algorithm="sample",
        title=f"Sampling and quantization of f(x, y) = {shown}: {M} x {N} samples, L = {L}",
        given=_sample_given(s, shown),
        derived=derived,
        notes=_sample_notes(s, left_out),
        walk=Walk(tables=(Table("Quantized levels (row i, column j)", matrix_columns(N), rows),)),
        plot=Plot(
            figures=()
            if left_out
            else (ShadedMatrix(tuple(tuple(r) for r in levels_m.tolist()), L, N),)
        ),
        data={"x": s.x.tolist(), "y": s.y.tolist()},
    )


def _spacing(name: str, lo: Number | float, hi: Number | float, count: int, cname: str) -> Quantity:
    """``Δx = (x1 − x0) / (N − 1) = (7 − 0) / 7 = 1``."""
    if count == 1:
        return worked(
            f"d{name}",
            0,
            f"{cname} = 1: \\text{{ one sample, }} {name} = {name}_0 = {_show(lo)}",
        )
    exact = not isinstance(lo, float) and not isinstance(hi, float)
    step: Number | float = (
        normalize(Fraction(hi - lo) / (count - 1))
        if exact
        else (float(hi) - float(lo)) / (count - 1)
    )
    a, b, d = _paren_show(hi), _paren_show(lo), _show(step)
    trel = _rel(lo, hi, step)
    return worked(
        f"d{name}",
        step,
        f"\\Delta {name} = \\frac{{{name}_1 - {name}_0}}{{{cname} - 1}} = \\frac{{{a} - {b}}}"
        f"{{{count - 1}}} {trel} {d}",
    )
