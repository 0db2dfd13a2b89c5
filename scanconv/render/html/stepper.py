"""What the HTML page steps through: positions, the pixels each lights, the captions.

:func:`stepping` reads an answer's :class:`~scanconv.document.Document` into a :class:`Stepping`
(see :mod:`scanconv.render.mappings.html` for what a position is): the step records with their pixels
(and mirror images), the pixels alone in plotting order for an answer without a step table,
or the rows of a comparison's side-by-side table. The captions give each decision with its
numbers, in Unicode. It reads the blocks' declared structure (the step table's regions,
symmetry and pixel offset, a table's ``stepped`` flag), never an answer's name.
"""

from __future__ import annotations

import re
from itertools import islice
from typing import Any, NamedTuple

from ...core.numeric import fmt_pixel
from ...core.records import Pixel, Solution, Step, step_getter
from ...core.working import tex_to_unicode
from ...document import Document, Pixels, StepTable, Table, as_document
from ...document.numbering import mirror_images
from .. import Options
from ..cells import cell, unicode_heading

MAX_STEPS = 20_000
"""Steps the stepper goes through; a longer answer's later steps light at the last step."""

MAX_PIXELS = 40_000
"""Pixels drawn in the grid."""

MAX_TABLE_ROWS = 1_000
"""Rows written of one table."""


class Stepping(NamedTuple):
    """What the stepper needs: positions 0 .. ``n`` (see the module)."""

    n: int
    """The last position."""
    total: int
    """Step records (or pixels, for a pixel stepper) in the answer; more than ``n`` if capped."""
    pixels: list[tuple[int, int]]
    """The drawn pixels, in plotting order (at most :data:`MAX_PIXELS`)."""
    pos: list[int]
    """The position at which each drawn pixel lights."""
    kind: list[int]
    """0: the step's own point; 1: a mirror image."""
    region: list[int]
    """1 or 2 (the ellipse's region 2), for each drawn pixel."""
    captions: list[str]
    """The caption of each position."""
    heads: list[str]
    """A short name of each position (``row k = 3``), for the hover text."""
    row_pos: list[int]
    """The position of each step record shown (``row_pos[i] == i + 1``)."""
    row_region: list[int]
    """The region of each step record shown."""
    total_pixels: int
    """Every plotted pixel, drawn or not."""
    table: int | None = None
    """A comparison's stepper goes through the rows of this secondary table (the methods side
    by side, one row a step); ``None``: through the steps or pixels."""
    table_rows: dict[int, int] | None = None
    """With :attr:`table`: the position of each of its rows that has one (a fill's trace: the
    row that takes pixel i); ``None``: row r is position r + 1."""


_K_SUB = re.compile(r"_\{k\s*([+-])\s*(\d+)\}|_\{k\}|_k(?![A-Za-z0-9])")
_MINUS = re.compile(r"(?<![\w)])-(?=[\d.])")


def with_minus(text: str) -> str:
    """Numbers with a real minus sign, for the captions.

    >>> with_minus("(-3, 4) -0.5 a-b")
    '(−3, 4) −0.5 a-b'
    """
    return _MINUS.sub("\u2212", text)


def column_label(tex: str, k: int | None) -> str:
    """A column heading in Unicode with the row's ``k`` put in its subscripts.

    >>> column_label("p_{k+1}", 2), column_label("p_k", 0), column_label("2r_y^2 x_{k+1}", 4)
    ('p₃', 'p₀', '2r_y² x₅')
    """
    if k is not None:

        def sub(m: re.Match[str]) -> str:
            if m.group(1):
                return "_{" + str(k + int(m.group(2)) * (1 if m.group(1) == "+" else -1)) + "}"
            return "_{" + str(k) + "}"

        tex = _K_SUB.sub(sub, tex)
    try:
        return unicode_heading(tex_to_unicode(tex))
    except ValueError:
        return tex


def _sign(value: Any) -> str:
    try:
        if value < 0:
            return " < 0"
        if value > 0:
            return " > 0"
    except TypeError:
        return ""
    return ""


_CORE = ("k", "p", "decision", "pixel", "region")


def _decided(table: StepTable, step: Step, region: int, exact: bool) -> str:
    """What a row decided, in words: ``p₃ = −2 < 0, so E`` (or ``move E``)."""
    columns = {c.key: c for c in table.columns}
    if step.p is not None and "p" in columns:
        p_tex = columns["p"].tex
        if 0 < region <= len(table.region_p):  # the region's own name of p (p1_k, p2_k)
            p_tex = table.region_p[region - 1]
        said = f"{column_label(p_tex, step.k)} = {with_minus(cell(step.p, columns['p'], exact))}"
        said += _sign(step.p)
        return said + (f", so {step.decision}" if step.decision is not None else "")
    if step.decision is not None:
        return f"move {step.decision}"
    return ""


def _plotted(table: StepTable, step: Step) -> str:
    """What a row plots, in words (a point and its mirror images, or a pixel)."""
    if table.symmetry in (4, 8):
        first = next(mirror_images(step.pixel, table.symmetry, table.center))
        return (
            f"point {with_minus(fmt_pixel(step.pixel))} about the centre: plot "
            f"{with_minus(fmt_pixel(first))} and its {table.symmetry - 1} mirror images (lighter)"
        )
    return f"plot {with_minus(fmt_pixel(step.pixel))}"


def _step_caption(table: StepTable, step: Step, region: int, exact: bool) -> tuple[str, str]:
    """The caption of one row, and its short name."""
    keys = [c.key for c in table.columns]
    head = f"row k = {step.k}" if "k" in keys else f"step {step.k}"
    if region > 1 or "region" in keys:
        head = f"region {region}, {head}"
    decided = _decided(table, step, region, exact)
    # A row that plots (x_{k+1}, y_{k+1}) plots what its decision chose; one that plots
    # (x_k, y_k) decides the move to the next row's pixel.
    before = table.offset == 1
    if decided and not before and step.decision is not None:
        decided += " for the next pixel"
    parts: list[str] = [decided] if decided and before else []
    parts.append(_plotted(table, step))
    if decided and not before:
        parts.append(decided)
    cells = table_cells(table, step)
    for column, value in zip(table.columns, cells, strict=True):
        text = cell(value, column, exact)
        if column.key not in _CORE and text != "-":
            parts.append(f"{column_label(column.tex, step.k)} = {with_minus(text)}")
    return f"{head[0].upper()}{head[1:]}: " + "; ".join(parts) + ".", head


def table_cells(table: StepTable, step: Step) -> tuple[Any, ...]:
    """A row's values in the step table's column order."""
    return step_getter(table.columns, table.extra_keys)(step)


def _regions(table: StepTable, steps: list[Step]) -> list[int]:
    """The region of each row, as :attr:`StepTable.regions` says to read it."""
    if table.regions == "column":
        at = table.extra_keys.index("region")
        return [int(step.extra[at]) for step in steps]
    out: list[int] = []
    current, previous = 1, None
    for step in steps:
        if table.regions == "restart" and previous is not None and step.k <= previous:
            current += 1
        previous = step.k
        out.append(current)
    return out


def stepping(answer: Solution | Document, options: Options | None = None) -> Stepping | None:
    """The stepper's data for an answer, or ``None`` if it has neither steps nor pixels."""
    doc = as_document(answer)
    exact = bool(options and options.exact)
    block: Pixels | None = doc.get(Pixels)
    pixels: list[Pixel] = []
    total_pixels = 0
    if block is not None:
        plotted = block.pixels()
        pixels = list(dict.fromkeys(islice(plotted, MAX_PIXELS)))
        total_pixels = len(pixels) + sum(1 for _ in plotted)
    table: StepTable | None = doc.get(StepTable)
    steps: list[Step] = []
    total_steps = 0
    if table is not None and table.columns:
        rows = table.steps()
        steps = list(islice(rows, MAX_STEPS))
        total_steps = len(steps) + sum(1 for _ in rows)
    if not steps and not pixels:
        return _table_stepping(doc.every(Table), exact)
    if table is None or not steps:
        return _pixel_stepping(doc, block, pixels, total_pixels)
    return _step_stepping(table, block, steps, total_steps, pixels, total_pixels, exact)


def _pixel_stepping(
    doc: Document, block: Pixels | None, pixels: list[Pixel], total_pixels: int
) -> Stepping:
    """A pixel stepper: one pixel a position, in plotting order."""
    labels = block.labels() if block is not None else {}
    captions = ["Start: nothing plotted yet; Next (\u2192) plots the first pixel."]
    heads = ["start"]
    for i, p in enumerate(pixels):
        number = labels.get(p)
        extra = f" (number {number} in the grid)" if number is not None else ""
        captions.append(f"Pixel {i + 1} of {len(pixels)}: plot {with_minus(fmt_pixel(p))}{extra}.")
        heads.append(f"pixel {i + 1}")
    found = _pixel_rows(doc.every(Table), pixels)
    return Stepping(
        n=len(pixels),
        total=total_pixels,
        pixels=pixels,
        pos=list(range(1, len(pixels) + 1)),
        kind=[0] * len(pixels),
        region=[1] * len(pixels),
        captions=captions,
        heads=heads,
        row_pos=[],
        row_region=[],
        total_pixels=total_pixels,
        table=found[0] if found else None,
        table_rows=found[1] if found else None,
    )


class _Lit(NamedTuple):
    """When each drawn pixel lights (-1: not yet known), whether it is a mirror image, and
    its region."""

    pos: list[int]
    kind: list[int]
    region: list[int]


def _light(table: StepTable, steps: list[Step], regions: list[int], pixels: list[Pixel]) -> _Lit:
    """Each drawn pixel lit by the first row that plots it (its point or a mirror image)."""
    index = {p: i for i, p in enumerate(pixels)}
    lit = _Lit([-1] * len(pixels), [0] * len(pixels), [1] * len(pixels))
    for n, (step, region) in enumerate(zip(steps, regions, strict=True), 1):
        for j, p in enumerate(mirror_images(step.pixel, table.symmetry, table.center)):
            at = index.get(p)
            if at is not None and lit.pos[at] < 0:
                lit.pos[at], lit.kind[at], lit.region[at] = n, (0 if j == 0 else 1), region
    return lit


def _start(table: StepTable, pixels: list[Pixel], lit: _Lit) -> str:
    """Light the start pixel (and its mirror images) at position 0 when the rows plot
    ``(x_{k+1}, y_{k+1})``; the start caption."""
    before = [i for i in range(len(pixels)) if lit.pos[i] < 0]
    if not (table.offset and before):
        return "Start: nothing plotted yet; Next (\u2192) plots row 0."
    start = pixels[before[0]]
    lit.pos[before[0]] = 0
    symmetry, center = table.symmetry, table.center
    if symmetry in (4, 8):  # the start point's mirror images are plotted with it
        index = {p: i for i, p in enumerate(pixels)}
        rel = (start[0] - int(center[0]), start[1] - int(center[1]))
        for q in mirror_images(rel, symmetry, center):
            at = index.get(q)
            if at is not None and lit.pos[at] < 0:
                lit.pos[at], lit.kind[at] = 0, 1
    also = " and its mirror images" if symmetry in (4, 8) else ""
    return (
        f"Start: plot {with_minus(fmt_pixel(start))}{also}, plotted before row 0 "
        "(each row plots the next pixel)."
    )


def _joins(lit: _Lit, last: int) -> None:
    """Pixels no row plots (a curve's joining pixels) light with the next row that does."""
    following = last
    for i in range(len(lit.pos) - 1, -1, -1):
        if lit.pos[i] < 0:
            lit.pos[i] = following
            if i > 0:
                lit.region[i] = lit.region[i - 1] if lit.pos[i - 1] >= 0 else lit.region[i]
        else:
            following = lit.pos[i]


def _step_stepping(
    table: StepTable,
    block: Pixels | None,
    steps: list[Step],
    total_steps: int,
    pixels: list[Pixel],
    total_pixels: int,
    exact: bool,
) -> Stepping:
    """A step stepper: position n is the n-th row of the step table."""
    regions = _regions(table, steps)
    lit = _light(table, steps, regions, pixels)
    captions = [""]
    heads = ["start"]
    for step, region in zip(steps, regions, strict=True):
        caption, head = _step_caption(table, step, region, exact)
        captions.append(caption)
        heads.append(head)
    captions[0] = _start(table, pixels, lit)
    n_last = len(steps)
    _joins(lit, n_last)
    if total_steps > len(steps):
        captions[-1] += f" (The stepper stops here: the answer has {total_steps:,} steps.)"
    return Stepping(
        n=n_last,
        total=total_steps,
        pixels=pixels,
        pos=lit.pos,
        kind=lit.kind,
        region=lit.region,
        captions=captions,
        heads=heads,
        row_pos=list(range(1, n_last + 1)),
        row_region=regions,
        total_pixels=total_pixels,
    )


def _pixel_rows(tables: list[Table], pixels: list[Pixel]) -> tuple[int, dict[int, int]] | None:
    """A further table with a column that takes the pixels in plotting order (a fill's
    trace; the pixel as a point or as its text): ``(table index, {row: position})``, the first
    row naming pixel i at position i + 1.
    """
    for t, table in enumerate(tables):
        rows = list(islice(table.rows(), MAX_TABLE_ROWS))
        for j in range(len(table.columns)):
            found: dict[int, int] = {}
            i = 0
            for r, row in enumerate(rows):
                if i < len(pixels) and j < len(row) and row[j] in (pixels[i], fmt_pixel(pixels[i])):
                    found[r] = i + 1
                    i += 1
            if i == len(pixels) and found:
                return t, found
    return None


def _table_stepping(tables: list[Table], exact: bool) -> Stepping | None:
    """An answer that plots nothing but has a :attr:`Table.stepped` table (a comparison): its
    rows, one a step, each caption naming every method's value in that row."""
    at = next((t for t, table in enumerate(tables) if table.stepped), None)
    if at is None:
        return None
    table = tables[at]
    rows = list(islice(table.rows(), MAX_TABLE_ROWS))
    if not rows:
        return None
    labels = [column_label(c.tex, None) for c in table.columns]
    captions = ["Start: Next (\u2192) goes through the table, one row a step."]
    heads = ["start"]
    for i, row in enumerate(rows, 1):
        said = [
            f"{label} = {with_minus(text)}"
            for label, value, c in zip(labels, row, table.columns, strict=False)
            if (text := cell(value, c, exact)) != "-"
        ]
        captions.append(f"Row {i}: " + "; ".join(said) + ".")
        heads.append(f"row {i}")
    n = len(rows)
    return Stepping(n, n, [], [], [], [], captions, heads, [], [], 0, table=at)
