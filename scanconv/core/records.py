"""The records every algorithm yields and the solution object every renderer reads.

Coordinate convention (stated once, used everywhere): ``(x, y)`` with x growing to the right
and y growing **upward**, as in the notes' tables and its 5 x 5 pixel grid. Screen addressing
(origin top-left, y down) is only a way of *drawing* the grid (``--origin top-left``); the
numbers in the tables never change.

An algorithm is a generator of :class:`Step` records. A :class:`Solution` bundles what an exam
answer shows around those steps (given values, derived quantities with numbers substituted,
column headings, the plotted pixels) without ever formatting or printing anything itself.
"""

from collections.abc import Callable, Iterable, Iterator
from enum import Enum
from typing import Any, Literal, NamedTuple

from .numeric import Number
from .working import tex_to_unicode

Pixel = tuple[int, int]
"""A plotted pixel ``(x, y)``."""


class Move(str, Enum):
    """The move a decision makes, named by compass direction (y up).

    ``E``/``NE`` in the first octant, ``N``/``NE`` on steep lines, ``E``/``SE`` for negative
    slopes, ``E``/``SE`` for the circle's first octant, and so on.
    """

    E = "E"
    NE = "NE"
    N = "N"
    NW = "NW"
    W = "W"
    SW = "SW"
    S = "S"
    SE = "SE"

    @classmethod
    def from_delta(cls, dx: int, dy: int) -> "Move":
        """The move for a unit step ``(dx, dy)``.

        >>> Move.from_delta(1, -1)
        <Move.SE: 'SE'>
        """
        return _MOVES[(dx, dy)]

    def __str__(self) -> str:
        return self.value


_MOVES = {
    (1, 0): Move.E,
    (1, 1): Move.NE,
    (0, 1): Move.N,
    (-1, 1): Move.NW,
    (-1, 0): Move.W,
    (-1, -1): Move.SW,
    (0, -1): Move.S,
    (1, -1): Move.SE,
}


class Step(NamedTuple):
    """One row of a step table.

    A NamedTuple (not a frozen dataclass) because tables can have millions of rows and a
    frozen dataclass is several times slower to build.
    """

    k: int
    """Step index, from 0."""
    p: Number | None
    """The decision parameter p_k the decision was taken on; ``None`` if the algorithm has none."""
    decision: Move | None
    """The move chosen at this step; ``None`` if the algorithm makes no decision."""
    pixel: Pixel
    """The pixel this row plots (for Bresenham: ``(x_{k+1}, y_{k+1})``)."""
    extra: tuple[Any, ...] = ()
    """The algorithm's own columns, in the order :attr:`Solution.extra_keys` names them."""


#: Building a record through ``tuple.__new__`` skips NamedTuple's Python-level ``__new__``;
#: the hot loops use it (``_step(Step, (k, p, move, pixel, extra))``).
new_step: Callable[[type[Step], tuple[Any, ...]], Step] = tuple.__new__


Role = Literal["label", "given", "working", "answer"]
"""What a table column's cells are to a student:

* ``label``: numbers or names the rows (the step ``k``, a point's name): shown everywhere;
* ``given``: values the question gives (a point's coordinates, an edge's end points): shown
  on a worksheet and in a quiz, never asked;
* ``working``: the arithmetic that leads to an answer (``7 + (8 - 9)/(-1.25) = 7.8``, the
  reason for a code): written in a key, left for the student on a worksheet, and in a quiz
  kept for the feedback (shown beside a blank it would give the blank away);
* ``answer``: what the question asks: a blank on a worksheet, a blank in a quiz."""

ROLES: tuple[Role, ...] = ("label", "given", "working", "answer")
"""Every :data:`Role`, in the order a row reads."""


class Column(NamedTuple):
    """How one table column is headed and displayed."""

    key: str
    """Name in JSON and CSV (``k``, ``p``, ``decision``, ``pixel`` or an ``extra`` key)."""
    text: str
    """Heading in Unicode, for the terminal and plain text; :func:`heading` derives it from
    :attr:`tex`."""
    tex: str
    """Heading as LaTeX math (without ``$``), for markdown and LaTeX."""
    places: int | None = None
    """Fixed decimals for every cell (``3`` prints ``2.000``); ``None``: integers as they are."""
    role: Role = "answer"
    """What its cells are to a student (:data:`ROLES`): what a worksheet and a quiz show, and
    what they ask."""


class Quantity(NamedTuple):
    """A given or derived value, with the working an exam answer writes out."""

    key: str
    """Name in JSON (``dx``, ``p0``, ``major_axis``)."""
    value: Any
    """The exact value: a number, a pixel, a string (``"x"``) or a tuple of numbers."""
    text: str
    """The working in Unicode: ``Δx = x₂ - x₁ = 10 - 2 = 8``; :func:`worked` derives it from
    :attr:`tex`."""
    tex: str
    """The same working as LaTeX math (without ``$``)."""


def worked(key: str, value: Any, tex: str) -> Quantity:
    """A quantity whose working is written once, as TeX math: the Unicode text is derived by
    :func:`~scanconv.core.working.tex_to_unicode`, so every format says the same thing.

    >>> q = worked("p0", 0, r"p_0 = 2\\Delta y - \\Delta x = 2 \\cdot 4 - 8 = 0")
    >>> q.text
    'p₀ = 2Δy - Δx = 2·4 - 8 = 0'
    """
    return Quantity(key, value, tex_to_unicode(tex), tex)


def rule(key: str, tex: str) -> Quantity:
    """A stated rule, written once as TeX math: its value (what JSON reports) is its text.

    >>> rule("loop", r"\\text{continue while } x < y").value
    'continue while x < y'
    """
    text = tex_to_unicode(tex)
    return Quantity(key, text, text, tex)


def heading(key: str, tex: str, places: int | None = None, role: Role = "answer") -> Column:
    """A table column headed once, in TeX math; the Unicode heading is derived.

    >>> heading("pixel", "(x_{k+1}, y_{k+1})")
    Column(key='pixel', text='(xₖ₊₁, yₖ₊₁)', tex='(x_{k+1}, y_{k+1})', places=None, role='answer')
    """
    return Column(key, tex_to_unicode(tex), tex, places, role)


class Table(NamedTuple):
    """A secondary table shown after the step table (for example the 8-way symmetry table)."""

    title: str
    """Heading shown above the table."""
    columns: tuple[Column, ...]
    """Column headings; cells are taken by position from each row."""
    rows: Callable[[], Iterable[tuple[Any, ...]]]
    """A fresh iterable of rows each time it is called."""


class Code(NamedTuple):
    """A pseudocode listing (``--algorithm``): shown as code after the further tables, never
    as a table (nothing in it to fill in or mark)."""

    title: str
    """Heading shown above the listing."""
    lines: tuple[str, ...]
    """The lines, plain ASCII, in order; leading spaces are the indentation (meaningful)."""


MAX_GRID_CELLS = 100
"""Largest number of columns or rows of a text figure (the pixel grid, a shaded picture); a
larger one is left out with a note."""


class PixelFigure(NamedTuple):
    """A text grid of two pixel sets, drawn under the answer by :mod:`scanconv.render`: ``#``
    where :attr:`pixels` has a pixel, ``o`` where :attr:`marks` has one, ``@`` where both do."""

    pixels: tuple[Pixel, ...]
    """The pixels drawn ``#``."""
    marks: tuple[Pixel, ...]
    """The pixels drawn ``o``."""
    bbox: tuple[int, int, int, int]
    """``(xmin, ymin, xmax, ymax)`` the grid covers (plus the usual margin)."""
    legend: str | None = None
    """What ``#`` and ``o`` mean here; ``None``: the pixel grid's own key."""
    title: str | None = None
    """A line above the grid. A titled figure that is too large says so under its title; an
    untitled one is left out silently."""


class ShadedMatrix(NamedTuple):
    """A matrix of gray levels, drawn as a shaded text picture (level 0 black)."""

    rows: tuple[tuple[int, ...], ...]
    """The levels, row 0 first (drawn at the top)."""
    levels: int
    """The number of gray levels L (levels run 0 .. L - 1)."""
    width: int
    """Cells per row."""


Figure = PixelFigure | ShadedMatrix
"""What an answer asks :mod:`scanconv.render` to draw under it, besides its own pixel grid."""


def _no_steps() -> Iterator[Step]:
    return iter(())


class Solution:
    """A worked solution: everything a renderer needs, computed lazily and exactly.

    ``steps()`` and ``pixels()`` return fresh generators on every call: a renderer that needs
    both (table, pixel list and grid) simply calls them again instead of keeping a list, so
    streaming output stays in constant memory.

    A plain class with slots rather than a dataclass: building a dataclass (and importing
    :mod:`dataclasses`) costs about 2 ms of every run's start-up. Its fields are
    :data:`FIELDS`, in the order of the constructor's parameters; two solutions are equal
    when all their fields are.
    """

    FIELDS = (
        "primitive",
        "algorithm",
        "title",
        "given",
        "derived",
        "columns",
        "extra_keys",
        "steps",
        "pixels",
        "bbox",
        "notes",
        "tables",
        "show_steps",
        "marks",
        "marks_label",
        "figures",
        "geometry",
        "data",
        "code",
    )
    __slots__ = (*FIELDS, "question")

    primitive: str
    """``"line"``, ``"circle"``, ...: the JSON ``primitive`` field."""
    algorithm: str
    """``"bresenham"``, ``"dda"``, ...: the JSON ``algorithm`` field."""
    title: str
    """A one-line heading in ASCII: ``Bresenham's line algorithm: (2, 2) to (10, 6)``."""
    given: tuple[Quantity, ...]
    """The problem's input, as the answer states it."""
    derived: tuple[Quantity, ...]
    """Derived values with their working, in the order an answer writes them."""
    columns: tuple[Column, ...]
    """The step table's columns, in the notes' order; empty: the answer has no step table."""
    extra_keys: tuple[str, ...]
    """Names of the values in :attr:`Step.extra`, in order."""
    steps: Callable[[], Iterator[Step]]
    """A fresh generator of the step records."""
    pixels: Callable[[], Iterator[Pixel]] | None
    """A fresh generator of every plotted pixel, once each, in plotting order; ``None``: the
    answer plots nothing (no pixel list, no grid)."""
    bbox: tuple[int, int, int, int]
    """``(xmin, ymin, xmax, ymax)`` of the plotted pixels, known without running the steps."""
    notes: tuple[str, ...]
    """Remarks shown under the derivation (swapped end points, tie rules, ...)."""
    tables: tuple[Table, ...]
    """Secondary tables shown after the step table."""
    show_steps: bool
    """``False``: the text formats leave the step table out because :attr:`tables` show the
    same steps split up (the ellipse's two regions); csv and json still carry every step."""
    marks: tuple[Pixel, ...]
    """Points drawn differently in the grid (control points, the centre)."""
    marks_label: str | None
    """What :attr:`marks` are, for the grid's legend (``"centre"``, ``"control point"``);
    ``None``: the renderer works it out from :attr:`geometry` (``"marked point"`` if it
    cannot)."""
    figures: tuple[Figure, ...]
    """Extra figures drawn under the pixel grid (a shaded picture of an image matrix, the grids
    of a comparison): data only, drawn by :mod:`scanconv.render`."""
    geometry: dict[str, Any]
    """The ideal primitive, for figures drawn over the pixels. Keys (all optional):
    ``line``: ``(x1, y1, x2, y2)``; ``circle``: ``(xc, yc, r)``; ``ellipse``:
    ``(xc, yc, rx, ry)``; ``polyline``: the sampled ideal curve as ``[(x, y), ...]`` floats;
    ``control``: control points ``[(x, y), ...]``; ``symmetry``: 1, 4 or 8 with ``center``:
    ``(xc, yc)``, saying how each step's point is mirrored into plotted pixels (with 4 or 8,
    ``Step.pixel`` is the point relative to the centre, as the circle tables print it)."""
    data: dict[str, Any]
    """Extra JSON fields (exact values for tools), merged into the top-level object."""
    code: tuple[Code, ...]
    """Pseudocode listings (``--algorithm``), shown after :attr:`tables`."""
    question: Any
    """The typed question the answer was built from (a stepped command's
    :mod:`scanconv.answers.asked` question, set by the command's answer; ``None``: not
    kept). The marking builds its model from it (not a field: it is no part of the output)."""

    def __init__(
        self,
        primitive: str,
        algorithm: str,
        title: str,
        given: tuple[Quantity, ...],
        derived: tuple[Quantity, ...],
        columns: tuple[Column, ...] = (),
        extra_keys: tuple[str, ...] = (),
        steps: Callable[[], Iterator[Step]] = _no_steps,
        pixels: Callable[[], Iterator[Pixel]] | None = None,
        bbox: tuple[int, int, int, int] = (0, 0, 0, 0),
        notes: tuple[str, ...] = (),
        tables: tuple[Table, ...] = (),
        show_steps: bool = True,
        marks: tuple[Pixel, ...] = (),
        marks_label: str | None = None,
        figures: tuple[Figure, ...] = (),
        geometry: dict[str, Any] | None = None,
        data: dict[str, Any] | None = None,
        code: tuple[Code, ...] = (),
    ) -> None:
        self.primitive = primitive
        self.algorithm = algorithm
        self.title = title
        self.given = given
        self.derived = derived
        self.columns = columns
        self.extra_keys = extra_keys
        self.steps = steps
        self.pixels = pixels
        self.bbox = bbox
        self.notes = notes
        self.tables = tables
        self.show_steps = show_steps
        self.marks = marks
        self.marks_label = marks_label
        self.figures = figures
        self.geometry = {} if geometry is None else geometry
        self.data = {} if data is None else data
        self.code = code
        self.question = None

    def fields(self) -> dict[str, Any]:
        """Every field by name (what a subclass copies to wrap a solution)."""
        return {name: getattr(self, name) for name in Solution.FIELDS}

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Solution):
            return NotImplemented
        return self.fields() == other.fields()

    __hash__ = None  # type: ignore[assignment]  # mutable, as a dataclass with eq is

    def __repr__(self) -> str:
        inner = ", ".join(f"{name}={getattr(self, name)!r}" for name in Solution.FIELDS)
        return f"{type(self).__name__}({inner})"

    @property
    def has_p(self) -> bool:
        """True if the step table has a decision-parameter column."""
        return any(c.key == "p" for c in self.columns)

    @property
    def has_decision(self) -> bool:
        """True if the step table has a decision column."""
        return any(c.key == "decision" for c in self.columns)


def step_getter(
    columns: Iterable[Column], extra_keys: tuple[str, ...]
) -> Callable[[Step], tuple[Any, ...]]:
    """A function that turns a step into its cells, in column order.

    >>> get = step_getter([Column("k", "k", "k"), Column("p_next", "p", "p")], ("p_next",))
    >>> get(Step(0, 0, Move.NE, (3, 3), (-8,)))
    (0, -8)
    """
    core = ("k", "p", "decision", "pixel")
    where = [
        (core.index(c.key), None) if c.key in core else (4, extra_keys.index(c.key))
        for c in columns
    ]

    def get(step: Step) -> tuple[Any, ...]:
        return tuple(step[i] if j is None else step.extra[j] for i, j in where)

    return get
