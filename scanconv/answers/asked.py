"""The typed questions: what every piece of a stepped command's method takes.

A method record (:mod:`.methods`) names its pieces (the answer, the derivation, the
pseudocode, the marking model, the errata note, the practice wording, the row estimate); each
piece of a command takes that command's one question, frozen and typed: a
:class:`LineQuestion`, a :class:`CircleQuestion` or an :class:`EllipseQuestion`. The knobs are
typed too (a knob that does not apply to the method is ``None``), so a piece reads
``q.knobs.tie``, never ``knobs.get("tie", "step")`` with the default restated. The answer
keeps its question (:attr:`~scanconv.core.records.Solution.question`), so the marking builds
its model from it instead of reading the question back out of the answer's text.

>>> q = line_question("bresenham", 2, 2, 10, 6)
>>> q.knobs
LineKnobs(rounding=None, tie='step', start='swap', scale=None, ends=None)
>>> q.ends
(2, 2, 10, 6)
"""

from collections.abc import Mapping
from typing import NamedTuple

from ..algorithms.conventions import resolve
from ..core.numeric import Number, normalize


class LineKnobs(NamedTuple):
    """A line's conventions, in the order of the knobs' declaration (the JSON's) (:data:`~scanconv.algorithms.conventions.KNOBS`); ``None``: the
    knob does not apply to the method."""

    rounding: str | None = None
    tie: str | None = None
    start: str | None = None
    scale: str | None = None
    ends: str | None = None


class LineQuestion(NamedTuple):
    """A line question: ``line X1 Y1 X2 Y2 --algo NAME`` with its conventions."""

    algo: str
    x1: Number
    y1: Number
    x2: Number
    y2: Number
    knobs: LineKnobs = LineKnobs()
    layout: str = "textbook"
    convention: str | None = None
    annotate: bool = False
    """Add the notes naming the conventions and the course notes' errata (the API's answers
    have them; a pipeline stage that embeds a line leaves them out)."""

    @property
    def key(self) -> str:
        """Its method record's key, ``line/<algo>``."""
        return f"line/{self.algo}"

    @property
    def points(self) -> tuple[Number, Number, Number, Number]:
        """The end points as given."""
        return (self.x1, self.y1, self.x2, self.y2)

    @property
    def ends(self) -> tuple[Number, Number, Number, Number]:
        """The end points, each exact (an integral fraction as an int)."""
        return (normalize(self.x1), normalize(self.y1), normalize(self.x2), normalize(self.y2))


class CircleKnobs(NamedTuple):
    """A circle's conventions; ``None``: the knob does not apply to the method."""

    rounding: str | None = None
    tie: str | None = None
    p0: str | None = None
    loop: str | None = None
    xstep: str | None = None
    update: str | None = None


class CircleQuestion(NamedTuple):
    """A circle question: ``circle R --method NAME --center XC YC``, its numbers checked."""

    method: str
    r: int
    xc: int = 0
    yc: int = 0
    knobs: CircleKnobs = CircleKnobs()
    layout: str = "textbook"
    convention: str | None = None

    @property
    def key(self) -> str:
        """Its method record's key, ``circle/<method>``."""
        return f"circle/{self.method}"


class EllipseKnobs(NamedTuple):
    """The midpoint ellipse's conventions."""

    tie: str | None = None
    p0: str | None = None
    loop: str | None = None


class EllipseQuestion(NamedTuple):
    """An ellipse question: ``ellipse RX RY --center XC YC``, its numbers checked."""

    method: str
    rx: int
    ry: int
    xc: int = 0
    yc: int = 0
    knobs: EllipseKnobs = EllipseKnobs()
    convention: str | None = None

    @property
    def key(self) -> str:
        """Its method record's key, ``ellipse/<method>``."""
        return f"ellipse/{self.method}"


def knob_values(knobs: NamedTuple) -> dict[str, str]:
    """The knobs that apply, by name (the JSON ``conventions`` field).

    >>> knob_values(LineKnobs(tie="keep", start="swap"))
    {'tie': 'keep', 'start': 'swap'}
    """
    return {k: v for k, v in knobs._asdict().items() if v is not None}


def line_question(
    algo: str,
    x1: Number,
    y1: Number,
    x2: Number,
    y2: Number,
    *,
    given: Mapping[str, str | None] | None = None,
    convention: str | None = None,
    layout: str = "textbook",
) -> LineQuestion:
    """The question with its conventions resolved (an explicit knob, the preset's, the
    default); :class:`~scanconv.core.checks.InputError` for a knob that does not apply."""
    knobs = resolve("line", algo, convention, dict(given or {}))
    return LineQuestion(algo, x1, y1, x2, y2, LineKnobs(**knobs), layout, convention)
