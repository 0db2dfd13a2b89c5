"""Practice questions: seeded, of a chosen difficulty, with their variety guaranteed.

:func:`practice` returns ``count`` questions as scanconv command lines (with their wording and
marks) from a :class:`random.Random` seeded with ``seed``: the same arguments give the same
questions on every machine and Python version (only ``randrange``, ``choice`` and ``shuffle``
of integers and fixed lists are used, whose results the random module keeps stable).

Variety is built in, not left to chance. Each topic walks a list of *kinds* in an order the
seed shuffles: lines go through the eight octants (so steep and shallow, positive and negative
slopes, left-to-right and right-to-left end points) and half of them have a tie (slope 1/2
with an odd minor length: Bresenham's p hits 0 and DDA's coordinate hits .5); circles and
ellipses alternate centres at and away from the origin (and tall and wide ellipses); curves
alternate quadratic and cubic, ``--at t`` and a table of samples. ``count`` questions of one
topic hold the first ``count`` kinds of its list, so eight line questions show every octant,
and across seeds every kind comes first. No question is degenerate: no line is horizontal,
vertical or diagonal, no radius or semi-axis is below 2, no two control points coincide and no
curve's control points are collinear.

Difficulties: ``easy`` (3 to 6 steps, coordinates 0 to 10), ``exam`` (what the notes' 14-mark
questions look like: 6 to 12 steps, small non-negative integers), ``hard`` (13 to 20 steps,
negative coordinates, larger radii).
"""

from __future__ import annotations

import random
from collections.abc import Callable, Iterator
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..answers.asked import CircleQuestion, EllipseQuestion
from ..answers.methods import method
from ..core import lazy
from ..core.checks import InputError
from .records import MARKS, PracticeQuestion, line_question

if TYPE_CHECKING:
    from . import beyond as practice_more
else:
    practice_more = lazy.module("scanconv.practice.beyond")

TOPICS: tuple[str, ...] = ("line", "circle", "ellipse", "bezier", "bspline", "storage", "quantize")
TOPICS += ("dither", "inside", "clip", "framebuffer")  # beyond the notes: .practice_more
TOPICS += ("attributes", "characters", "midpoint-line", "antialias", "line-methods", "visible")
TOPICS += ("3d",)  # the 3D chapter: transformations and projections
"""The topics a practice set can draw from (``all``: every one, lines most often)."""
DIFFICULTIES = ("easy", "exam", "hard")
MAX_COUNT = 200
"""The most questions in one practice set."""

#: The order ``all`` takes its topics in, repeated: lines and circles most, as in the notes.
MIX: tuple[str, ...] = ("line", "circle", "line", "ellipse", "bezier", "line", "circle")
MIX += ("bspline", "storage", "quantize")


_RADIUS = {"easy": (4, 7), "exam": (8, 15), "hard": (17, 30)}
_AXES = {"easy": (2, 5), "exam": (3, 8), "hard": (8, 14)}
_CENTRE = {"easy": (1, 6), "exam": (2, 10), "hard": (5, 20)}
_CURVE = {"easy": (0, 6), "exam": (0, 10), "hard": (-10, 10)}


def _line_kinds(rng: random.Random) -> list[tuple[int, bool]]:
    """Every octant once with a tie and once without, the first eight covering every
    octant, half of them with ties."""
    order = list(range(1, 9))
    rng.shuffle(order)
    first = [(o, i % 2 == 0) for i, o in enumerate(order)]
    second = [(o, i % 2 == 1) for i, o in enumerate(order)]
    return first + second


def _centre(rng: random.Random, difficulty: str) -> tuple[int, int]:
    lo, hi = _CENTRE[difficulty]
    xc, yc = (rng.randrange(lo, hi + 1) for _ in range(2))
    if difficulty == "hard":  # away from the origin in any quadrant
        xc, yc = xc * rng.choice((1, -1)), yc * rng.choice((1, -1))
    return xc, yc


def _circle(rng: random.Random, difficulty: str, kind: tuple[str, bool]) -> PracticeQuestion:
    name, away = kind
    r = rng.randrange(_RADIUS[difficulty][0], _RADIUS[difficulty][1] + 1)
    argv = ["circle", str(r), "--method", name]
    features = {name}
    xc = yc = 0
    if away:
        xc, yc = _centre(rng, difficulty)
        argv += ["--center", str(xc), str(yc)]
        features.add("centre away")
    return PracticeQuestion(
        "circle",
        tuple(argv),
        method("circle", name).load("practice")(CircleQuestion(name, r, xc, yc)),
        MARKS[difficulty],
        frozenset(features),
    )


def _ellipse(rng: random.Random, difficulty: str, kind: tuple[bool, bool]) -> PracticeQuestion:
    tall, away = kind
    lo, hi = _AXES[difficulty]
    a = rng.randrange(lo + 1, hi + 1)
    b = rng.randrange(lo, a)
    rx, ry = (b, a) if tall else (a, b)
    argv = ["ellipse", str(rx), str(ry)]
    features = {"tall" if tall else "wide"}
    xc = yc = 0
    if away:
        xc, yc = _centre(rng, difficulty)
        argv += ["--center", str(xc), str(yc)]
        features.add("centre away")
    return PracticeQuestion(
        "ellipse",
        tuple(argv),
        method("ellipse", "midpoint").load("practice")(EllipseQuestion("midpoint", rx, ry, xc, yc)),
        MARKS[difficulty],
        frozenset(features),
    )


def _points(rng: random.Random, difficulty: str, n: int) -> list[tuple[int, int]]:
    """``n`` distinct control points, not all on one line."""
    lo, hi = _CURVE[difficulty]
    while True:
        pts = [(rng.randrange(lo, hi + 1), rng.randrange(lo, hi + 1)) for _ in range(n)]
        (x0, y0), (x1, y1) = pts[0], pts[-1]
        collinear = all((x1 - x0) * (y - y0) == (y1 - y0) * (x - x0) for x, y in pts)
        if len(set(pts)) == n and not collinear:
            return pts


def _flat(points: list[tuple[int, int]]) -> list[str]:
    return [str(v) for p in points for v in p]


def _listed(points: list[tuple[int, int]]) -> str:
    return ", ".join(f"({x}, {y})" for x, y in points)


_T = (Fraction(1, 4), Fraction(1, 3), Fraction(1, 2), Fraction(2, 3), Fraction(3, 4))


def _bezier(rng: random.Random, difficulty: str, kind: tuple[int, bool]) -> PracticeQuestion:
    degree, at = kind
    pts = _points(rng, difficulty, degree + 1)
    argv = ["bezier", *_flat(pts)]
    shape = "cubic" if degree == 3 else "quadratic"
    if at:
        t = rng.choice(_T)
        argv += ["--at", str(t)]
        task = f"find the point at t = {t} by de Casteljau's construction"
    else:
        n = {"easy": 4, "exam": 8, "hard": 10}[difficulty]
        argv += ["--samples", str(n)]
        task = f"tabulate the curve at {n + 1} values of t from 0 to 1"
    return PracticeQuestion(
        "bezier",
        tuple(argv),
        f"For the {shape} Bezier curve with control points {_listed(pts)}, {task}.",
        MARKS[difficulty] // 2 if at else MARKS[difficulty],
        frozenset({shape, "at t" if at else "samples"}),
    )


def _bspline(rng: random.Random, difficulty: str, kind: tuple[int, bool]) -> PracticeQuestion:
    degree, at = kind
    n = degree + 1 + {"easy": 0, "exam": 1, "hard": 2}[difficulty]
    pts = _points(rng, difficulty, n)
    argv = ["bspline", *_flat(pts), "--degree", str(degree)]
    if at:
        t = rng.choice(_T) * (n - degree)  # inside the open knot vector's range
        argv += ["--at", str(t)]
        task = f"evaluate the curve at t = {t} with the Cox-de Boor recursion"
    else:
        argv += ["--samples", str({"easy": 4, "exam": 8, "hard": 10}[difficulty])]
        task = "tabulate its basis functions and the curve"
    return PracticeQuestion(
        "bspline",
        tuple(argv),
        f"For the B-spline of degree {degree} with control points {_listed(pts)} and an "
        f"open uniform knot vector, {task}.",
        MARKS[difficulty],
        frozenset({f"degree {degree}", "at t" if at else "samples"}),
    )


_SIZES = {
    "easy": ((256, 256), (320, 240), (512, 512), (640, 480)),
    "exam": ((640, 480), (800, 600), (1024, 768), (1280, 1024)),
    "hard": ((1920, 1080), (2048, 1536), (3840, 2160), (1366, 768)),
}


def _storage(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    m, n = rng.choice(_SIZES[difficulty])
    argv = ["storage", str(m), str(n)]
    if kind == "levels":
        levels = rng.choice((4, 8, 16, 64, 256) if difficulty != "hard" else (5, 12, 100, 1000))
        argv += ["--levels", str(levels)]
        what = f"an image of {levels} gray levels"
    elif kind == "binary":
        argv += ["--binary"]
        what = "a binary image"
    elif kind == "color":
        argv += ["--color", "rgb24"]
        what = "a 24-bit true-colour image"
    else:
        frames = rng.choice((2, 10, 25, 30))
        argv += ["--bits", "8", "--frames", str(frames)]
        what = f"{frames} frames of 8 bits per pixel"
    return PracticeQuestion(
        "storage",
        tuple(argv),
        f"How much storage does a {m} x {n} frame buffer need for {what}?",
        4,
        frozenset({kind}),
    )


def _quantize(rng: random.Random, difficulty: str, kind: int) -> PracticeQuestion:
    bits = {"easy": 2, "exam": 3, "hard": 4}[difficulty]
    high = kind
    return PracticeQuestion(
        "quantize",
        ("quantize", "--bits", str(bits), "--range", "0", str(high)),
        f"Quantize the gray values 0 to {high} to {bits} bits: give each level's code and "
        "the inputs it takes.",
        6,
        frozenset({f"{bits} bits"}),
    )


def _kinds(topic: str, rng: random.Random) -> list[Any]:
    if topic == "line":
        return _line_kinds(rng)
    if topic not in _MAKERS:  # the topics beyond the notes
        kinds = practice_more.KINDS[topic]
        start = rng.randrange(len(kinds))
        return kinds[start:] + kinds[:start]
    pairs: dict[str, list[Any]] = {
        "circle": [
            ("midpoint", False),
            ("bresenham", True),
            ("midpoint", True),
            ("bresenham", False),
        ],
        "ellipse": [(False, True), (True, False), (True, True), (False, False)],
        "bezier": [(3, False), (2, True), (3, True), (2, False)],
        "bspline": [(2, False), (3, True), (3, False), (2, True)],
        "storage": ["levels", "binary", "color", "frames"],
        "quantize": [255, 63, 100, 1023],
    }
    kinds = pairs[topic]
    start = rng.randrange(len(kinds))  # a rotation keeps each pair of kinds together
    return kinds[start:] + kinds[:start]


_MAKERS: dict[str, Callable[[random.Random, str, object], PracticeQuestion]] = {
    "line": line_question,  # type: ignore[dict-item]
    "circle": _circle,  # type: ignore[dict-item]
    "ellipse": _ellipse,  # type: ignore[dict-item]
    "bezier": _bezier,  # type: ignore[dict-item]
    "bspline": _bspline,  # type: ignore[dict-item]
    "storage": _storage,  # type: ignore[dict-item]
    "quantize": _quantize,  # type: ignore[dict-item]
}


def practice(
    topic: str = "all", count: int = 10, seed: int = 0, difficulty: str = "exam"
) -> list[PracticeQuestion]:
    """``count`` questions on ``topic`` (one of :data:`TOPICS` or ``all``), the same for the
    same arguments.

    >>> [q.argv for q in practice("line", 2, seed=1)] == [q.argv for q in practice("line", 2, seed=1)]
    True
    >>> sorted({f for q in practice("line", 8, seed=5) for f in q.features if f.startswith("octant")})
    ['octant 1', 'octant 2', 'octant 3', 'octant 4', 'octant 5', 'octant 6', 'octant 7', 'octant 8']
    """
    if topic != "all" and topic not in TOPICS:
        raise ValueError(f"unknown topic {topic!r}: one of {', '.join(TOPICS)} or all")
    if difficulty not in DIFFICULTIES:
        raise ValueError(f"unknown difficulty {difficulty!r}: one of {', '.join(DIFFICULTIES)}")
    if not 1 <= count <= MAX_COUNT:
        raise InputError(f"the number of questions must be 1 to {MAX_COUNT} (got {count})", "count")
    rng = random.Random(seed)
    topics = MIX if topic == "all" else (topic,)
    kinds = {t: _cycle(_kinds(t, rng)) for t in dict.fromkeys(topics)}
    makers = dict(_MAKERS)
    if any(t not in makers for t in topics):
        makers.update(practice_more.MAKERS)  # type: ignore[arg-type]
    return [
        makers[t](rng, difficulty, next(kinds[t]))
        for t in (topics[i % len(topics)] for i in range(count))
    ]


def _cycle(items: list[Any]) -> Iterator[Any]:
    while True:
        yield from items


def question_file(questions: list[PracticeQuestion], title: str) -> str:
    """The questions as a question file for ``scanconv sheet`` (wording, marks, command).

    >>> print(question_file(practice("storage", 1, seed=2), "Practice"), end="")
    title: Practice
    <BLANKLINE>
    > How much storage does a 640 x 480 frame buffer need for an image of 4 gray levels?
    [4] storage 640 480 --levels 4
    """
    import shlex

    lines = [f"title: {title}", ""]
    for q in questions:
        lines.append(f"> {q.wording}")
        lines.append(f"[{q.marks}] {shlex.join(q.argv)}")
    return "\n".join(lines) + "\n"
