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

METHODS = ("threshold", "ordered", "lookup", "floyd-steinberg", "pattern")
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
        dict(threshold=t, compare=compare),  # JSON keys
    )


def _dither_matrix(matrix: int | Sequence[Sequence[Number]]) -> tuple[d.Matrix, str]:
    if isinstance(matrix, int):
        return d.bayer(matrix), f"the {matrix} x {matrix} Bayer matrix"
    m = d.check_matrix(matrix, "dither matrix", "matrix")
    if len(m) > d.MAX_ORDER or len(m[0]) > d.MAX_ORDER:
        raise InputError(f"a dither matrix is at most {d.MAX_ORDER} wide", "matrix")
    return m, f"the {len(m)} x {len(m[0])} matrix given"


def _thresholds(
    dm: d.Matrix, top: Number, scale: str, base: str, transpose: bool
) -> tuple[d.Matrix, list[Quantity], str]:
    """The threshold matrix of ``dm``, the working that gives it (D, the rule, T) and its
    conventions in words for the notes."""
    table = d.thresholds(dm, top, scale=scale, base=base, transpose=transpose)
    read = "by columns (transposed)" if transpose else "by rows"
    if scale == "given":  # the entries are the thresholds, in the image's units
        how = rule("T", r"T = D \text{ (the entries are thresholds, in the image's units)}")
        note = f"thresholds given (T = D, in the image's units), the matrix read {read}"
    else:
        n2 = len(dm) * len(dm[0])
        shift = "" if base == "0" else " - 1"
        half = " + 1/2" if scale == "centered" else ""
        how = rule("T", f"T(d) = (d{shift}{half}) \\cdot {fmt_short(top)} / {n2}")
        note = (
            f"thresholds {scale} (T = (d{shift}{half}) * top / n^2), entries from {base}, "
            f"the matrix read {read}"
        )
    return table, [_matrix("D", "D", dm), how, _matrix("thresholds", "T", table)], note


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
    rel = _COMPARE_TEX[d.choice("compare", compare)]
    table, derived, t_note = _thresholds(dm, top, scale, base, transpose)
    derived.append(
        rule(
            "test",
            f"\\text{{on when }} I(i, j) {rel} T[i \\bmod {len(table)}][j \\bmod {len(table[0])}]",
        )
    )
    notes = [f"Conventions: compare {compare}, {t_note}."]
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


MAX_LOOKUPS = 64
"""The most pixels looked up in one answer."""


def _lookup_columns(n: int, m: int) -> tuple[Column, ...]:
    """The columns of a lookup table (``value`` and ``output`` last: left out with no value)."""
    return (
        heading("k", "k"),
        heading("x", "x"),
        heading("y", "y"),
        heading("i", "i"),
        heading("j", "j"),
        heading("row", rf"i \bmod {n}"),
        heading("col", rf"j \bmod {m}"),
        heading("threshold", "T"),
        heading("value", "I"),
        heading("output", r"\text{output}"),
    )


def lookup_solution(
    pixels: Sequence[tuple[int, int]],
    matrix: int | Sequence[Sequence[Number]] = 4,
    top: Number = 1,
    *,
    value: Number | None = None,
    count: str = "0",
    compare: str = ">",
    scale: str = "raw",
    base: str = "0",
    transpose: bool = False,
) -> Solution:
    """Each pixel's threshold from its screen position: ``T[(y - c) mod n][(x - c) mod n]``
    (positions counted from ``c`` = ``count``), and whether a pixel of intensity ``value`` there
    is on.

    >>> sol = lookup_solution([(5, 2)], 4, 16, value=10)
    >>> [s.extra for s in sol.steps()]
    [(5, 2, 2, 5, 2, 1, 11, 10, 0)]
    """
    if not 1 <= len(pixels) <= MAX_LOOKUPS:
        raise InputError(f"give 1 .. {MAX_LOOKUPS} pixels (X Y pairs), got {len(pixels)}", "pixels")
    if not top > 0:
        raise InputError(f"the scale's top must be positive, got {fmt_short(top)}", "top")
    dm, named = _dither_matrix(matrix)
    rel = _COMPARE_TEX[d.choice("compare", compare)]
    table, derived, t_note = _thresholds(dm, top, scale, base, transpose)
    c = int(d.choice("count", count))
    found = [d.lookup(table, x, y, count) for x, y in pixels]
    n, m = len(table), len(table[0])
    at = f"y - {c}" if c else "y"
    derived.append(
        rule(
            "lookup",
            f"i = {at}, \\; j = {at.replace('y', 'x')}, \\; T(x, y) = "
            f"T[i \\bmod {n}][j \\bmod {m}]",
        )
    )
    if value is not None:
        derived.append(
            rule("test", f"\\text{{on when }} I {rel} T(x, y), \\; I = {fmt_short(value)}")
        )
    outputs = None if value is None else [int(d._on(value, f.threshold, compare)) for f in found]
    notes = [
        f"Conventions: positions counted from {c} (x across, y down: row i = {at}, column "
        f"j = {at.replace('y', 'x')}), {t_note}, compare {compare}.",
    ]

    def steps() -> Iterator[Step]:
        for k, ((x, y), f) in enumerate(zip(pixels, found, strict=True)):
            extra = (x, y, f.i, f.j, f.row, f.col, f.threshold)
            decided = () if outputs is None else (value, outputs[k])
            yield Step(k, None, None, (x, y), extra + decided)

    columns = _lookup_columns(n, m)
    keys = ("x", "y", "i", "j", "row", "col", "threshold", "value", "output")
    return Solution(
        primitive="dither",
        algorithm="lookup",
        title=f"Dither thresholds looked up by position ({named})",
        given=(
            worked(
                "pixels",
                [list(p) for p in pixels],
                "(x, y) = " + ", ".join(f"({x}, {y})" for x, y in pixels),
            ),
            worked("top", top, f"\\text{{intensities on the scale }} 0 \\ldots {fmt_short(top)}"),
        ),
        derived=tuple(derived),
        walk=Walk(
            columns=columns if value is not None else columns[:-2],
            extra_keys=keys if value is not None else keys[:-2],
            steps=steps,
        ),
        notes=tuple(notes),
        data={
            "matrix": [list(r) for r in dm],
            "thresholds": [list(r) for r in table],
            "lookups": [f.threshold for f in found],
            "output": outputs,
            "compare": compare,
        },
    )


def _over(weight: Fraction, divisor: int) -> str:
    """A kernel weight over the kernel's published divisor: ``2/8``, not ``1/4``."""
    return "1" if divisor == 1 else f"{weight * divisor}/{divisor}"


def _carries_text(carries: Sequence[d.Carry]) -> str:
    """Each share in the form of the table's other values (3 decimals, a whole number as it is),
    never a decimal in one row and a fraction in the next (issue 39, item 8)."""
    return ", ".join(f"({c.pixel[1]}, {c.pixel[0]}) += {fmt(c.amount)}" for c in carries)


def _diffusion_notes(
    img: d.Matrix, top: Number, kernel: str, order: str, arithmetic: str, carry: str, compare: str
) -> list[str]:
    """The conventions of an error diffusion, its kernel's source and its mean bound."""
    half = normalize(Fraction(top) / 2)
    notes = [
        f"Conventions: kernel {kernel}, {order} order, {arithmetic} arithmetic, negative "
        f"carries {carry}, on when I' {compare} {fmt_short(half)}; outputs 0 and {fmt_short(top)}.",
        "I' is the pixel's value plus the error it received; shares that fall outside the "
        "image are lost.",
        f"Kernel {kernel}: weights over {d.KERNELS[kernel].divisor}, summing to 1; "
        f"{d.KERNELS[kernel].source}.",
    ]
    if order == "serpentine":
        notes.append("Odd rows are scanned right to left, the kernel mirrored (j - 1 is ahead).")
    if arithmetic == "exact" and carry == "kept":
        lost = d.lost_weight(kernel, len(img), len(img[0]), order)
        notes.append(
            "The mean is kept within its bound: each error is at most top/2, so the input's "
            "total less the output's (the shares lost off the edges) is at most top/2 x "
            f"{fmt_short(lost)} (the kernel weight falling outside) = "
            f"{fmt_short(normalize(Fraction(top) / 2 * lost))}."
        )
    return notes


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
    shares = d.KERNELS[d.choice("kernel", kernel)].shares
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
                f"{_over(s.weight, d.KERNELS[kernel].divisor)} \\text{{ to }} (i{s.di:+d}, j{s.dj:+d})"
                for s in shares
            ),
        ),
    ]
    notes = _diffusion_notes(img, top, kernel, order, arithmetic, carry, compare)

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
        dict(kernel=kernel, order=order, arithmetic=arithmetic, carry=carry, compare=compare),
    )


_ORDER_NOTES = {
    "bayer": "the cells turn on in the order of the Bayer matrix",
    "clustered": "a dot grows from the cell's centre, nearest cells first, ties row by row",
    "given": "the cells turn on in the order given",
}


def _cell(n: int, order: str, matrix: Sequence[Sequence[Number]] | None) -> tuple[Any, str]:
    """The cell's order (ranks 0 .. n² - 1) and how it was made, in words."""
    if matrix is not None:
        ranks = d.check_cell(matrix)
        if len(ranks) != n:
            raise InputError(f"the cell's order is {len(ranks)} wide, not {n}", "matrix")
        return ranks, _ORDER_NOTES["given"]
    ranks = d.cell_order(n, order)
    if order == "bayer" and n & (n - 1):
        side = 1 << (n - 1).bit_length()
        return ranks, (
            f"the cells turn on in the order of the top-left {n} x {n} block of the "
            f"{side} x {side} Bayer matrix, its entries ranked 0 .. {n * n - 1}"
        )
    return ranks, _ORDER_NOTES[order]


def pattern_solution(
    n: int,
    level: int | None = None,
    bits: int = 1,
    *,
    order: str = "bayer",
    matrix: Sequence[Sequence[Number]] | None = None,
) -> Solution:
    """The n x n halftone patterns (any n from 1 to 16): how many levels they give and the
    pattern of each level (or of one ``level``); ``order`` how the cell fills (``bayer`` or
    ``clustered``), or the order given as a ``matrix``.

    >>> sol = pattern_solution(2)
    >>> [r[1] for r in sol.tables[0].rows()]
    ['0 0 / 0 0', '1 0 / 0 0', '1 0 / 0 1', '1 1 / 0 1', '1 1 / 1 1']
    >>> pattern_solution(5).data["levels"]
    26
    """
    if not 1 <= n <= d.MAX_ORDER:
        raise InputError(f"a halftone cell is 1 .. {d.MAX_ORDER} pixels wide, got {n}", "n")
    if not 1 <= bits <= 8:
        raise InputError(f"bits per pixel must be 1..8, got {bits}", "bits")
    ranks, how = _cell(n, order, matrix)
    count = d.pattern_levels(n, bits)
    levels = range(n * n + 1) if level is None else (level,)
    patterns = [(lv, d.pattern(n, lv, ranks)) for lv in levels]
    derived = [
        _matrix("D", "D", ranks),
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
            f"Each pattern contains the one before it ({how}), so a region of slowly changing "
            "intensity shows no contour.",
            f"An n x n cell of bilevel dots gives n^2 + 1 = {n * n + 1} nested levels: level l has "
            "l dots on.",
        ),
        walk=Walk(tables=(table,)),
        plot=Plot(figures=figures),
        data={
            "levels": count,
            "order": [list(r) for r in ranks],
            "patterns": {lv: [list(r) for r in p] for lv, p in patterns},
        },
    )
