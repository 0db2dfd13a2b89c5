"""Halftoning and dithering: thresholding, ordered dither, error diffusion and halftone patterns.

Every generator yields one :class:`~scanconv.core.records.Step` per pixel, in the scan order,
with exact values: ``pixel`` is ``(j, i)`` (column, row; row 0 is the image's first row, drawn at
the top), ``p`` and ``decision`` are ``None``, and ``extra`` holds the numbers a student writes
in the table (named by each generator).

The conventions that change the printed numbers are named and settable (:data:`DITHER_KNOBS`):

- ``compare``: a pixel is on when its value is ``>`` the threshold (Hearn & Baker: "if
  I > D_n(j, k), we turn on the pixel") or ``>=`` it;
- ``scale``: the threshold of matrix entry d on the scale 0..top is ``d·top/n²`` (``raw``: the
  intensity scaled to 0..n² compared with d itself, Hearn & Baker's form) or ``(d + 1/2)·top/n²``
  (``centered``: the middle of the entry's band),
  or the entries taken as thresholds already in the image's units (``given``);
- ``count``: a pixel's screen position counted from 0 or from 1 (a threshold looked up at
  ``(x, y)`` is ``D[(y - c) mod n][(x - c) mod n]``);
- ``base``: matrix entries counted from 0 (``0 .. n² - 1``, the usual Bayer matrix) or from 1;
- ``transpose``: the matrix read as ``D[i mod n][j mod n]`` (row by row, the default) or as
  ``D[j mod n][i mod n]`` (Hearn & Baker index D by x first);
- error diffusion: the ``kernel`` (Floyd–Steinberg's 7/16, 3/16, 5/16, 1/16, the simple
  3/8, 3/8, 2/8 taught under the same name, Jarvis–Judice–Ninke, Stucki, Burkes, the Sierra
  family or the one-dimensional kernel: :data:`KERNELS`, each with its source), the ``order`` (``raster`` or ``serpentine``),
  ``arithmetic`` (``exact`` fractions, or ``integer``: each share truncated toward zero as C's
  integer division does) and ``carry`` (negative errors ``kept`` or ``clamped`` at 0).

References: R. W. Floyd and L. Steinberg, "An adaptive algorithm for spatial greyscale",
Proc. SID 17 (1976); B. E. Bayer, "An optimum method for two-level rendition of continuous-tone
pictures", ICC 1973; Hearn & Baker, *Computer Graphics with OpenGL*, 3rd ed., §4-... (halftone
patterns and dithering techniques).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize
from ..core.records import Step, new_step

Matrix = tuple[tuple[Number, ...], ...]
"""A matrix of exact values, row 0 first."""

MAX_ORDER = 16
"""The largest Bayer matrix built (16 x 16: 256 thresholds)."""

MAX_CELLS = 4096
"""The largest image dithered in a step table (64 x 64 pixels)."""


class Share(NamedTuple):
    """One neighbour's share of an error: ``(di, dj, weight)``, ``dj`` toward the scan."""

    di: int
    dj: int
    weight: Fraction


class Kernel(NamedTuple):
    """One error-diffusion kernel: its name, the common denominator it is published with (its
    weights are written over it), each share's offset from the pixel and its weight (they sum
    to 1, so the error is moved, not lost), and where it is published (its answer names it in
    a note)."""

    name: str
    divisor: int
    shares: tuple[Share, ...]
    source: str


def _kernel(name: str, divisor: int, source: str, *rows: tuple[int, tuple[int, ...]]) -> Kernel:
    """A kernel written as published: each row ``(di, weights)`` with the weights of columns
    ``j - 2 .. j + 2`` (the current row's from ``j + 1``), over ``divisor``."""
    shares = []
    for di, weights in rows:
        first = 1 if di == 0 else -(len(weights) // 2)
        shares += [Share(di, first + k, Fraction(w, divisor)) for k, w in enumerate(weights) if w]
    return Kernel(name, divisor, tuple(shares), source)


_HELLAND = 'T. Helland, "Image dithering: eleven algorithms" (2012)'
_CROCKER = "as tabled in L. Crocker's DHALF.TXT"

KERNELS: dict[str, Kernel] = {
    k.name: k
    for k in (
        _kernel(
            "floyd-steinberg",
            16,
            'R. W. Floyd and L. Steinberg, "An adaptive algorithm for spatial greyscale", '
            "Proc. SID 17 (1976)",
            (0, (7,)),
            (1, (3, 5, 1)),
        ),
        Kernel(  # no paper; taught under Floyd and Steinberg's name
            "simple",
            8,
            (Share(0, 1, Fraction(3, 8)), Share(1, 0, Fraction(3, 8)), Share(1, 1, Fraction(2, 8))),
            "the three-share simplification taught under Floyd and Steinberg's name "
            "(3/8 right, 3/8 below, 2/8 below right)",
        ),
        _kernel(
            "jarvis-judice-ninke",
            48,
            'J. F. Jarvis, C. N. Judice and W. H. Ninke, "A survey of techniques for the display '
            'of continuous tone pictures on bilevel displays", Computer Graphics and Image '
            "Processing 5 (1976)",
            (0, (7, 5)),
            (1, (3, 5, 7, 5, 3)),
            (2, (1, 3, 5, 3, 1)),
        ),
        _kernel(
            "stucki",
            42,
            'P. Stucki, "MECCA - a multiple-error correction computation algorithm for bi-level '
            'image hardcopy reproduction", IBM Research RZ1060 (1981)',
            (0, (8, 4)),
            (1, (2, 4, 8, 4, 2)),
            (2, (1, 2, 4, 2, 1)),
        ),
        _kernel(
            "burkes",
            32,
            f"D. Burkes, the Burkes error filter (1988), {_CROCKER} (1989) and {_HELLAND}",
            (0, (8, 4)),
            (1, (2, 4, 8, 4, 2)),
        ),
        _kernel(
            "sierra",
            32,
            f"F. Sierra (1989), {_CROCKER} and T. Helland (2012)",
            (0, (5, 3)),
            (1, (2, 4, 5, 4, 2)),
            (2, (0, 2, 3, 2, 0)),
        ),
        _kernel(
            "two-row-sierra",
            16,
            f"F. Sierra (1990), {_CROCKER} and T. Helland (2012)",
            (0, (4, 3)),
            (1, (1, 2, 3, 2, 1)),
        ),
        _kernel(
            "sierra-lite",
            4,
            'F. Sierra\'s "Filter Lite" (1990), as tabled in T. Helland (2012)',
            (0, (2,)),
            (1, (1, 1, 0)),
        ),
        _kernel(
            "one-dimensional",
            1,
            "one-dimensional error diffusion, all of the error to the next pixel of the row "
            '(S. Hocevar, "Libcaca study", part 3, "Error diffusion" (2007); Wikipedia, '
            '"Error diffusion")',
            (0, (1,)),
        ),
    )
}
"""The error-diffusion kernels, by name."""

DITHER_KNOBS: dict[str, tuple[str, ...]] = dict(  # knob names (one, arithmetic, is also a method's)
    compare=(">", ">="),
    scale=("raw", "centered", "given"),
    base=("0", "1"),
    count=("0", "1"),
    kernel=tuple(KERNELS),  # the kernels' records, above
    order=("raster", "serpentine"),
    arithmetic=("exact", "integer"),
    carry=("kept", "clamped"),
)
"""Each named convention and its values, the default first."""


def choice_of(values: Sequence[str], value: str, knob: str) -> str:
    """``value`` if it is one of ``values``, else :class:`InputError` naming them."""
    if value not in values:
        raise InputError(f"unknown {knob} {value!r} (choose from {', '.join(values)})", knob)
    return value


def choice(knob: str, value: str) -> str:
    """``value`` if it is one of the knob's values, else :class:`InputError` naming them."""
    return choice_of(DITHER_KNOBS[knob], value, knob)


def bayer(n: int) -> tuple[tuple[int, ...], ...]:
    """The n x n Bayer matrix (n a power of 2 up to :data:`MAX_ORDER`), entries 0 .. n² - 1:
    ``D_2 = [[0, 2], [3, 1]]`` and ``D_2n = [[4D_n, 4D_n + 2], [4D_n + 3, 4D_n + 1]]``.

    >>> bayer(2)
    ((0, 2), (3, 1))
    >>> bayer(4)[0], bayer(4)[3]
    ((0, 8, 2, 10), (15, 7, 13, 5))
    """
    if n < 2 or n > MAX_ORDER or n & (n - 1):
        raise InputError(f"a Bayer matrix is 2, 4, 8 or 16 wide, got {n}", "matrix")
    d: list[list[int]] = [[0]]
    while len(d) < n:
        d = [
            *(
                [4 * v + a for v in row] + [4 * v + b for v in row]
                for row in d
                for a, b in [(0, 2)]
            ),
            *(
                [4 * v + a for v in row] + [4 * v + b for v in row]
                for row in d
                for a, b in [(3, 1)]
            ),
        ]
    return tuple(tuple(row) for row in d)


def check_matrix(rows: Sequence[Sequence[Number]], what: str, param: str) -> Matrix:
    """``rows`` as an exact matrix: at least one row, every row as long, at most
    :data:`MAX_CELLS` cells."""
    if not rows or not rows[0]:
        raise InputError(f"the {what} has no values", param)
    width = len(rows[0])
    if any(len(r) != width for r in rows):
        raise InputError(f"every row of the {what} must have {width} values", param)
    if len(rows) * width > MAX_CELLS:
        raise InputError(
            f"the {what} has {len(rows) * width:,} cells; at most {MAX_CELLS:,} are worked", param
        )
    return tuple(tuple(normalize(Fraction(v)) for v in r) for r in rows)


def thresholds(
    matrix: Sequence[Sequence[Number]],
    top: Number,
    *,
    scale: str = "raw",
    base: str = "0",
    transpose: bool = False,
) -> Matrix:
    """The threshold of each matrix cell on the scale 0 .. ``top``.

    >>> thresholds(bayer(2), 4)
    ((0, 2), (3, 1))
    >>> thresholds(bayer(2), 1, scale="centered")
    ((Fraction(1, 8), Fraction(5, 8)), (Fraction(7, 8), Fraction(3, 8)))
    """
    choice("scale", scale)
    shift = int(choice("base", base))
    if scale == "given":  # the entries are the thresholds, in the image's units
        given = tuple(zip(*matrix, strict=True)) if transpose else matrix
        return tuple(tuple(normalize(Fraction(v)) for v in row) for row in given)
    n2 = len(matrix) * len(matrix[0])
    half = Fraction(1, 2) if scale == "centered" else 0
    cells = tuple(zip(*matrix, strict=True)) if transpose else matrix
    return tuple(
        tuple(normalize((Fraction(d) - shift + half) * Fraction(top) / n2) for d in row)
        for row in cells
    )


def _on(value: Number, threshold: Number, compare: str) -> int:
    return int(value > threshold if compare == ">" else value >= threshold)


def ordered(image: Matrix, table: Matrix, compare: str = ">") -> Iterator[Step]:
    """Ordered dither: pixel (j, i) is on when its value passes ``table[i mod n][j mod m]``.
    ``extra`` is ``(value, threshold, output)``.

    >>> [s.extra for s in ordered(((1, 3),), thresholds(bayer(2), 4))]
    [(1, 0, 1), (3, 2, 1)]
    """
    choice("compare", compare)
    n, m = len(table), len(table[0])
    for i, row in enumerate(image):
        for j, v in enumerate(row):
            t = table[i % n][j % m]
            yield new_step(Step, (i * len(row) + j, None, None, (j, i), (v, t, _on(v, t, compare))))


class Lookup(NamedTuple):
    """One pixel's threshold looked up from its screen position: the position counted from 0,
    the matrix cell it falls on and the threshold there."""

    i: int
    j: int
    row: int
    col: int
    threshold: Number


def lookup(table: Matrix, x: int, y: int, count: str = "0") -> Lookup:
    """The threshold of the pixel at column ``x``, row ``y`` (counted from ``count``):
    ``table[(y - c) mod n][(x - c) mod m]``.

    >>> lookup(thresholds(bayer(4), 16), 5, 2)
    Lookup(i=2, j=5, row=2, col=1, threshold=11)
    >>> lookup(thresholds(bayer(4), 16), 6, 3, "1").threshold
    11
    """
    c = int(choice("count", count))
    i, j = y - c, x - c
    if i < 0 or j < 0:
        raise InputError(f"positions count from {c}: got ({x}, {y})", "pixels")
    n, m = len(table), len(table[0])
    return Lookup(i, j, i % n, j % m, table[i % n][j % m])


def threshold(image: Matrix, t: Number, compare: str = ">=") -> Iterator[Step]:
    """Thresholding at one value ``t``: ``extra`` is ``(value, t, output)``.

    >>> [s.extra[2] for s in threshold(((0, 5, 10),), 5)]
    [0, 1, 1]
    """
    return ordered(image, ((t,),), compare)


class Carry(NamedTuple):
    """One share of a diffused error: the pixel it goes to and the amount."""

    pixel: tuple[int, int]
    amount: Number


def _share(err: Number, weight: Fraction, arithmetic: str) -> Number:
    amount = err * weight
    if arithmetic == "integer":  # C's integer division: toward zero
        whole = abs(amount.numerator) // amount.denominator
        return whole if amount >= 0 else -whole
    return normalize(amount)


def error_diffusion(
    image: Matrix,
    top: Number,
    *,
    kernel: str = "floyd-steinberg",
    order: str = "raster",
    arithmetic: str = "exact",
    carry: str = "kept",
    compare: str = ">=",
) -> Iterator[Step]:
    """Error diffusion to two levels (0 and ``top``), one step per pixel in scan order.

    The pixel's value (its own plus what it received) is compared with ``top / 2``; the output
    is ``top`` or 0; the error ``value - output`` is shared among the unvisited neighbours by the
    kernel (the shares that fall outside the image are lost). ``extra`` is
    ``(received, value, output, error, carries)``.

    >>> for s in error_diffusion(((100, 100), (100, 100)), 255):
    ...     print(s.pixel, s.extra[1], s.extra[2], s.extra[3])
    (0, 0) 100 0 100
    (1, 0) 575/4 255 -445/4
    (0, 1) 7065/64 0 7065/64
    (1, 1) 122655/1024 0 122655/1024
    """
    shares = KERNELS[choice("kernel", kernel)].shares
    for knob, given in (("order", order), ("arithmetic", arithmetic), ("carry", carry)):
        choice(knob, given)
    choice("compare", compare)
    rows, cols = len(image), len(image[0])
    received = [[Fraction(0)] * cols for _ in range(rows)]
    half = Fraction(top) / 2
    k = 0
    for i in range(rows):
        backward = order == "serpentine" and i % 2 == 1
        direction = -1 if backward else 1
        for j in range(cols - 1, -1, -1) if backward else range(cols):
            value = normalize(Fraction(image[i][j]) + received[i][j])
            out = top if _on(value, half, compare) else 0
            err = normalize(value - out)
            spread = 0 if carry == "clamped" and err < 0 else err
            carries: list[Carry] = []
            for s in shares if spread else ():
                ti, tj = i + s.di, j + s.dj * direction
                if 0 <= ti < rows and 0 <= tj < cols:
                    amount = _share(spread, s.weight, arithmetic)
                    received[ti][tj] += amount
                    carries.append(Carry((tj, ti), amount))
            extra = (normalize(received[i][j]), value, out, err, tuple(carries))
            yield new_step(Step, (k, None, None, (j, i), extra))
            k += 1


CELL_ORDERS = ("bayer", "clustered")
"""How an n x n halftone cell's dots turn on (:func:`cell_order`), the default first."""


def cell_order(n: int, order: str = "bayer") -> tuple[tuple[int, ...], ...]:
    """The rank 0 .. n² - 1 at which each dot of an n x n halftone cell turns on (1 <= n <=
    :data:`MAX_ORDER`).

    ``bayer`` (dispersed): the Bayer matrix when n is a power of 2; for any other n the
    top-left n x n block of the Bayer matrix of the next power of 2, its entries ranked.
    ``clustered``: a dot growing from the cell's centre, nearest dots first (ties: row by row,
    top first, then left to right).

    >>> cell_order(2), cell_order(3)
    (((0, 2), (3, 1)), ((0, 5, 2), (7, 4, 8), (3, 6, 1)))
    >>> cell_order(3, "clustered")
    ((5, 1, 6), (2, 0, 3), (7, 4, 8))
    """
    if not 1 <= n <= MAX_ORDER:
        raise InputError(f"a halftone cell is 1 .. {MAX_ORDER} dots wide, got {n}", "n")
    if choice_of(CELL_ORDERS, order, "order") == "bayer":
        side = 1 << (n - 1).bit_length()
        block = [row[:n] for row in bayer(side)[:n]] if side > 1 else [[0]]
        key: dict[tuple[int, int], tuple[Number, ...]] = {
            (i, j): (block[i][j],) for i in range(n) for j in range(n)
        }
    else:
        c = Fraction(n - 1, 2)
        key = {(i, j): ((i - c) ** 2 + (j - c) ** 2, i, j) for i in range(n) for j in range(n)}
    ranked = {cell: r for r, cell in enumerate(sorted(key, key=key.__getitem__))}
    return tuple(tuple(ranked[i, j] for j in range(n)) for i in range(n))


def check_cell(rows: Sequence[Sequence[Number]]) -> tuple[tuple[int, ...], ...]:
    """A cell's order given: a square matrix holding 0 .. n² - 1 (or 1 .. n², shifted to 0)
    once each."""
    m = check_matrix(rows, "cell order", "matrix")
    n = len(m)
    if len(m[0]) != n or n > MAX_ORDER:
        raise InputError(f"a cell's order is square, at most {MAX_ORDER} wide", "matrix")
    flat = sorted(m[i][j] for i in range(n) for j in range(n))
    shift = 1 if flat == list(range(1, n * n + 1)) else 0
    if flat != list(range(shift, n * n + shift)):
        raise InputError(f"a {n} x {n} cell's order holds 0 .. {n * n - 1} once each", "matrix")
    return tuple(tuple(int(v) - shift for v in row) for row in m)


def pattern(
    n: int, level: int, order: Sequence[Sequence[int]] | None = None
) -> tuple[tuple[int, ...], ...]:
    """The n x n halftone pattern of intensity ``level`` (0 .. n²): the dots whose rank in the
    cell's ``order`` (default :func:`cell_order`) is below the level are on, so each pattern
    contains the one before (no contouring).

    >>> pattern(2, 1), pattern(2, 3)
    (((1, 0), (0, 0)), ((1, 1), (0, 1)))
    """
    if not 0 <= level <= n * n:
        raise InputError(f"a {n} x {n} pattern has levels 0 .. {n * n}, got {level}", "level")
    ranks = cell_order(n) if order is None else order
    return tuple(tuple(int(d < level) for d in row) for row in ranks)


def lost_weight(kernel: str, rows: int, cols: int, order: str = "raster") -> Fraction:
    """The kernel weight of every pixel's shares that fall outside a ``rows`` x ``cols`` image,
    summed: with exact shares and negative errors kept, the input's total less the output's is
    at most ``top / 2`` times this (each error is at most ``top / 2``).

    >>> lost_weight("floyd-steinberg", 2, 2)  # 3/16 + (7 + 1)/16 + (3 + 5 + 1)/16 + 1
    Fraction(9, 4)
    >>> lost_weight("one-dimensional", 3, 4)
    Fraction(3, 1)
    """
    total = Fraction(0)
    for i in range(rows):
        sign = -1 if order == "serpentine" and i % 2 else 1
        for j in range(cols):
            for s in KERNELS[kernel].shares:
                if not (0 <= i + s.di < rows and 0 <= j + sign * s.dj < cols):
                    total += s.weight
    return total


def pattern_levels(n: int, bits: int = 1) -> int:
    """The intensity levels n x n cells of ``bits``-bit pixels give: ``n²(2^b - 1) + 1``.

    >>> pattern_levels(2), pattern_levels(3, 2)
    (5, 28)
    """
    return n * n * ((1 << bits) - 1) + 1
