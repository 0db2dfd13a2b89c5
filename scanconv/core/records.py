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

from .ideal import Ideal
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
    stepped: bool = False
    """The stepper goes through this table one row a step (a comparison: the methods side by
    side, nothing plotted)."""
    points: bool = False
    """Its rows hold construction points to draw over the grid (de Casteljau's levels)."""


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


Regions = Literal["column", "restart", "none"]
"""How a step table's rows fall into regions (the ellipse's region 2 is coloured apart):
``"column"``: the ``region`` value of each row; ``"restart"``: a new region wherever ``k``
starts again; ``"none"``: one region."""


class Walk(NamedTuple):
    """An answer's tables: the step table of its walk, as the answer declares it, and the
    further tables."""

    columns: tuple[Column, ...] = ()
    """The step table's columns, in the notes' order; empty: the answer has no step table."""
    extra_keys: tuple[str, ...] = ()
    """Names of the values in :attr:`Step.extra`, in order."""
    steps: Callable[[], Iterator[Step]] = _no_steps
    """A fresh generator of the step records."""
    shown: bool = True
    """``False``: the text formats leave the step table out because :attr:`tables` show the
    same steps split up (the ellipse's two regions); csv and json still carry every step."""
    tables: tuple[Table, ...] = ()
    """Secondary tables shown after the step table."""
    regions: Regions = "restart"
    """How the step table's rows fall into regions (:data:`Regions`)."""
    region_p: tuple[str, ...] = ()
    """The TeX name of the decision parameter in each region (``p1_k``, ``p2_k``), region 1
    first; empty: the ``p`` column's own heading."""
    symmetry: int = 1
    """1, 4 or 8: how each step's point is mirrored into plotted pixels (with 4 or 8,
    ``Step.pixel`` is the point relative to :attr:`center`, as the circle tables print it)."""
    center: tuple[Any, Any] = (0, 0)
    """The centre the points are mirrored about (with symmetry 4 or 8)."""
    next_pixel: bool = False
    """``True``: row k's pixel is ``(x_{k+1}, y_{k+1})``, the pixel its decision reaches (the
    textbooks' layout), so the grid numbers it k + 1 and the start 0; ``False``: row k's pixel
    is numbered k. Declared by the answer that lays the table out, never read from a heading."""


Numbering = Literal["row", "continued", "order", "none"]
"""How the grid numbers the plotted pixels (:func:`scanconv.document.numbering.numbering`)."""


class Plot(NamedTuple):
    """What an answer draws: its plotted pixels with the grid's marks, outline, shades and
    ideal primitive, and the figures under the grid."""

    pixels: Callable[[], Iterator[Pixel]] | None = None
    """A fresh generator of every plotted pixel, once each, in plotting order; ``None``: the
    answer plots nothing (no pixel list, no grid)."""
    bbox: tuple[int, int, int, int] = (0, 0, 0, 0)
    """``(xmin, ymin, xmax, ymax)`` of the plotted pixels, known without running the steps."""
    marks: tuple[Pixel, ...] = ()
    """Points drawn differently in the grid (control points, the centre)."""
    marks_label: str | None = None
    """What :attr:`marks` are, for the grid's legend (``"centre"``, ``"control point"``);
    ``None``: worked out from :attr:`ideal` (``"marked point"`` if it cannot be)."""
    figures: tuple[Figure, ...] = ()
    """Extra figures drawn under the pixel grid (a shaded picture of an image matrix, the grids
    of a comparison): data only, drawn by :mod:`scanconv.render`."""
    ideal: tuple[Ideal, ...] = ()
    """The ideal primitive drawn over the pixels, shape by shape in drawing order."""
    outline: tuple[Pixel, ...] = ()
    """Pixels drawn as an outline under the plotted ones (a fill's boundary)."""
    outline_name: str = "outline"
    """What the outline is called in a legend."""
    shades: dict[Pixel, int] | None = None
    """Grey level of each shaded pixel (anti-aliasing); ``None``: the pixels are not shaded."""
    levels: int = 2
    """The number of grey levels of :attr:`shades`."""
    numbering: Numbering | None = None
    """How the pixels are numbered; ``None``: worked out from the walk."""
    order_name: str = "plotting order"
    """What the numbers mean when they are the plotting order, for a legend."""
    construction: str | None = None
    """A legend's name for the construction points of :attr:`Table.points` tables."""


class Theory(NamedTuple):
    """What ``--derive`` and ``--algorithm`` add to an answer."""

    derivation: tuple[Quantity, ...] = ()
    """The method's derivation with this input's numbers, its heading first; written after
    the working (:attr:`Solution.derived`)."""
    code: tuple[Code, ...] = ()
    """Pseudocode listings, shown after the further tables."""


NO_WALK = Walk()
"""No step table and no further table."""
NO_PLOT = Plot()
"""Nothing plotted, nothing drawn."""
NO_THEORY = Theory()
"""No derivation and no listing."""


class Solution:
    """A worked solution: everything a renderer needs, computed lazily and exactly.

    ``steps()`` and ``pixels()`` return fresh generators on every call: a renderer that needs
    both (table, pixel list and grid) simply calls them again instead of keeping a list, so
    streaming output stays in constant memory.

    A plain class with slots rather than a dataclass: building a dataclass (and importing
    :mod:`dataclasses`) costs about 2 ms of every run's start-up. Its fields are
    :data:`FIELDS`, in the order of the constructor's parameters; two solutions are equal
    when all their fields are. The parts of :attr:`walk`, :attr:`plot` and :attr:`theory`
    read as attributes of their own (``solution.columns``, ``solution.pixels``).
    """

    FIELDS = (
        "primitive",
        "algorithm",
        "title",
        "given",
        "derived",
        "notes",
        "walk",
        "plot",
        "theory",
        "data",
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
    """Derived values with their working, in the order an answer writes them (the derivation
    apart, in :attr:`theory`)."""
    notes: tuple[str, ...]
    """Remarks shown under the derivation (swapped end points, tie rules, ...)."""
    walk: Walk
    """The step table and the further tables."""
    plot: Plot
    """The pixels, the ideal primitive and the figures."""
    theory: Theory
    """The derivation and the pseudocode listings."""
    data: dict[str, Any]
    """Extra JSON fields (exact values for tools), merged into the top-level object: output
    only, never read by another answer."""
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
        notes: tuple[str, ...] = (),
        walk: Walk = NO_WALK,
        plot: Plot = NO_PLOT,
        theory: Theory = NO_THEORY,
        data: dict[str, Any] | None = None,
    ) -> None:
        self.primitive = primitive
        self.algorithm = algorithm
        self.title = title
        self.given = given
        self.derived = derived
        self.notes = notes
        self.walk = walk
        self.plot = plot
        self.theory = theory
        self.data = {} if data is None else data
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
    def columns(self) -> tuple[Column, ...]:
        """The step table's columns (:attr:`Walk.columns`)."""
        return self.walk.columns

    @property
    def extra_keys(self) -> tuple[str, ...]:
        """Names of the values in :attr:`Step.extra` (:attr:`Walk.extra_keys`)."""
        return self.walk.extra_keys

    @property
    def steps(self) -> Callable[[], Iterator[Step]]:
        """A fresh generator of the step records (:attr:`Walk.steps`)."""
        return self.walk.steps

    @property
    def show_steps(self) -> bool:
        """Whether the text formats show the step table (:attr:`Walk.shown`)."""
        return self.walk.shown

    @property
    def tables(self) -> tuple[Table, ...]:
        """The further tables (:attr:`Walk.tables`)."""
        return self.walk.tables

    @property
    def pixels(self) -> Callable[[], Iterator[Pixel]] | None:
        """A fresh generator of the plotted pixels, or ``None`` (:attr:`Plot.pixels`)."""
        return self.plot.pixels

    @property
    def bbox(self) -> tuple[int, int, int, int]:
        """The plotted pixels' box (:attr:`Plot.bbox`)."""
        return self.plot.bbox

    @property
    def marks(self) -> tuple[Pixel, ...]:
        """Points drawn apart in the grid (:attr:`Plot.marks`)."""
        return self.plot.marks

    @property
    def marks_label(self) -> str | None:
        """What :attr:`marks` are (:attr:`Plot.marks_label`)."""
        return self.plot.marks_label

    @property
    def figures(self) -> tuple[Figure, ...]:
        """The figures under the grid (:attr:`Plot.figures`)."""
        return self.plot.figures

    @property
    def derivation(self) -> tuple[Quantity, ...]:
        """The method's derivation (:attr:`Theory.derivation`)."""
        return self.theory.derivation

    @property
    def code(self) -> tuple[Code, ...]:
        """The pseudocode listings (:attr:`Theory.code`)."""
        return self.theory.code

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
