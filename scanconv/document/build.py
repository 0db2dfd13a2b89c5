"""A :class:`~scanconv.document.blocks.Document` from a :class:`~scanconv.core.records.Solution`.

:func:`document` lays out the structure a solution declares: its working with the
derivation apart (:class:`~scanconv.core.records.Theory`), its step table with its regions
and symmetry and its further tables, which one a stepper goes through and which hold
construction points (:class:`~scanconv.core.records.Walk`), its pixels with the ideal
primitive (:class:`~scanconv.core.records.Plot`). It reads typed fields only, never a title or
an answer's name; the formats read the blocks it returns. An answer may build its document
directly instead.
"""

from __future__ import annotations

from functools import partial
from typing import TYPE_CHECKING, Any

from ..core import lazy, records
from ..core.records import Solution
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
    if solution.derived or solution.derivation:
        blocks.append(Working(solution.derived, solution.derivation))
    if solution.notes:
        blocks.append(Notes(tuple(prose(n) for n in solution.notes)))
    if solution.columns or solution.steps is not records._no_steps:
        blocks.append(_step_table(solution))
    blocks.extend(Table(t.title, t.columns, t.rows, t.stepped, t.points) for t in solution.tables)
    blocks.extend(Pseudocode(c.title, c.lines) for c in solution.code)
    if solution.pixels is not None:
        blocks.append(_pixels(solution))
    blocks.extend(Drawing(f) for f in solution.figures)
    return Document(
        solution.primitive, solution.algorithm, solution.title, tuple(blocks), solution.data
    )


def _step_table(solution: Solution) -> StepTable:
    walk = solution.walk
    return StepTable(
        walk.columns,
        walk.extra_keys,
        walk.steps,
        walk.shown,
        walk.regions,
        walk.region_p,
        walk.symmetry,
        walk.center,
        label_offset(solution),
        lambda: _model(solution),
    )


def _model(solution: Solution) -> Any:
    """The marking model of ``solution``'s walk (loaded on first use: start-up time)."""
    return marking_diagnose.model_for(solution)


def _pixels(solution: Solution) -> Pixels:
    plot = solution.plot
    assert plot.pixels is not None
    return Pixels(
        plot.pixels,
        plot.bbox,
        plot.marks,
        marks_label(solution),
        plot.ideal,
        plot.outline,
        plot.outline_name,
        None if plot.shades is None else dict(plot.shades),
        plot.levels,
        partial(step_labels, solution),
        partial(numbering_legend, solution),
        plot.construction,
    )
