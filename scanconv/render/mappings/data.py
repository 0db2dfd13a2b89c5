"""The ``csv`` and ``json`` formats: data for other tools, streamed row by row.

CSV is the step table only, one header row of unique column names; a pixel column becomes two
columns ``x`` and ``y`` (``plot_x`` and ``plot_y`` next to the algorithm's own coordinates,
:func:`pixel_names`). JSON is one object (documented in docs/formats.md, "JSON output")::

    {"primitive": "line", "algorithm": "bresenham", "title": ..., "given": {...},
     "derived": {...}, "working": [...], "notes": [...], "columns": [...],
     "steps": [{"k": 0, "p": 0, "decision": "NE", "pixel": [3, 3], "p_next": -8}, ...],
     "pixels": [[2, 2], [3, 3], ...]}

Steps carry ``k`` and ``pixel`` always, ``p`` and ``decision`` where the algorithm has them,
and the algorithm's own columns under their own keys. Integers are JSON integers, other
exact values JSON numbers. Both formats are written as they are produced.

Further tables are JSON's ``tables`` (CSV writes the first only when there is no step
table); pseudocode (``--algorithm``) is JSON's ``pseudocode``, ``[{"title": ..., "lines":
[...]}]``, each line as written (its leading spaces the indentation, no numbers). CSV leaves
it out: it is no table.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Iterator
from itertools import chain, islice
from typing import Any

from ...core.records import Solution
from ...core.working import json_visible
from ...document import (
    Document,
    Given,
    Notes,
    Pixels,
    Pseudocode,
    StepTable,
    Table,
    Working,
    as_document,
)
from .. import Options
from ..cells import json_value, segments_unicode


def render_csv(answer: Solution | Document, options: Options | None = None) -> Iterator[str]:
    """The step table as CSV (or, for an answer without one, its first secondary table)."""
    doc = as_document(answer)
    table: StepTable | None = doc.get(StepTable)
    if table is None or not table.columns:
        yield from _table_csv(doc.get(Table))
        return
    shown = {c.key for c in table.columns} | {"k", "pixel"}
    keys = [k for k in ("k", "p", "decision", "pixel", *table.extra_keys) if k in shown]
    header: list[str] = []
    for k in keys:
        header.extend(pixel_names(table.extra_keys) if k == "pixel" else (k,))
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(header)
    yield buf.getvalue()
    index = {"k": 0, "p": 1, "decision": 2, "pixel": 3}
    extra = {k: i for i, k in enumerate(table.extra_keys)}
    for step in table.steps():
        row: list[object] = []
        for k in keys:
            if k == "pixel":
                row.extend(step.pixel)
            else:
                row.append(_csv_cell(step[index[k]] if k in index else step.extra[extra[k]]))
        buf.seek(0)
        buf.truncate()
        writer.writerow(row)
        yield buf.getvalue()


_COORDINATES = ("x", "y", "x_k", "y_k")


def pixel_names(extra_keys: tuple[str, ...]) -> tuple[str, str]:
    """The CSV names of the pixel's two columns: ``x, y``, or ``plot_x, plot_y`` next to the
    algorithm's own coordinates (the DDA's exact ``x, y`` and ``round_x``, a circle's octant
    point ``x_k, y_k``), so that every column name is unique and says what it holds.

    >>> pixel_names(("p_next",)), pixel_names(("x", "y", "round_x", "round_y"))
    (('x', 'y'), ('plot_x', 'plot_y'))
    """
    if any(k in _COORDINATES or k.startswith("round_") for k in extra_keys):
        return ("plot_x", "plot_y")
    return ("x", "y")


def _table_csv(table: Table | None) -> Iterator[str]:
    if table is None:
        return
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow([c.key for c in table.columns])
    yield buf.getvalue()
    rows = iter(table.rows())
    per = batch_rows(len(table.columns))
    while batch := list(islice(rows, per)):  # 2**24 rows at most: written in batches
        text = _plain_csv(batch)
        if text is None:
            buf.seek(0)
            buf.truncate()
            writer.writerows([_csv_cell(v) for v in row] for row in batch)
            text = buf.getvalue()
        yield text


_BATCH_CELLS = 16_384
"""Cells of a secondary table rendered at once (``csv``, ``json``): 4,096 rows of a
quantizer's four columns, 4 rows of a 4096-column matrix (a batch of 4,096 such rows held
16.7 million cells: 415 MB for ``sample`` at 4096 x 4096)."""


def batch_rows(columns: int) -> int:
    """Rows of a table of ``columns`` columns rendered at once.

    >>> batch_rows(4), batch_rows(4097), batch_rows(100_000)
    (4096, 3, 1)
    """
    return max(1, _BATCH_CELLS // max(1, columns))


_PLAIN = {int, str}
"""Cell types that csv and json write as they are (no conversion, see :func:`_csv_cell`)."""


def _plain(rows: list[tuple[Any, ...]]) -> bool:
    """Whether every cell of ``rows`` is an ``int`` or a ``str`` (not a bool, not an enum)."""
    return {*map(type, chain.from_iterable(rows))} <= _PLAIN


def _plain_csv(rows: list[tuple[Any, ...]]) -> str | None:
    r"""The text ``csv.writer`` writes for ``rows`` (equal lengths >= 2, int and str cells, no
    text that needs quoting), formatted at once; ``None`` otherwise.

    >>> _plain_csv([(1, "a b"), (2, "c")]), _plain_csv([(1, "a,b")]), _plain_csv([("x",)])
    ('1,a b\n2,c\n', None, None)
    """
    width = len(rows[0])
    if width < 2 or {*map(len, rows)} != {width} or not _plain(rows):
        return None
    text = (("%s," * (width - 1) + "%s\n") * len(rows)) % tuple(chain.from_iterable(rows))
    if (
        text.count(",") != (width - 1) * len(rows)
        or text.count("\n") != len(rows)
        or '"' in text
        or "\r" in text
    ):
        return None  # a text cell with a comma, quote or line break: csv.writer quotes it
    return text


def _csv_cell(v: object) -> object:
    if type(v) is int or type(v) is str:  # the common cells first (16,777,216 in a matrix)
        return v
    j = json_value(v)
    if isinstance(j, list):
        return " ".join(str(x) for x in j)
    return "" if j is None else j


def render_json(answer: Solution | Document, options: Options | None = None) -> Iterator[str]:
    """The whole answer as one JSON object, steps streamed one per line."""
    doc = as_document(answer)
    d = json.dumps
    given: Given | None = doc.get(Given)
    working: Working | None = doc.get(Working)
    notes: Notes | None = doc.get(Notes)
    table: StepTable | None = doc.get(StepTable)
    derived = working.lines if working else ()
    head = {
        "primitive": doc.primitive,
        "algorithm": doc.algorithm,
        "title": doc.title,
        "given": {q.key: json_value(q.value) for q in (given.quantities if given else ())},
        "derived": {q.key: json_value(q.value) for q in derived},
        "working": [q.text for q in derived],
        "notes": [
            segments_unicode(n.segments) for n in (notes.notes if notes else ())
        ],  # as "working"
        "columns": [c.key for c in (table.columns if table else ())],
    }
    head.update({k: json_value(v) for k, v in doc.data.items()})
    yield json_visible(d(head, ensure_ascii=False))[:-1] + ',\n "steps": [\n'
    if table is not None:
        yield from _steps_json(table)
    yield " ]"
    pixels: Pixels | None = doc.get(Pixels)
    if pixels is not None:
        yield ',\n "pixels": ['
        first = True
        for p in pixels.pixels():
            yield ("" if first else ", ") + f"[{p[0]}, {p[1]}]"
            first = False
        yield "]"
    yield from _tables_json(doc.every(Table))
    yield from _code_json(doc.every(Pseudocode))
    yield "}\n"


def _steps_json(table: StepTable) -> Iterator[str]:
    """The ``steps`` array's rows, one a line, and the line break after the last."""
    d = json.dumps
    has_p, has_decision, keys = table.has_p, table.has_decision, table.extra_keys
    first = True
    for s in table.steps():
        obj: dict[str, object] = {"k": s.k}
        if has_p:
            obj["p"] = json_value(s.p)
        if has_decision:
            obj["decision"] = json_value(s.decision)
        obj["pixel"] = list(s.pixel)
        for k, v in zip(keys, s.extra, strict=True):
            obj[k] = json_value(v)
        yield ("  " if first else ",\n  ") + d(obj, ensure_ascii=False)
        first = False
    if not first:
        yield "\n"


def _tables_json(tables: list[Table]) -> Iterator[str]:
    """The ``tables`` field: the text one ``json.dumps`` would write, streamed row by row."""
    if not tables:
        return
    d = json.dumps
    yield ',\n "tables": ['
    for n, t in enumerate(tables):
        title = json_visible(d(t.title, ensure_ascii=False))
        columns = d([c.key for c in t.columns], ensure_ascii=False)
        yield f'{", " if n else ""}{{"title": {title}, "columns": {columns}, "rows": ['
        encode = json.JSONEncoder(ensure_ascii=False).encode  # once: 2**24 rows at most
        rows, sep, per = iter(t.rows()), "", batch_rows(len(t.columns))
        while batch := list(islice(rows, per)):
            if _plain(batch):  # json_value leaves int and str as they are: one encode
                text = encode(batch)[1:-1]
            else:
                text = ", ".join(encode([json_value(v) for v in row]) for row in batch)
            yield sep + json_visible(text)
            sep = ", "
        yield "]}"
    yield "]"


def _code_json(listings: list[Pseudocode]) -> Iterator[str]:
    """The ``pseudocode`` field: each listing's title and its lines, unnumbered.

    >>> print("".join(_code_json([Pseudocode("t", ("a", "  b"))])))
    ,
     "pseudocode": [{"title": "t", "lines": ["a", "  b"]}]
    """
    if listings:
        items = [{"title": c.title, "lines": list(c.lines)} for c in listings]
        yield ',\n "pseudocode": ' + json_visible(json.dumps(items, ensure_ascii=False))
