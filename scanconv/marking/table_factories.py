"""The table model of each method marked by its own columns, built for one answer: what the
method record's ``model`` names for a command that is not a pixel walk
(:mod:`scanconv.answers.methods`), so the marking reaches a method through its record, never
by its name (:func:`scanconv.marking.tables.table_model_for`)."""

from __future__ import annotations

from collections.abc import Callable

from ..core.records import Solution
from .table_models import (
    CyrusBeckTable,
    DiffusionTable,
    DitherTable,
    FrameBufferTable,
    InsideVerdictsTable,
    LineStyleTable,
    MidpointClipTable,
    NLLTable,
    PlainRowsTable,
    TableModel,
)


def _alone(model: Callable[[], TableModel]) -> Callable[[Solution], TableModel]:
    """The factory of a table model that needs nothing of the answer."""
    return lambda solution: model()


cyrus_beck = _alone(CyrusBeckTable)
nll = _alone(NLLTable)
midpoint_clip = _alone(MidpointClipTable)
line_style = _alone(LineStyleTable)
framebuffer = _alone(FrameBufferTable)
inside = _alone(InsideVerdictsTable)


def dither_ordered(solution: Solution) -> TableModel:
    """Ordered dither turns a pixel on above its threshold (``>``) unless the answer says."""
    return DitherTable(solution.data.get("compare", ">"))


def dither_threshold(solution: Solution) -> TableModel:
    """Thresholding turns a pixel on at its threshold or above (``>=``) unless the answer says."""
    return DitherTable(solution.data.get("compare", ">="))


def diffusion(solution: Solution) -> TableModel:
    given = {q.key: q.value for q in solution.given}
    data = solution.data
    return DiffusionTable(given["image"], given["top"], data, data.get("compare", ">="))


def printer(solution: Solution) -> TableModel:
    return PlainRowsTable(
        "Printer and screen", ("value",), "Each quantity stands alone (dpi, lpi, cell, levels)."
    )


def dither_lookup(solution: Solution) -> TableModel:
    return PlainRowsTable(
        None,
        ("i", "j", "row", "col", "threshold", "output"),
        "Each pixel's lookup stands alone (its position, its matrix cell, its threshold).",
    )


def halftone_patterns(solution: Solution) -> TableModel | None:
    """The patterns table, titled as the answer titles it (``4 x 4 patterns``); none without."""
    if not solution.tables:
        return None
    title = solution.tables[0].title.split(" (")[0]
    return PlainRowsTable(title, ("pattern", "on"), "Each level's pattern stands alone.")


def thick_line(solution: Solution) -> TableModel:
    """A thick line, by replication or a brush."""
    return PlainRowsTable(None, ("added",), "Each step's added pixels stand alone.")


def bitmap_char(solution: Solution) -> TableModel:
    return PlainRowsTable(None, ("row", "column"), "Each pixel stands alone.")


def stroke_char(solution: Solution) -> TableModel:
    return PlainRowsTable(None, ("segment", "pixels"), "Each stroke's pixels stand alone.")


def font_storage(solution: Solution) -> TableModel:
    return PlainRowsTable(
        "Every packing",
        ("glyph", "bits", "bytes"),
        "Each packing's sizes stand alone (a glyph's bits, the font's bits and bytes).",
    )
