"""A :class:`~scanconv.document.blocks.Document` from a :class:`~scanconv.core.records.Solution`.

:func:`document` is the one place that reads a solution's structure: the rendering hints of
its ``geometry`` side channel, its regions, which table a stepper goes through. The formats
read the blocks it returns and never guess again. An answer may build its document directly
instead.
"""

from __future__ import annotations

from functools import partial
from typing import TYPE_CHECKING, Any

from ..core import lazy, records
from ..core.records import Quantity, Solution
from .blocks import (
    Block,
    Document,
    Drawing,
    Given,
    Notes,
    Pixels,
    Prose,
    Pseudocode,
    StepTable,
    Table,
    Title,
    Working,
)
from .numbering import label_offset, marks_label, numbering_legend, step_labels
from .prose import note_segments

if TYPE_CHECKING:
    from ..marking import diagnose as marking_diagnose
else:
    marking_diagnose = lazy.module("scanconv.marking.diagnose")

IDEAL = ("line", "circle", "ellipse", "polyline", "control")
"""The :attr:`Solution.geometry` keys that describe the ideal primitive."""

_REGION = lazy.pattern(r"Region (\d+) ")

DERIVATION = "derivation"
"""The key of the rule that heads a derivation in the working
(:data:`scanconv.answers.theory.derivations.DERIVATION`)."""


def prose(text: str) -> Prose:
    """A note as prose with its math kept as math.

    >>> prose("$p_k < 0$ chooses E").segments
    ((True, 'p_k < 0'), (False, ' chooses E'))
    """
    return Prose(text, tuple(note_segments(text)))


def as_document(answer: Solution | Document) -> Document:
    """``answer`` as a document (a document as it is)."""
    return answer if isinstance(answer, Document) else document(answer)


def document(solution: Solution) -> Document:
    """The blocks of ``solution``, in reading order: the title, the given values, the
    working, the notes, the step table, the further tables, the pseudocode, the pixels, the
    drawings.

    >>> from scanconv.answers.primitives.line import line_solution
    >>> doc = document(line_solution("bresenham", 0, 0, 2, 1))
    >>> [type(b).__name__ for b in doc.blocks]
    ['Title', 'Given', 'Working', 'Notes', 'StepTable', 'Pixels']
    >>> doc.get(StepTable).offset, doc.get(Pixels).labels()[(2, 1)]
    (1, 2)
    """
    blocks: list[Block] = [Title(solution.title)]
    if solution.given:
        blocks.append(Given(solution.given))
    if solution.derived:
        blocks.append(_working(solution.derived))
    if solution.notes:
        blocks.append(Notes(tuple(prose(n) for n in solution.notes)))
    if solution.columns or solution.steps is not records._no_steps:
        blocks.append(_step_table(solution))
    points = solution.algorithm == "de-casteljau"
    for i, t in enumerate(solution.tables):
        stepped = solution.algorithm == "compare" and i == 0
        blocks.append(Table(t.title, t.columns, t.rows, stepped, points))
    blocks.extend(Pseudocode(c.title, c.lines) for c in solution.code)
    if solution.pixels is not None:
        blocks.append(_pixels(solution, "de Casteljau points" if points else None))
    blocks.extend(Drawing(f) for f in solution.figures)
    return Document(
        solution.primitive, solution.algorithm, solution.title, tuple(blocks), solution.data
    )


def _working(derived: tuple[Quantity, ...]) -> Working:
    """The working, its derivation (from the ``derivation`` rule on) apart.

    >>> from scanconv.core.records import rule
    >>> w = _working((rule("a", "a"), rule("derivation", "D"), rule("b", "b")))
    >>> [q.key for q in w.quantities], [q.key for q in w.derivation]
    (['a'], ['derivation', 'b'])
    """
    at = next((i for i, q in enumerate(derived) if q.key == DERIVATION), len(derived))
    return Working(derived[:at], derived[at:])


def _step_table(solution: Solution) -> StepTable:
    keys = {c.key: c for c in solution.columns}
    region_p: tuple[str, ...] = ()
    if "region" in keys and "p" in keys:
        named: dict[int, str] = {}
        for t in solution.tables:
            m = _REGION.match(t.title)
            p = next((c.tex for c in t.columns if c.key == "p"), None)
            if m and p is not None:
                named[int(m.group(1))] = p
        top = max(named, default=0)
        region_p = tuple(named.get(n, keys["p"].tex) for n in range(1, top + 1))
    return StepTable(
        solution.columns,
        solution.extra_keys,
        solution.steps,
        solution.show_steps,
        "column" if "region" in solution.extra_keys else "restart",
        region_p,
        int(solution.geometry.get("symmetry", 1)),
        solution.geometry.get("center", (0, 0)),
        label_offset(solution),
        lambda: _model(solution),
    )


def _model(solution: Solution) -> Any:
    """The marking model of ``solution``'s walk (loaded on first use: start-up time)."""
    return marking_diagnose.model_for(solution)


def _pixels(solution: Solution, construction: str | None) -> Pixels:
    geometry: dict[str, Any] = solution.geometry
    assert solution.pixels is not None
    shades = geometry.get("shades")
    return Pixels(
        solution.pixels,
        solution.bbox,
        solution.marks,
        marks_label(solution),
        {k: geometry[k] for k in IDEAL if k in geometry},
        str(geometry.get("polyline_name", "curve")),
        tuple(geometry.get("outline") or ()),
        str(geometry.get("outline_name", "outline")),
        None if shades is None else dict(shades),
        int(geometry.get("levels", 2)),
        partial(step_labels, solution),
        partial(numbering_legend, solution),
        construction,
    )
