"""The typed blocks of an answer document (see :mod:`scanconv.document`).

Each block is a NamedTuple (cheap to define and to build: start-up time counts) holding data
only: numbers stay exact, math stays TeX math, tables are row factories (a fresh iterator on
every call, so a format that streams a table of millions of rows does so in constant memory).
"""

from collections.abc import Callable, Iterable, Iterator
from typing import Any, NamedTuple

from ..core.ideal import Ideal
from ..core.records import Column, Figure, Pixel, Quantity, Regions, Step

Segments = tuple[tuple[bool, str], ...]
"""Prose with math: ``(is_math, text)`` pairs, the math as TeX (``(True, "p_k < 0")``)."""


class Prose(NamedTuple):
    """A sentence with formulas in it (a note): its source and its segments."""

    source: str
    """The text as the answer wrote it (``$...$`` around its TeX formulas)."""
    segments: Segments
    """Text and math, in order: a format escapes the text and sets the math as math."""


class Title(NamedTuple):
    """The answer's one-line heading, in ASCII."""

    text: str
    level: int = 2
    """Its heading's level: 2 for an answer alone, one deeper under a :class:`Question`'s
    heading (a format with fewer levels maps it to its own)."""


class Question(NamedTuple):
    """A question of a document (a sheet, the exam book, a practice set), above its answer:
    its number, marks, wording and the command line that answers it."""

    number: int
    marks: int | None = None
    wording: str = ""
    """The question in words, as the question file gives it; ``""``: none shown."""
    command: str = ""
    """The command line that answers it (``scanconv line 2 2 10 6``); ``""``: not shown (a
    worksheet)."""
    level: int = 2
    """Its heading's level (3 under the document's sections)."""
    entry: str = ""
    """Its line in the document's :class:`Contents` (a format whose contents are filled in
    from the headings, LaTeX's ``\\tableofcontents``, marks the heading with it); ``""``:
    none."""

    @property
    def heading(self) -> str:
        """The heading's text.

        >>> Question(3, 4).heading, Question(1, 1).heading, Question(2).heading
        ('Question 3 (4 marks)', 'Question 1 (1 mark)', 'Question 2')
        """
        if self.marks is None:
            return f"Question {self.number}"
        return f"Question {self.number} ({self.marks} mark{'' if self.marks == 1 else 's'})"


class Entry(NamedTuple):
    """One line of a :class:`Contents`: a question's number and wording, under its section."""

    number: int
    wording: str
    """The question in words on one line (its command line if it has no wording)."""
    section: str = ""
    """The section it is under, or ``""``."""


class Contents(NamedTuple):
    """A document's table of contents (the exam book): every question's number and wording,
    under its section, in order."""

    entries: tuple[Entry, ...]
    linked: bool = True
    """Above the document's questions, each entry leading to its question (HTML links to
    the question's section, LaTeX's page numbers from the headings'
    :attr:`Question.entry`); ``False``: the list alone, nothing answered (``exam --contents``)."""

    def sections(self) -> list[tuple[str, list[Entry]]]:
        """The entries grouped by section, in order.

        >>> Contents((Entry(1, "a", "S"), Entry(2, "b", "S"), Entry(3, "c", "T"))).sections()
        [('S', [Entry(number=1, wording='a', section='S'), Entry(number=2, wording='b', \
section='S')]), ('T', [Entry(number=3, wording='c', section='T')])]
        """
        out: list[tuple[str, list[Entry]]] = []
        for entry in self.entries:
            if not out or out[-1][0] != entry.section:
                out.append((entry.section, []))
            out[-1][1].append(entry)
        return out


class Given(NamedTuple):
    """The problem's input, as the answer states it (each with its TeX and Unicode)."""

    quantities: tuple[Quantity, ...]


class Working(NamedTuple):
    """Derived quantities with their working, numbers substituted, in the answer's order."""

    quantities: tuple[Quantity, ...]
    derivation: tuple[Quantity, ...] = ()
    """The method's derivation with this input's numbers (``--derive``), its heading first;
    empty: none. Written after :attr:`quantities`."""

    @property
    def lines(self) -> tuple[Quantity, ...]:
        """Every line of the working, the derivation last."""
        return self.quantities + self.derivation


class Notes(NamedTuple):
    """Remarks under the working (swapped end points, tie rules, conventions)."""

    notes: tuple[Prose, ...]


class StepTable(NamedTuple):
    """The step table: one row per :class:`~scanconv.core.records.Step`."""

    columns: tuple[Column, ...]
    """The shown columns, in the notes' order (empty: the answer has steps but no table)."""
    extra_keys: tuple[str, ...]
    """Names of the values in :attr:`Step.extra`, in order."""
    steps: Callable[[], Iterator[Step]]
    """A fresh generator of the rows on every call."""
    shown: bool = True
    """``False``: the document formats leave the table out because later :class:`Table`
    blocks show the same rows split up (the ellipse's two regions); csv, json and the
    stepper still read every row."""
    regions: Regions = "restart"
    """How the rows fall into regions (the ellipse's region 2 is coloured apart):
    ``"column"``: the ``region`` value of each row; ``"restart"``: a new region wherever
    ``k`` starts again; ``"none"``: one region."""
    region_p: tuple[str, ...] = ()
    """The TeX name of the decision parameter in each region (``p1_k``, ``p2_k``), region 1
    first; empty: the ``p`` column's own heading."""
    symmetry: int = 1
    """1, 4 or 8: how each row's point is mirrored into plotted pixels (with 4 or 8 the
    point is relative to :attr:`center`, as the circle tables print it)."""
    center: tuple[Any, Any] = (0, 0)
    """The centre the point is mirrored about (with symmetry 4 or 8)."""
    offset: int = 0
    """1 when a row plots ``(x_{k+1}, y_{k+1})`` (the pixel its decision chose: the start
    pixel is plotted before row 0), else 0."""
    model: Callable[[], Any] | None = None
    """The walk's marking model (:mod:`scanconv.marking.models`), built on first call; ``None``
    or a call returning ``None``: no rule a step can be judged by (the test-yourself mode)."""

    @property
    def has_p(self) -> bool:
        """Whether the table has a decision-parameter column."""
        return any(c.key == "p" for c in self.columns)

    @property
    def has_decision(self) -> bool:
        """Whether the table has a decision column."""
        return any(c.key == "decision" for c in self.columns)


class Table(NamedTuple):
    """A further table (the symmetry table, a region's rows, a comparison, a fill's trace)."""

    title: str
    columns: tuple[Column, ...]
    rows: Callable[[], Iterable[tuple[Any, ...]]]
    """A fresh iterable of rows on every call; cells by position."""
    stepped: bool = False
    """The stepper goes through this table one row a step (a comparison: the methods side by
    side, nothing plotted)."""
    points: bool = False
    """Its rows hold construction points to draw over the grid (de Casteljau's levels)."""


class Pseudocode(NamedTuple):
    """A pseudocode listing (``--algorithm``): code, not a table (no stepper, no blanks, no
    marks). Each format numbers the lines and keeps their indentation."""

    title: str
    lines: tuple[str, ...]
    """Plain ASCII lines; leading spaces are the indentation."""

    def numbered(self) -> list[str]:
        """The lines numbered from 1 as every format shows them: the numbers right-aligned,
        two spaces, then the line with its indentation.

        >>> Pseudocode("t", ("a",) * 9 + ("  b",)).numbered()[-2:]
        [' 9  a', '10    b']
        """
        width = len(str(len(self.lines)))
        return [f"{n:>{width}}  {line}" for n, line in enumerate(self.lines, 1)]


class Pixels(NamedTuple):
    """The plotted pixels, with what the grid needs to draw, number and mark them."""

    pixels: Callable[[], Iterator[Pixel]]
    """A fresh generator of every plotted pixel, once each, in plotting order."""
    bbox: tuple[int, int, int, int]
    """``(xmin, ymin, xmax, ymax)`` of the pixels, known without running the steps."""
    marks: tuple[Pixel, ...]
    """Points drawn apart (control points, the centre)."""
    marks_label: str
    """What :attr:`marks` are (``"centre"``, ``"control point"``)."""
    ideal: tuple[Ideal, ...]
    """The ideal primitive drawn over the pixels, shape by shape in drawing order
    (:mod:`scanconv.core.ideal`: a line, circle, ellipse, sampled curve, control polygon)."""
    outline: tuple[Pixel, ...]
    """Pixels drawn as an outline under the plotted ones (a fill's boundary)."""
    outline_name: str
    """What the outline is called in a legend."""
    shades: dict[Pixel, int] | None
    """Grey level of each shaded pixel (anti-aliasing); ``None``: the pixels are not shaded."""
    levels: int
    """The number of grey levels of :attr:`shades`."""
    labels: Callable[[], dict[Pixel, int]]
    """The step number of each plotted pixel that has one (computed on demand)."""
    numbering: Callable[[], str]
    """What those numbers mean, for a legend (computed on demand)."""
    construction: str | None = None
    """A legend's name for the construction points of :attr:`Table.points` tables."""


class Drawing(NamedTuple):
    """A figure drawn under the grid (a two-set pixel figure, a shaded matrix)."""

    figure: Figure


Block = (
    Contents
    | Question
    | Title
    | Given
    | Working
    | Notes
    | StepTable
    | Table
    | Pseudocode
    | Pixels
    | Drawing
)
"""Any block of a document."""


class Document(NamedTuple):
    """One answer as typed blocks, in reading order; :attr:`data` carries the record fields
    (for json) that no block shows."""

    primitive: str
    algorithm: str
    title: str
    blocks: tuple[Block, ...]
    data: dict[str, Any]

    def get(self, kind: type[Any]) -> Any:
        """The first block of type ``kind``, or ``None``."""
        return next((b for b in self.blocks if isinstance(b, kind)), None)

    def every(self, kind: type[Any]) -> list[Any]:
        """Every block of type ``kind``, in order."""
        return [b for b in self.blocks if isinstance(b, kind)]
