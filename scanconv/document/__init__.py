"""The answer document: typed blocks between the answers and the formats.

An answer (a :class:`~scanconv.core.records.Solution`) becomes a :class:`Document`, a tuple
of typed blocks in reading order (:mod:`.blocks`): :class:`Title`, :class:`Given`,
:class:`Working` (derived quantities with their working, as TeX math), :class:`Notes` (prose
with its math as math), :class:`StepTable` (columns, a fresh row iterator, its regions and
layout), :class:`Table`, :class:`Pseudocode` (a numbered listing, shown as code), :class:`Pixels` (with symmetry, numbering, marks and the ideal
primitive) and :class:`Drawing`; in a document of many answers (a sheet), a
:class:`Question` (its number, marks, wording and command) heads each answer, and a
:class:`Contents` (the exam book's) lists the questions. :func:`document` builds it (:mod:`.build`, the one place
that reads a solution's structure); each format in :mod:`scanconv.render` is one mapping from
block types to output, so a format never guesses what an answer holds.

This layer sits between ``answers`` and ``render`` (the import-linter contract): it formats
nothing.
"""

from __future__ import annotations

from .blocks import (
    Block,
    Contents,
    Document,
    Drawing,
    Entry,
    Given,
    Notes,
    Pixels,
    Prose,
    Pseudocode,
    Question,
    StepTable,
    Table,
    Title,
    Working,
)
from .build import as_document, document, prose

__all__ = [
    "Block",
    "Contents",
    "Document",
    "Drawing",
    "Entry",
    "Given",
    "Notes",
    "Pixels",
    "Prose",
    "Pseudocode",
    "Question",
    "StepTable",
    "Table",
    "Title",
    "Working",
    "as_document",
    "document",
    "prose",
]
