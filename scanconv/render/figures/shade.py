"""The shaded text picture of a gray-level matrix (the image answers' figure).

Level 0 is black (the darkest character), level L - 1 white (a space).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from fractions import Fraction

from ...core.numeric import round_half_up
from ...core.records import ShadedMatrix

SHADES = "@%#*+=-:. "
"""Picture characters from darkest (black) to lightest (white), for up to 10 levels."""

SHADES_LONG = "@B%8&WM#*oahkbdpqwmZO0QLCJUYXzcvunxrjft/()1{}[]?-_+~<>i!lI;:,^'. "
"""A longer dark-to-light ramp (Paul Bourke's, without ``$ \\ | " ```), for up to 65 levels."""


def _ramp(levels: int) -> str:
    return SHADES if levels <= len(SHADES) else SHADES_LONG


def shade(k: int, levels: int) -> str:
    """The picture character of level ``k``: ``round_half_up(k (R - 1) / (L - 1))`` along the
    ramp. Up to 10 levels use :data:`SHADES`, more use
    :data:`SHADES_LONG` (R characters); beyond R levels, neighbouring levels share a character.

    >>> shade(0, 8), shade(7, 8), shade(128, 256)
    ('@', ' ', 'u')
    """
    ramp = _ramp(levels)
    return ramp[round_half_up(Fraction(k * (len(ramp) - 1), levels - 1))]


def shade_chars(levels: int) -> str:
    """The picture characters of levels ``0 .. L - 1``, darkest first (the ramp if L > R).

    >>> shade_chars(8), shade_chars(2)
    ('@%*+=-. ', '@ ')
    """
    ramp = _ramp(levels)
    if levels > len(ramp):
        return ramp
    return "".join(shade(k, levels) for k in range(levels))


def shade_lines(rows: Iterable[Sequence[int]], levels: int, width: int) -> list[str]:
    """A shaded text picture of a level matrix, framed, with a legend.

    >>> print("\\n".join(shade_lines([[0, 1], [1, 0]], 2, 2)))
    +--+
    |@ |
    | @|
    +--+
    shades: '@' = 0 (black), ' ' = 1 (white); row 0 at the top
    """
    chars = shade_chars(levels)
    border = "+" + "-" * width + "+"
    lines = [border]
    # shade_lines(ramp 8x8, L=8) -> |@%*+=-. | ; |%*+=-. .| ; ...
    for row in rows:
        lines.append("|" + "".join(shade(int(v), levels) for v in row) + "|")
    lines.append(border)
    if levels <= 16 and len(chars) == levels:
        legend = ", ".join(
            f"{chars[k]!r} = {k}"
            + (" (black)" if k == 0 else " (white)" if k == levels - 1 else "")
            for k in range(levels)
        )
    elif len(chars) == levels:
        legend = (
            f"{chars[0]!r} = 0 (black) to {chars[-1]!r} = {levels - 1} (white), one character "
            f"per level, darkest first: {chars}"
        )
    else:
        legend = (
            f"{chars[0]!r} = 0 (black) to {chars[-1]!r} = {levels - 1} (white); {levels} levels "
            f"share {len(chars)} characters in bands, darkest first: {chars}"
        )
    lines.append(f"shades: {legend}; row 0 at the top")
    return lines


def matrix_lines(matrix: ShadedMatrix) -> list[str]:
    """The picture of a :class:`~scanconv.core.records.ShadedMatrix`."""
    return shade_lines(matrix.rows, matrix.levels, matrix.width)
