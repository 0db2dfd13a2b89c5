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

The commands whose records dispatch by method without a stepped table have one question each
too, built once where the command's function checks its input, every piece of the command
taking it: :class:`ClipLineQuestion` (``clip line``: the answer and the pipeline's ``stage``),
:class:`ClipPolygonQuestion` (``clip polygon``), :class:`FillQuestion` (``fill``) and
:class:`ProjectionQuestion` (``3d project``: each kind's builder, its record's ``generator``); their
choices are typed by the :mod:`~scanconv.core.choices` ``Literal`` of the API, so a misspelt
method is a mypy error here as it is in ``scanconv.clip_line(..., method=...)``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Literal, NamedTuple

from ..algorithms.conventions import resolve
from ..core.numeric import Number, normalize

if TYPE_CHECKING:  # the choices' Literal types cost the start-up nothing
    from ..core.choices import (
        ClipEndsName,
        FillMethodName,
        LineClipMethodName,
        MidpointName,
        MidpointStopName,
        NormalsName,
        OrderName,
        PolygonClipMethodName,
    )


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


class ClipLineQuestion(NamedTuple):
    """A line clipping question: ``clip line X1 Y1 X2 Y2 --window XMIN YMIN XMAX YMAX --method
    NAME``, its end points exact and its window checked; what a ``clip`` line method's
    ``answer`` and ``stage`` take. A convention is ``None`` where not given (the method's
    default); one given to a method that does not take it is refused before the question is
    built."""

    method: LineClipMethodName
    p1: tuple[Number, Number]
    p2: tuple[Number, Number]
    window: tuple[Number, Number, Number, Number]
    """``(xmin, ymin, xmax, ymax)``, ``xmin < xmax`` and ``ymin < ymax``."""
    normals: NormalsName | None = None
    ends: ClipEndsName | None = None
    midpoint: MidpointName | None = None
    stop: MidpointStopName | None = None

    @property
    def key(self) -> str:
        """Its method record's key, ``clip/<method>``."""
        return f"clip/{self.method}"


class ClipPolygonQuestion(NamedTuple):
    """A polygon clipping question: ``clip polygon X1 Y1 ... (--window XMIN YMIN XMAX YMAX |
    --window-vertices X Y ...) --method NAME``; what a ``clip`` polygon method's ``answer``
    takes."""

    method: PolygonClipMethodName
    vertices: tuple[Number, ...]
    """The polygon's ``x y x y ...``."""
    window: tuple[Number, ...]
    """A rectangle's ``(xmin, ymin, xmax, ymax)``, or a polygon window's ``x y x y ...``."""
    polygon: bool = False
    """The window is a polygon's vertices (``False``: the rectangle)."""

    @property
    def key(self) -> str:
        """Its method record's key, ``clip/<method>``."""
        return f"clip/{self.method}"


Connectivity = Literal[4, 8]
"""A seed fill's neighbours (:data:`scanconv.algorithms.seedfill.CONNECTIVITIES`)."""


class FillQuestion(NamedTuple):
    """A seed fill question: ``fill METHOD --seed X Y (VERTICES | --rows ROWS)``, checked;
    what a ``fill`` method's ``answer`` takes. Exactly one of ``vertices`` and ``rows``."""

    method: FillMethodName
    seed: tuple[int, int]
    vertices: tuple[Number, ...] | None = None
    """A polygon's ``x y x y ...``, whose Bresenham outline is the boundary."""
    rows: tuple[str, ...] | None = None
    """The grid as text rows, top row first."""
    connectivity: Connectivity = 4
    order: OrderName = "stack"
    span: bool = False
    """The span (scan-line seed) fill."""

    @property
    def key(self) -> str:
        """Its method record's key, ``fill/<method>``."""
        return f"fill/{self.method}"


ObliqueAngle = Literal["receding", "projector"]
"""What an oblique projection's angle is (the ``oblique-angle`` convention,
:data:`~scanconv.algorithms.space_conventions.SPACE_KNOBS`)."""
CentreOfProjection = Literal["minus-d", "plus-d", "origin"]
"""Where a perspective's centre of projection is (the ``cop`` convention)."""


class ProjectionQuestion(NamedTuple):
    """A projection question: ``3d project ... --parallel KIND | --perspective KIND`` with its
    options, ``None`` where not given (the kind's default); what each kind's builder (its
    ``3d`` record's ``generator``) takes. The two conventions a builder reads come resolved (a
    preset's or the one given), and ``sense`` is 1 for the standard sense of a positive
    angle, -1 for the reversed."""

    kind: str
    oblique_angle: ObliqueAngle
    """What an oblique ``angle`` is (the ``oblique-angle`` convention)."""
    cop: CentreOfProjection
    """Where the centre of projection is (the ``cop`` convention)."""
    sense: Literal[1, -1]
    view: str | None = None
    angle: str | None = None
    receding: str | None = None
    angles: tuple[str, ...] | None = None
    ratio: Number | None = None
    d: Number | None = None

    @property
    def key(self) -> str:
        """Its method record's key, ``3d/<kind>``."""
        return f"3d/{self.kind}"

    def given(self) -> dict[str, object]:
        """The options given (not ``None``), by name."""
        return {k: getattr(self, k) for k in PROJECTION_OPTIONS if getattr(self, k) is not None}


PROJECTION_OPTIONS = ProjectionQuestion._fields[ProjectionQuestion._fields.index("sense") + 1 :]
"""The options of :class:`ProjectionQuestion`, its fields after ``sense``: a kind's builder
says which it reads (``Built.reads``), and one given that it does not read is refused."""
