"""What the HTML page steps through: positions, the pixels each lights, the captions.

:func:`stepping` reads a :class:`~scanconv.core.records.Solution` into a :class:`Stepping`
(see :mod:`scanconv.render.html` for what a position is): the step records with their pixels
(and mirror images), the pixels alone in plotting order for an answer without a step table,
or the rows of a comparison's side-by-side table. The captions give each decision with its
numbers, in Unicode.
"""

from __future__ import annotations

import re
from itertools import islice
from typing import Any, NamedTuple

from ..core.numeric import fmt_pixel
from ..core.records import Solution, Step, step_getter
from ..core.working import tex_to_unicode
from ..document.numbering import label_offset, mirror_images, step_labels
from . import Options
from .cells import cell, unicode_heading

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


def _step_caption(
    solution: Solution, step: Step, region: int, symmetry: int, center: Any, exact: bool
) -> tuple[str, str]:
    """The caption of one step, and its short name."""
    columns = {c.key: c for c in solution.columns}
    get = step_getter(solution.columns, solution.extra_keys)
    cells = dict(zip((c.key for c in solution.columns), get(step), strict=True))
    head = f"row k = {step.k}" if "k" in columns else f"step {step.k}"
    if region > 1 or "region" in columns:
        head = f"region {region}, {head}"
    decided = ""
    if step.p is not None and "p" in columns:
        p_tex = columns["p"].tex
        if "region" in columns:  # the region's own name of p (p1_k, p2_k), from its table
            for table in solution.tables:
                if table.title.startswith(f"Region {region} "):
                    p_tex = next((c.tex for c in table.columns if c.key == "p"), p_tex)
        decided = f"{column_label(p_tex, step.k)} = {with_minus(cell(step.p, columns['p'], exact))}"
        decided += _sign(step.p)
        if step.decision is not None:
            decided += f", so {step.decision}"
    elif step.decision is not None:
        decided = f"move {step.decision}"
    # A row that plots (x_{k+1}, y_{k+1}) plots what its decision chose; one that plots
    # (x_k, y_k) decides the move to the next row's pixel.
    before = label_offset(solution) == 1
    if decided and not before and step.decision is not None:
        decided += " for the next pixel"
    parts: list[str] = [decided] if decided and before else []
    if symmetry in (4, 8):
        first = next(mirror_images(step.pixel, symmetry, center))
        parts.append(
            f"point {with_minus(fmt_pixel(step.pixel))} about the centre: plot "
            f"{with_minus(fmt_pixel(first))} and its {symmetry - 1} mirror images (lighter)"
        )
    else:
        parts.append(f"plot {with_minus(fmt_pixel(step.pixel))}")
    if decided and not before:
        parts.append(decided)
    for key, column in columns.items():
        if key in _CORE:
            continue
        text = cell(cells[key], column, exact)
        if text != "-":
            parts.append(f"{column_label(column.tex, step.k)} = {with_minus(text)}")
    return f"{head[0].upper()}{head[1:]}: " + "; ".join(parts) + ".", head


def stepping(solution: Solution, options: Options | None = None) -> Stepping | None:
    """The stepper's data for ``solution``, or ``None`` if it has neither steps nor pixels."""
    exact = bool(options and options.exact)
    plotted_all = solution.pixels() if solution.pixels is not None else iter(())
    pixels = list(dict.fromkeys(islice(plotted_all, MAX_PIXELS)))
    total_pixels = len(pixels) + sum(1 for _ in plotted_all)
    has_steps = bool(solution.columns)
    steps_iter = solution.steps() if has_steps else iter(())
    steps = list(islice(steps_iter, MAX_STEPS))
    total_steps = len(steps) + sum(1 for _ in steps_iter)
    if not steps and not pixels:
        return _table_stepping(solution, exact)
    index = {p: i for i, p in enumerate(pixels)}
    pos = [-1] * len(pixels)
    kind = [0] * len(pixels)
    region = [1] * len(pixels)
    if not steps:  # a pixel stepper: one pixel a position, in plotting order
        labels = step_labels(solution) if solution.pixels is not None else {}
        captions = ["Start: nothing plotted yet; Next (\u2192) plots the first pixel."]
        heads = ["start"]
        for i, p in enumerate(pixels):
            pos[i] = i + 1
            number = labels.get(p)
            extra = f" (number {number} in the grid)" if number is not None else ""
            captions.append(
                f"Pixel {i + 1} of {len(pixels)}: plot {with_minus(fmt_pixel(p))}{extra}."
            )
            heads.append(f"pixel {i + 1}")
        found = _pixel_rows(solution, pixels)
        return Stepping(
            len(pixels), total_pixels, pixels, pos, kind, region, captions, heads, [], [],
            total_pixels, found[0] if found else None, found[1] if found else None,
        )  # fmt: skip
    symmetry = int(solution.geometry.get("symmetry", 1))
    center = solution.geometry.get("center", (0, 0))
    has_region = "region" in solution.extra_keys
    captions = [""]
    heads = ["start"]
    row_region: list[int] = []
    current_region, previous_k = 1, None
    for n, step in enumerate(steps, 1):
        if has_region:
            current_region = int(step.extra[solution.extra_keys.index("region")])
        elif previous_k is not None and step.k <= previous_k:
            current_region += 1
        previous_k = step.k
        row_region.append(current_region)
        for j, p in enumerate(mirror_images(step.pixel, symmetry, center)):
            at = index.get(p)
            if at is not None and pos[at] < 0:
                pos[at], kind[at], region[at] = n, (0 if j == 0 else 1), current_region
        caption, head = _step_caption(solution, step, current_region, symmetry, center, exact)
        captions.append(caption)
        heads.append(head)
    n_last = len(steps)
    before = [i for i in range(len(pixels)) if pos[i] < 0]
    if label_offset(solution) and before:
        start = pixels[before[0]]
        pos[before[0]] = 0
        if symmetry in (4, 8):  # the start point's mirror images are plotted with it
            rel = (start[0] - int(center[0]), start[1] - int(center[1]))
            for q in mirror_images(rel, symmetry, center):
                at = index.get(q)
                if at is not None and pos[at] < 0:
                    pos[at], kind[at] = 0, 1
        also = " and its mirror images" if symmetry in (4, 8) else ""
        captions[0] = (
            f"Start: plot {with_minus(fmt_pixel(start))}{also}, plotted before row 0 "
            "(each row plots the next pixel)."
        )
    else:
        captions[0] = "Start: nothing plotted yet; Next (\u2192) plots row 0."
    following = n_last
    for i in range(len(pixels) - 1, -1, -1):  # joining pixels light with the next step's
        if pos[i] < 0:
            pos[i] = following
            if i > 0:
                region[i] = region[i - 1] if pos[i - 1] >= 0 else region[i]
        else:
            following = pos[i]
    if total_steps > len(steps):
        captions[-1] += f" (The stepper stops here: the answer has {total_steps:,} steps.)"
    return Stepping(
        n_last, total_steps, pixels, pos, kind, region, captions, heads,
        list(range(1, n_last + 1)), row_region, total_pixels,
    )  # fmt: skip


def _pixel_rows(
    solution: Solution, pixels: list[tuple[int, int]]
) -> tuple[int, dict[int, int]] | None:
    """A secondary table with a column that takes the pixels in plotting order (a fill's
    trace; the pixel as a point or as its text): ``(table index, {row: position})``, the first
    row naming pixel i at position i + 1.
    """
    for t, table in enumerate(solution.tables):
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


def _table_stepping(solution: Solution, exact: bool) -> Stepping | None:
    """A comparison (no steps, no pixels of its own): its first table's rows, one a step, each
    caption naming every method's value in that row."""
    if solution.algorithm != "compare" or not solution.tables:
        return None
    table = solution.tables[0]
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
    return Stepping(n, n, [], [], [], [], captions, heads, [], [], 0, table=0)
