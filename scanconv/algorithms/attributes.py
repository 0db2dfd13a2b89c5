"""Line attributes on Bresenham's line: styles from a pixel mask (dashed, dotted) and thick
lines by pixel replication or by a rectangular brush.

Each generator yields one :class:`~scanconv.core.records.Step` per pixel of the centre line
(row 0 the start pixel, then Bresenham's steps), with what the attribute does there in
``extra``.

Conventions, named and settable:

- ``bits``: a mask is read ``msb`` first (as written, left to right: ``11110000``) or ``lsb``
  first (OpenGL's ``glLineStipple``: bit 0 is the first pixel); ``repeat`` draws each bit for
  that many pixels (OpenGL's factor).
- a thick line of width w replicates each pixel across the minor axis (vertically when
  |m| <= 1, horizontally when |m| > 1), ``w`` pixels from ``-((w - 1) // 2)`` to ``w // 2``, so
  an even width puts its extra pixel above (or to the right); a brush is a ``w`` x ``w`` square
  placed the same way around each pixel.

References: Hearn & Baker, *Computer Graphics with OpenGL*, 3rd ed., §5-6 (line attributes:
line width by pixel spans, line style by pixel masks, pen and brush options); the OpenGL 1.x
specification, ``glLineStipple``.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterator
from typing import NamedTuple

from ..core.checks import InputError
from ..core.records import Pixel, Step, new_step
from .lines import bresenham, orient

MAX_MASK = 64
"""The longest mask, in bits."""

MAX_WIDTH = 25
"""The widest line or brush, in pixels."""


class Mask(NamedTuple):
    """A line style: the bits in the order they are applied, and each bit's run length."""

    bits: tuple[int, ...]
    repeat: int


def parse_mask(text: str, order: str = "msb", repeat: int = 1) -> Mask:
    """A mask from ``1``/``0`` digits (``"11110000"``) or hexadecimal (``"0x00FF"``, 4 bits a
    digit), read ``msb`` (as written) or ``lsb`` first.

    >>> parse_mask("1100").bits, parse_mask("0x0F", "lsb").bits
    ((1, 1, 0, 0), (1, 1, 1, 1, 0, 0, 0, 0))
    """
    s = text.strip().lower().replace("_", "")
    if s.startswith("0x"):
        digits = s[2:]
        if not digits or any(c not in "0123456789abcdef" for c in digits):
            raise InputError(f"a hexadecimal mask takes 0-9 and a-f, got {text!r}", "mask")
        bits = "".join(f"{int(c, 16):04b}" for c in digits)
    else:
        bits = s
    if not bits or any(c not in "01" for c in bits):
        raise InputError(f"a mask is 1s and 0s or 0x hexadecimal, got {text!r}", "mask")
    if len(bits) > MAX_MASK:
        raise InputError(f"a mask has at most {MAX_MASK} bits, got {len(bits)}", "mask")
    if order not in ("msb", "lsb"):
        raise InputError(f"bits are read msb or lsb first, got {order!r}", "bits")
    if not 1 <= repeat <= 256:
        raise InputError(f"the repeat factor is 1..256, got {repeat}", "repeat")
    seq = bits if order == "msb" else bits[::-1]
    return Mask(tuple(int(c) for c in seq), repeat)


def centre_line(x1: int, y1: int, x2: int, y2: int) -> Iterator[tuple[int, Pixel]]:
    """The centre line's pixels with their index: the start pixel, then Bresenham's steps.

    >>> list(centre_line(0, 0, 3, 1))
    [(0, (0, 0)), (1, (1, 0)), (2, (2, 1)), (3, (3, 1))]
    """
    sx, sy = orient(x1, y1, x2, y2)[:2]
    yield 0, (sx, sy)
    for s in bresenham(x1, y1, x2, y2):
        yield s.k + 1, s.pixel


def styled(x1: int, y1: int, x2: int, y2: int, mask: Mask) -> Iterator[Step]:
    """The centre line through a mask: ``extra`` is ``(bit index, bit)``; a pixel is drawn
    when its bit is 1.

    >>> [(s.pixel, s.extra) for s in styled(0, 0, 4, 0, parse_mask("10"))]
    [((0, 0), (0, 1)), ((1, 0), (1, 0)), ((2, 0), (0, 1)), ((3, 0), (1, 0)), ((4, 0), (0, 1))]
    """
    n = len(mask.bits)
    for k, pixel in centre_line(x1, y1, x2, y2):
        at = (k // mask.repeat) % n
        yield new_step(Step, (k, None, None, pixel, (at, mask.bits[at])))


def thick_offsets(width: int) -> range:
    """A thick line's offsets from its centre pixel, across the minor axis (or each axis of a
    square brush): ``-(w - 1) // 2 .. w // 2``, an even width's extra pixel above or right.

    >>> list(thick_offsets(3)), list(thick_offsets(4))
    ([-1, 0, 1], [-1, 0, 1, 2])
    """
    if not 1 <= width <= MAX_WIDTH:
        raise InputError(f"the width is 1..{MAX_WIDTH} pixels, got {width}", "width")
    return range(-((width - 1) // 2), width // 2 + 1)


def thick(x1: int, y1: int, x2: int, y2: int, width: int, brush: bool = False) -> Iterator[Step]:
    """A thick line: ``extra`` is ``(pixels added at this step,)``, in order, each pixel once.
    Replication (``brush=False``) spans the minor axis; a brush is a ``width`` square.

    >>> [s.extra[0] for s in thick(0, 0, 2, 0, 3)]
    [((0, -1), (0, 0), (0, 1)), ((1, -1), (1, 0), (1, 1)), ((2, -1), (2, 0), (2, 1))]
    >>> [len(s.extra[0]) for s in thick(0, 0, 2, 1, 2, brush=True)]
    [4, 3, 2]
    """
    span = thick_offsets(width)
    steep = abs(y2 - y1) > abs(x2 - x1)
    if brush:
        offsets = [(dx, dy) for dy in span for dx in span]
    else:
        offsets = [(d, 0) if steep else (0, d) for d in span]
    # The centre line moves one pixel along its major axis a step, so a pixel of this step can
    # only repeat one of the last `width` steps': those are all it remembers (constant memory
    # for a line of any length).
    recent: deque[tuple[Pixel, ...]] = deque(maxlen=width + 1)
    seen: set[Pixel] = set()
    for k, (x, y) in centre_line(x1, y1, x2, y2):
        added = []
        for dx, dy in offsets:
            p = (x + dx, y + dy)
            if p not in seen:
                seen.add(p)
                added.append(p)
        if len(recent) == recent.maxlen:
            seen.difference_update(recent[0])
        recent.append(tuple(added))
        yield new_step(Step, (k, None, None, (x, y), (tuple(added),)))
