"""What every practice question is, and the line question the line topics start from.

:class:`PracticeQuestion` is what each topic's maker returns (:mod:`.notes` for the notes'
topics, :mod:`.beyond` for the others); :func:`line_question` draws a line in a chosen octant,
with or without a tie, and is the notes' line topic and the base of the midpoint line's. Both
sit here, below the two makers' modules, so that neither imports the other's.
"""

from __future__ import annotations

import random
from collections.abc import Callable
from typing import NamedTuple

from ..answers.asked import LineQuestion
from ..answers.methods import method

__all__ = ["LINE", "MARKS", "PracticeQuestion", "line_features", "line_question", "octant"]


class PracticeQuestion(NamedTuple):
    """One generated question."""

    topic: str
    argv: tuple[str, ...]
    """The command line, without ``scanconv``."""
    wording: str
    """The question in words, as an exam would ask it."""
    marks: int
    features: frozenset[str]
    """The variety it shows: ``octant 3``, ``steep``, ``negative slope``, ``right to left``,
    ``tie``, ``centre away``, ``tall``, ``cubic``, ``at t``, ..."""


class _Range(NamedTuple):
    steps: tuple[int, int]
    """Smallest and largest major length (a line's steps)."""
    low: int
    high: int
    """The coordinates' range."""


LINE = {
    "easy": _Range((3, 6), 0, 10),
    "exam": _Range((6, 12), 0, 20),
    "hard": _Range((13, 20), -20, 20),
}
"""The major lengths and coordinates of a line question of each difficulty."""
MARKS = {"easy": 6, "exam": 14, "hard": 14}
"""The marks of a question of each difficulty."""


# the eight octants: (dx, dy) from the major length L and the minor length m
_OCTANTS: dict[int, Callable[[int, int], tuple[int, int]]] = {
    1: lambda L, m: (L, m),
    2: lambda L, m: (m, L),
    3: lambda L, m: (-m, L),
    4: lambda L, m: (-L, m),
    5: lambda L, m: (-L, -m),
    6: lambda L, m: (-m, -L),
    7: lambda L, m: (m, -L),
    8: lambda L, m: (L, -m),
}


def octant(dx: int, dy: int) -> int:
    """The octant (1 to 8, counter-clockwise from the positive x axis) of the direction
    ``(dx, dy)`` of a line that is neither horizontal, vertical nor diagonal.

    >>> [octant(8, 4), octant(4, 8), octant(-4, 8), octant(-8, -4), octant(8, -4)]
    [1, 2, 3, 5, 8]
    """
    steep = abs(dy) > abs(dx)
    if dx > 0 and dy > 0:
        return 2 if steep else 1
    if dx < 0 < dy:
        return 3 if steep else 4
    if dx < 0 and dy < 0:
        return 6 if steep else 5
    return 7 if steep else 8


def line_features(dx: int, dy: int, tie: bool) -> frozenset[str]:
    """The variety a line shows.

    >>> sorted(line_features(-3, 6, False))
    ['negative slope', 'octant 3', 'right to left', 'steep']
    """
    found = {f"octant {octant(dx, dy)}"}
    if abs(dy) > abs(dx):
        found.add("steep")
    if (dx < 0) != (dy < 0):
        found.add("negative slope")
    if dx < 0:
        found.add("right to left")
    if tie:
        found.add("tie")
    return frozenset(found)


def line_question(
    rng: random.Random, difficulty: str, kind: tuple[int, bool], algo: str | None = None
) -> PracticeQuestion:
    """A line question of ``difficulty`` in the octant ``kind[0]``, with a tie (slope 1/2 with
    an odd minor length) when ``kind[1]``, by ``algo`` (a line method with a practice wording),
    else by the DDA or Bresenham's algorithm (the notes' two)."""
    which, tie = kind
    r = LINE[difficulty]
    lo, hi = r.steps
    if tie:  # slope 1/2 with an odd minor length: p = 0 in Bresenham, .5 in DDA
        major = rng.choice([n for n in range(lo, hi + 1) if n % 4 == 2])
        minor = major // 2
    else:
        major = rng.randrange(lo, hi + 1)
        minor = rng.choice([m for m in range(1, major) if 2 * m != major] or [1])
    dx, dy = _OCTANTS[which](major, minor)
    x1 = rng.randrange(max(r.low, r.low - dx), min(r.high, r.high - dx) + 1)
    y1 = rng.randrange(max(r.low, r.low - dy), min(r.high, r.high - dy) + 1)
    x2, y2 = x1 + dx, y1 + dy
    if algo is None:
        algo = rng.choice(("dda", "bresenham"))
    return PracticeQuestion(
        "line",
        ("line", str(x1), str(y1), str(x2), str(y2), "--algo", algo),
        method("line", algo).load("practice")(LineQuestion(algo, x1, y1, x2, y2)),
        MARKS[difficulty],
        line_features(dx, dy, tie) | {algo},
    )
