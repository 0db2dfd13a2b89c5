"""Marking a table that is not a pixel walk, by its own columns, with follow-through
(the models of :mod:`.table_models`): dithering, error diffusion, Cyrus-Beck, NLL, midpoint
subdivision, the inside-outside test, line styles, thick lines, bitmap characters (and a
glyph's bytes, a font table) and the frame buffer.

The student's columns are matched to the answer's by their headings (the key, the heading
as printed, or its TeX, in any case and spacing); a column the answer does not have is not
marked. Each row is compared with the answer's row in the same place: a marked cell is right
when it is the answer's own value, or the value the method's rule gives from the student's
own earlier cells (follow-through, so one slip is charged once). The result is a
:class:`~.marking_rows.Marking`, shown and batched as every marking is.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from fractions import Fraction
from typing import Any

from ..answers.methods import STEPPED, answered_by
from ..core.checks import InputError
from ..core.numeric import fmt_short, parse_number
from ..core.records import Column, Solution
from .limits import MAX_QUESTION_ROWS
from .rows import Marking, RowText, Verdict
from .table_models import (
    CoxDeBoorTable,
    FontTableTable,
    GlyphBytesTable,
    InsideVerdictsTable,
    PixelAddressTable,
    PlainRowsTable,
    Row,
    TableModel,
)

TABLE_RULES = (
    "Marking rules: each row is compared with the answer's row in the same place; a row is "
    "right when every marked cell is the answer's own value or the value the method's rule "
    "gives from the student's own earlier cells (follow-through: one slip costs one row). A "
    "row past the end costs one mark, a missing row is wrong."
)


_STAGE_COLUMNS = ("point_edge", "method", "point_out")
"""A clipping stage's columns: each polygon edge, its case and its output."""


def table_models_for(solution: Solution) -> list[TableModel]:
    """The tables of ``solution`` a student's table may be (the inside-outside test: the
    verdicts, or one point's edge tests); the one whose columns the student's headings
    match best is marked."""
    if solution.primitive == "inside":
        verdicts: list[TableModel] = [InsideVerdictsTable()]
        if len(solution.tables) == 2:  # one point: its edge tests too
            verdicts.append(
                PlainRowsTable(
                    "P1", ("straddles", "x", "crossing", "sign"), "Each edge's test stands alone."
                )
            )
        return verdicts
    if solution.primitive == "3d":  # the visible-surface tables: each row stands alone
        return [
            PlainRowsTable(
                t.title,
                tuple(c.key for c in t.columns if c.role == "answer"),
                "Each row stands alone (a face's normal and verdict, a pixel's depth, a window's "
                "decision, a buffer's row).",
            )
            for t in solution.tables
        ]
    stages = [t for t in solution.tables if tuple(c.key for c in t.columns) == _STAGE_COLUMNS]
    if stages and not solution.columns:  # a polygon clipped stage by stage (Sutherland-Hodgman)
        return [
            PlainRowsTable(
                t.title.split(";")[0],
                ("method", "point_out"),
                "Each polygon edge's case and output stand alone: the stage's input vertices "
                "are the table's own (the window edge it names); the stage the student wrote is "
                "the one whose polygon edges the student's are.",
            )
            for t in stages
        ]
    one = table_model_for(solution)
    if one is not None and solution.primitive == "framebuffer" and "base" in solution.data:
        return [one, PixelAddressTable(int(solution.data["b"]), int(solution.data["base"]))]
    if one is not None and solution.primitive == "characters":
        return [one, *_glyph_tables(solution)]
    return [] if one is None else [one]


def _glyph_tables(solution: Solution) -> list[TableModel]:
    """A character's other tables: a glyph's bytes row by row, a font's table of addresses."""
    titles = [t.title for t in solution.tables]
    found: list[TableModel] = []
    if any(t.startswith("The glyph as bytes") for t in titles):
        found.append(GlyphBytesTable())
    if any(t.startswith("The font table") for t in titles):
        found.append(FontTableTable(int(solution.data["per_glyph"])))
    return found


def table_model_for(solution: Solution) -> TableModel | None:
    """The table model of ``solution``'s method, or ``None`` (a pixel walk, or unmarked): the
    factory its method record names (:func:`~scanconv.answers.methods.answered_by`, the
    record's ``model``, :mod:`.table_factories`)."""
    if solution.primitive == "inside":
        return table_models_for(solution)[0]
    if (solution.primitive, solution.algorithm) == ("curve", "bspline-basis-at"):
        found = {q.key: q.value for q in solution.derived}
        t = next(q.value for q in solution.given if q.key == "t")
        return CoxDeBoorTable(found["knots"], t, int(found["span"]))
    record = answered_by(solution.primitive, solution.algorithm)
    if record is None or record.model is None or record.command in STEPPED:
        return None
    model: TableModel | None = record.load("model")(solution)
    return model


def canon(value: Any) -> Any:
    """A cell as compared: an exact number, a pair of them, lower-case text, or ``None``.

    >>> canon("-6/7"), canon("(270/7, 50)"), canon(" Entering "), canon("-")
    (Fraction(-6, 7), (Fraction(270, 7), Fraction(50, 1)), 'entering', None)
    >>> canon("+1 (up)"), canon("Inside (odd)")
    (Fraction(1, 1), 'inside')
    """
    if value is None or isinstance(value, bool):
        return None if value is None else Fraction(int(value))
    if isinstance(value, int | Fraction):
        return Fraction(value)
    if isinstance(value, float):
        return Fraction(str(value))
    if isinstance(value, tuple | list):
        return tuple(canon(v) for v in value)
    text = " ".join(str(value).replace("\u2212", "-").split()).lower()
    if text in ("", "-", "\u2013"):
        return None
    remark = re.fullmatch(r"(.*[^\s(])\s+\([^()]*\)", text)
    if remark:  # "+1 (up)", "inside (odd)": the remark is not marked
        return canon(remark[1])
    try:
        return parse_number(text, 10**24)
    except ValueError:
        pass
    pair = re.fullmatch(r"\(?\s*([^,()]+?)\s*,\s*([^,()]+?)\s*\)?", text)
    if pair:
        try:
            return (parse_number(pair[1], 10**24), parse_number(pair[2], 10**24))
        except ValueError:
            pass
    return text.replace("\u2260", "!=").replace("\u2264", "<=").replace("\u2265", ">=")


def _norm(text: str) -> str:
    return re.sub(r"\\text|[\s${}\\_*·.']", "", text).lower()


def _answer_columns(solution: Solution, model: TableModel) -> tuple[Column, ...]:
    if model.table is None:
        return solution.columns
    table = next((t for t in solution.tables if t.title.startswith(model.table)), None)
    return () if table is None else table.columns


def _answer(solution: Solution, model: TableModel) -> tuple[tuple[Column, ...], list[Row]]:
    """The marked table's columns and its rows, canonical."""
    if model.table is None:
        keys = ("k", "p", "decision", "pixel")
        extra = solution.extra_keys

        def cells(s: Any) -> Iterator[Any]:
            for c in solution.columns:
                yield getattr(s, c.key) if c.key in keys else s.extra[extra.index(c.key)]

        rows = []
        for n, s in enumerate(solution.steps()):
            if n >= MAX_QUESTION_ROWS:  # the row n + 1 (n counts from 0)
                raise InputError(f"the question's table has more than {MAX_QUESTION_ROWS} rows")
            rows.append(tuple(cells(s)))
        columns = solution.columns
    else:
        table = next((t for t in solution.tables if t.title.startswith(model.table)), None)
        if table is None:
            raise InputError(f"the question has no {model.table!r} table to mark", "question")
        columns, rows = table.columns, list(table.rows())
    return columns, [{c.key: canon(v) for c, v in zip(columns, r, strict=False)} for r in rows]


def _match(headers: Sequence[str], columns: Sequence[Column]) -> list[str | None]:
    """Each heading's column key (``None``: not the answer's); a repeated heading takes the
    next column of that name (NLL's two ``value`` columns)."""
    taken: set[str] = set()
    out: list[str | None] = []
    for h in headers:
        n = _norm(str(h))
        key = next(
            (c.key for c in columns
             if c.key not in taken and n in (_norm(c.key), _norm(c.text), _norm(c.tex))),
            None,
        )  # fmt: skip
        if key is not None:
            taken.add(key)
        out.append(key)
    return out


def _show(v: Any) -> str:
    if v is None:
        return "-"
    if isinstance(v, tuple):
        return "(" + ", ".join(_show(x) for x in v) + ")"
    return fmt_short(v) if isinstance(v, Fraction) else str(v)


def mark_table(
    headers: Sequence[str],
    raw: Sequence[tuple[str, list[Any]]],
    solution: Solution,
    models: Sequence[TableModel],
    name: str,
) -> Marking:
    """Mark the student's rows ``raw`` (with their ``headers``) against ``solution``'s table
    of the model whose marked columns the headings match most."""

    def matched(m: TableModel) -> int:
        keys = _match(headers, _answer_columns(solution, m))
        return sum(k in keys for k in m.marked)

    def agreed(m: TableModel) -> int:
        """How many of the student's unmarked cells (the inputs they copied: a stage's
        polygon edges) are that table's own: which of several like tables they wrote."""
        columns, answer = _answer(solution, m)
        keys = _match(headers, columns)
        return sum(
            canon(m.read(k, v)) == row.get(k)
            for (_, cells), row in zip(raw, answer, strict=False)
            for k, v in zip(keys, cells, strict=False)
            if k is not None and k not in m.marked
        )

    best = max(map(matched, models))
    tied = [m for m in models if matched(m) == best]
    model = tied[0] if len(tied) == 1 else max(tied, key=agreed)
    columns, answer = _answer(solution, model)
    keys = _match(headers, columns)
    marked = [k for k in model.marked if k in keys]
    if not marked:
        names = ", ".join(c.text for c in columns if c.key in model.marked)
        raise InputError(f"{name}: no column to mark: the answer's table has {names}", "answer")
    texts = [c.text for c in columns]
    titles = {
        c.key: c.text if texts.count(c.text) == 1 else f"{c.text} ({c.key.replace('_', ' ')})"
        for c in columns
    }
    verdicts = _verdicts(raw, keys, marked, titles, model, answer)
    right = sum(v.mark.startswith("right") for v in verdicts[: len(answer)])
    right = max(0, right - max(0, len(raw) - len(answer)))
    first = next((v for v in verdicts if not v.mark.startswith("right")), None)
    return Marking(
        tuple(verdicts),
        right,
        len(answer),
        _first_error(first, titles),
        "",
        True,
        tuple(titles[k] for k in marked),
        "",
        f"{TABLE_RULES} {model.rules}",
    )


def _verdicts(
    raw: Sequence[tuple[str, list[Any]]],
    keys: Sequence[str | None],
    marked: list[str],
    titles: dict[str, str],
    model: TableModel,
    answer: list[Row],
) -> list[Verdict]:
    """Each student row judged against what the model expects after the student's own rows
    (follow-through), then a "missing" verdict for each answer row the student left out."""

    def text(row: Row) -> RowText:
        return RowText(", ".join(f"{titles[k]} = {_show(row.get(k))}" for k in marked))

    own: list[Row] = []
    verdicts: list[Verdict] = []
    for n, (where, cells) in enumerate(raw):
        row = {
            k: canon(model.read(k, v)) for k, v in zip(keys, cells, strict=False) if k is not None
        }
        own.append(row)
        if n >= len(answer):
            verdicts.append(Verdict(n + 1, where, text(row), None, "extra"))  # type: ignore[arg-type]
            continue
        exp = {k: canon(v) for k, v in model.expect(n, answer, own).items()}
        wrong = tuple(k for k in marked if row.get(k) not in (exp.get(k), answer[n].get(k)))
        follows = any(row.get(k) != answer[n].get(k) for k in marked)
        mark = "wrong" if wrong else "right (follow-through)" if follows else "right"
        verdicts.append(Verdict(n + 1, where, text(row), text(exp), mark, wrong))  # type: ignore[arg-type]
    for n in range(len(raw), len(answer)):
        verdicts.append(Verdict(n + 1, "-", None, text(answer[n]), "missing"))  # type: ignore[arg-type]
    return verdicts


def _first_error(v: Verdict | None, titles: dict[str, str]) -> str:
    if v is None:
        return ""
    if v.mark == "missing":
        return f"Row {v.row}: missing ({v.expected.text})"  # type: ignore[union-attr]
    if v.mark == "extra":
        return f"Row {v.row} ({v.where}): a row past the end of the table"
    cells = ", ".join(titles[k] for k in v.wrong)
    return f"Row {v.row} ({v.where}): {cells} wrong; expected {v.expected.text}"  # type: ignore[union-attr]
