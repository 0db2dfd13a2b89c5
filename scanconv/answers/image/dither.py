"""The worked answers of halftoning and dithering: thresholding, ordered dither, error
diffusion (Floyd–Steinberg) and halftone patterns, from :mod:`scanconv.algorithms.dither`.

Every answer states its conventions (comparison, threshold scale, matrix base and reading,
kernel, scan order, arithmetic, carries) in its notes, so a published table that follows its
own stated rule can be reproduced by setting them.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from fractions import Fraction
from typing import Any

from ...algorithms import dither as d
from ...core.checks import InputError
from ...core.numeric import Number, fmt, fmt_short, normalize
from ...core.records import (
    Column,
    Plot,
    Quantity,
    ShadedMatrix,
    Solution,
    Step,
    Table,
    Walk,
    heading,
    rule,
    worked,
)
from ..process._shared import matrix_tex, matrix_text
from ._shared import matrix_columns

METHODS = ("threshold", "ordered", "floyd-steinberg", "pattern")
"""The dithering methods, as ``scanconv dither METHOD`` takes them."""


def _checked(image: Sequence[Sequence[Number]], top: Number) -> d.Matrix:
    """The image as an exact matrix, its scale's top checked positive (the mean divides by it)."""
    if not top > 0:
        raise InputError(f"the scale's top must be positive, got {fmt_short(top)}", "top")
    return d.check_matrix(image, "image", "image")


def _matrix(key: str, name: str, rows: Sequence[Sequence[Number]]) -> Quantity:
    """``name = [[...], ...]`` with its TeX ``bmatrix``."""
    m = tuple(tuple(r) for r in rows)
    return Quantity(
        key, [list(r) for r in m], f"{name} = {matrix_text(m)}", f"{name} = {matrix_tex(m)}"
    )


def _matrix_table(title: str, rows: Sequence[Sequence[Any]]) -> Table:
    frozen = tuple(tuple(r) for r in rows)
    return Table(
        title,
        matrix_columns(len(frozen[0])),
        lambda: ((i, *r) for i, r in enumerate(frozen)),
    )


def _output_parts(
    steps: Callable[[], Iterator[Step]], shape: tuple[int, int], at: int
) -> tuple[tuple[tuple[int, ...], ...], Table, ShadedMatrix]:
    """The output matrix (1 on, 0 off) read from the steps (``extra[at]``), its table and its
    picture."""
    rows, cols = shape
    out = [[0] * cols for _ in range(rows)]
    for s in steps():
        j, i = s.pixel
        out[i][j] = 1 if s.extra[at] else 0
    frozen = tuple(tuple(r) for r in out)
    return frozen, _matrix_table("Output (1 = on)", frozen), ShadedMatrix(frozen, 2, cols)


def _given_image(image: d.Matrix, top: Number) -> list[Quantity]:
    rows, cols = len(image), len(image[0])
    return [
        _matrix("image", "I", image),
        worked("size", (rows, cols), f"{rows} \\times {cols} \\text{{ pixels}}"),
        worked("top", top, f"\\text{{intensities on the scale }} 0 \\ldots {fmt_short(top)}"),
    ]


def _rows_of(steps: Callable[[], Iterator[Step]], width: int) -> Callable[[], Iterator[Step]]:
    """The steps with ``extra`` led by the row i and column j a student writes."""

    def rows() -> Iterator[Step]:
        for s in steps():
            j, i = s.pixel
            yield s._replace(extra=(i, j, *s.extra))

    return rows


_CELL = (heading("k", "k", role="label"), heading("i", "i"), heading("j", "j"))
_DECIDED = (
    heading("value", "I(i, j)"),
    heading("threshold", "T"),
    heading("output", r"\text{output}"),
)
"""The columns of a pixel compared with its threshold (thresholding, ordered dither)."""
_COMPARE_TEX = {">": ">", ">=": r"\ge"}


def _solution(
    kind: str,
    title: str,
    image: d.Matrix,
    top: Number,
    derived: list[Quantity],
    notes: list[str],
    columns: tuple[Column, ...],
    steps: Callable[[], Iterator[Step]],
    extra_keys: tuple[str, ...],
    output_at: int,
    data: dict[str, Any],
) -> Solution:
    shape = (len(image), len(image[0]))
    out, out_table, picture = _output_parts(steps, shape, output_at)
    rows = _rows_of(steps, shape[1])
    on = sum(map(sum, out))
    total = sum((Fraction(v) for r in image for v in r), Fraction(0))
    mean_in = normalize(total / (shape[0] * shape[1] * Fraction(top)))
    derived = [
        *derived,
        worked(
            "mean",
            (mean_in, Fraction(on, shape[0] * shape[1])),
            f"\\text{{mean intensity }} {fmt_short(mean_in)} \\text{{ of the scale; pixels on: }} "
            f"{on} / {shape[0] * shape[1]} = {fmt_short(Fraction(on, shape[0] * shape[1]))}",
        ),
    ]
    return Solution(
        primitive="dither",
        algorithm=kind,
        title=title,
        given=tuple(_given_image(image, top)),
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(
            columns=(*_CELL, *columns),
            extra_keys=("i", "j", *extra_keys),
            steps=rows,
            tables=(out_table,),
        ),
        plot=Plot(figures=(picture,)),
        data={**data, "output": [list(r) for r in out]},
    )


def threshold_solution(
    image: Sequence[Sequence[Number]],
    top: Number = 1,
    at: Number | None = None,
    compare: str = ">=",
) -> Solution:
    """Thresholding: a pixel is on when its value passes one threshold (default ``top / 2``).

    >>> sol = threshold_solution([[10, 200], [128, 127]], 255, 128)
    >>> sol.data["output"]
    [[0, 1], [1, 0]]
    """
    img = _checked(image, top)
    t = normalize(Fraction(top) / 2) if at is None else normalize(Fraction(at))
    rel = _COMPARE_TEX[d.choice("compare", compare)]
    derived = [
        worked("T", t, f"T = {fmt_short(t)}"),
        rule("test", f"\\text{{on when }} I(i, j) {rel} T"),
    ]
    return _solution(
        "threshold",
        f"Thresholding at T = {fmt_short(t)}",
        img,
        top,
        derived,
        [f"A pixel is on when its value is {compare} T."],
        _DECIDED,
        lambda: d.threshold(img, t, compare),
        ("value", "threshold", "output"),
        2,
        {"threshold": t, "compare": compare},
    )


def _dither_matrix(matrix: int | Sequence[Sequence[Number]]) -> tuple[d.Matrix, str]:
    if isinstance(matrix, int):
        return d.bayer(matrix), f"the {matrix} x {matrix} Bayer matrix"
    m = d.check_matrix(matrix, "dither matrix", "matrix")
    if len(m) > d.MAX_ORDER or len(m[0]) > d.MAX_ORDER:
        raise InputError(f"a dither matrix is at most {d.MAX_ORDER} wide", "matrix")
    return m, f"the {len(m)} x {len(m[0])} matrix given"


def ordered_solution(
    image: Sequence[Sequence[Number]],
    matrix: int | Sequence[Sequence[Number]] = 2,
    top: Number = 1,
    *,
    compare: str = ">",
    scale: str = "raw",
    base: str = "0",
    transpose: bool = False,
) -> Solution:
    """Ordered dither with a Bayer matrix (``matrix`` = 2, 4, 8, 16) or a matrix given.

    >>> sol = ordered_solution([[1, 2], [3, 4]], 2, 4)
    >>> [s.extra[2:] for s in sol.steps()]
    [(1, 0, 1), (2, 2, 0), (3, 3, 0), (4, 1, 1)]
    """
    img = _checked(image, top)
    dm, named = _dither_matrix(matrix)
    n2 = len(dm) * len(dm[0])
    table = d.thresholds(dm, top, scale=scale, base=base, transpose=transpose)
    rel = _COMPARE_TEX[d.choice("compare", compare)]
    shift = "" if base == "0" else " - 1"
    half = " + 1/2" if scale == "centered" else ""
    derived = [
        _matrix("D", "D", dm),
        rule(
            "T",
            f"T(d) = (d{shift}{half}) \\cdot {fmt_short(top)} / {n2}",
        ),
        _matrix("thresholds", "T", table),
        rule(
            "test",
            f"\\text{{on when }} I(i, j) {rel} T[i \\bmod {len(table)}][j \\bmod {len(table[0])}]",
        ),
    ]
    notes = [
        f"Conventions: compare {compare}, thresholds {scale} (T = (d{shift}{half}) * top / n^2), "
        f"entries from {base}, the matrix read {'by columns (transposed)' if transpose else 'by rows'}.",
    ]
    return _solution(
        "ordered",
        f"Ordered dither with {named}",
        img,
        top,
        derived,
        notes,
        _DECIDED,
        lambda: d.ordered(img, table, compare),
        ("value", "threshold", "output"),
        2,
        {
            "matrix": [list(r) for r in dm],
            "thresholds": [list(r) for r in table],
            "compare": compare,
        },
    )


def _carries_text(carries: Sequence[d.Carry]) -> str:
    """Each share in the form of the table's other values (3 decimals, a whole number as it is),
    never a decimal in one row and a fraction in the next (issue 39, item 8)."""
    return ", ".join(f"({c.pixel[1]}, {c.pixel[0]}) += {fmt(c.amount)}" for c in carries)


def diffusion_solution(
    image: Sequence[Sequence[Number]],
    top: Number = 1,
    *,
    kernel: str = "floyd-steinberg",
    order: str = "raster",
    arithmetic: str = "exact",
    carry: str = "kept",
    compare: str = ">=",
) -> Solution:
    """Error diffusion to two levels, with the error table of every step.

    >>> sol = diffusion_solution([[100, 100], [100, 100]], 255)
    >>> sol.data["output"]
    [[0, 1], [0, 0]]
    """
    img = _checked(image, top)
    shares = d.KERNELS[d.choice("kernel", kernel)]
    rel = _COMPARE_TEX[d.choice("compare", compare)]
    half = normalize(Fraction(top) / 2)
    derived = [
        rule(
            "output",
            f"\\text{{output}} = {fmt_short(top)} \\text{{ if }} I' {rel} {fmt_short(half)}"
            f"\\text{{, else }} 0",
        ),
        rule("error", r"e = I' - \text{output}"),
        rule(
            "kernel",
            r"\text{shares: }"
            + ", ".join(
                f"{s.weight.numerator}/{s.weight.denominator} \\text{{ to }} (i{s.di:+d}, j{s.dj:+d})"
                for s in shares
            ),
        ),
    ]
    notes = [
        f"Conventions: kernel {kernel}, {order} order, {arithmetic} arithmetic, negative "
        f"carries {carry}, on when I' {compare} {fmt_short(half)}; outputs 0 and {fmt_short(top)}.",
        "I' is the pixel's value plus the error it received; shares that fall outside the "
        "image are lost.",
    ]
    if order == "serpentine":
        notes.append("Odd rows are scanned right to left, the kernel mirrored (j - 1 is ahead).")

    def steps() -> Iterator[Step]:
        for s in d.error_diffusion(
            img,
            top,
            kernel=kernel,
            order=order,
            arithmetic=arithmetic,
            carry=carry,
            compare=compare,
        ):
            received, value, out, err, carries = s.extra
            yield s._replace(extra=(received, value, out, err, _carries_text(carries)))

    columns = (
        heading("received", r"\text{received}"),
        heading("value", "I'"),
        heading("output", r"\text{output}"),
        heading("error", "e"),
        heading("carries", r"\text{carried to } (i, j)"),
    )
    return _solution(
        "floyd-steinberg",
        f"Error diffusion ({kernel}, {order})",
        img,
        top,
        derived,
        notes,
        columns,
        steps,
        ("received", "value", "output", "error", "carries"),
        2,
        {
            "kernel": kernel,
            "order": order,
            "arithmetic": arithmetic,
            "carry": carry,
            "compare": compare,
        },
    )


def pattern_solution(n: int, level: int | None = None, bits: int = 1) -> Solution:
    """The n x n halftone patterns: how many levels they give and the pattern of each level
    (or of one ``level``).

    >>> sol = pattern_solution(2)
    >>> [r[1] for r in sol.tables[0].rows()]
    ['0 0 / 0 0', '1 0 / 0 0', '1 0 / 0 1', '1 1 / 0 1', '1 1 / 1 1']
    """
    if not 2 <= n <= d.MAX_ORDER or n & (n - 1):
        raise InputError(f"a halftone cell is 2, 4, 8 or 16 pixels wide, got {n}", "n")
    if not 1 <= bits <= 8:
        raise InputError(f"bits per pixel must be 1..8, got {bits}", "bits")
    count = d.pattern_levels(n, bits)
    levels = range(n * n + 1) if level is None else (level,)
    patterns = [(lv, d.pattern(n, lv)) for lv in levels]
    derived = [
        _matrix("D", "D", d.bayer(n)),
        worked(
            "levels",
            count,
            f"\\text{{levels}} = n^2 (2^b - 1) + 1 = {n}^2 \\cdot (2^{bits} - 1) + 1 = {count}",
        ),
        rule("on", r"\text{level } l \text{ turns on the cells with } D < l"),
    ]

    def rows() -> Iterator[tuple[Any, ...]]:
        for lv, p in patterns:
            yield lv, " / ".join(" ".join(str(c) for c in r) for r in p), sum(map(sum, p))

    table = Table(
        f"{n} x {n} patterns (1 = on, rows top first)",
        (heading("level", "l"), heading("pattern", r"\text{pattern}"), heading("on", r"\text{on}")),
        rows,
    )
    figures = tuple(ShadedMatrix(p, 2, n) for _, p in patterns[:8])
    return Solution(
        primitive="dither",
        algorithm="pattern",
        title=f"Halftone patterns {n} x {n}" + ("" if level is None else f", level {level}"),
        given=(
            worked("n", n, f"n = {n}"),
            worked("b", bits, f"b = {bits} \\text{{ bit per pixel}}"),
        ),
        derived=tuple(derived),
        notes=(
            "Each pattern contains the one before it (the cells turn on in the order of the "
            "Bayer matrix), so a region of slowly changing intensity shows no contour.",
        ),
        walk=Walk(tables=(table,)),
        plot=Plot(figures=figures),
        data={"levels": count, "patterns": {lv: [list(r) for r in p] for lv, p in patterns}},
    )
