"""A student's step table, read from CSV, a Markdown pipe table or JSON, forgivingly.

A teacher hands scanconv the table a student wrote; this module turns it into rows of exact
values, matching the columns by their headings and the cells by their values, however they
were typed:

* headings: case, spaces, TeX (``$p_k$``, ``(x_{k+1}, y_{k+1})``), Unicode subscripts
  (``pₖ``) and common names (``p``, ``pk``, ``d_k``, ``pixel``, ``plot``, ``(x, y)``,
  ``x`` and ``y`` in two columns, ``round(x)``) all map to a few canonical fields;
* cells: ``2.5`` is ``2.500``, ``5/2`` is 2.5, ``(3,3)`` is ``(3, 3)`` and ``3 3``, the
  Unicode minus ``−`` is a minus, an empty cell or a dash is "no value".

Nothing in a cell is ever evaluated: numbers go through
:func:`~scanconv.core.numeric.parse_number`, which accepts only literals.

The canonical fields (:data:`FIELDS`) are ``k``, ``p`` (the decision parameter a row decides
on), ``p_next``, ``x`` and ``y`` (two coordinate columns), ``xy`` (a coordinate pair column),
``px``/``py``/``pxy`` (columns named as rounded or plotted: ``round(x)``, ``plot``, ``pixel``),
``region`` and ``decision``. Which of them is the pixel and which an exact coordinate is for
the marking to decide (a DDA table has both).

Bad input raises :class:`~scanconv.core.checks.InputError` with one line that names the file
and, where there is one, the line (``alice.csv, line 4: 'abc' is not a number``).

>>> t = parse_text("k,p_k,(x_{k+1}, y_{k+1})\\n0,0,(3,3)\\n1,−8,\\"(4, 3)\\"\\n", "a.csv")
>>> t.fields, t.after, [r.cells["p"].value for r in t.rows], t.rows[1].cells["xy"]
(('k', 'p', 'xy'), True, [Fraction(0, 1), Fraction(-8, 1)], (Cell(value=Fraction(4, 1), places=0), Cell(value=Fraction(3, 1), places=0)))
"""

from __future__ import annotations

import csv
import json
import os
import re
from fractions import Fraction
from pathlib import Path
from typing import Any, NamedTuple

from ..core.checks import InputError
from ..core.decisions import EMPTY as _EMPTY
from ..core.decisions import move_of
from ..core.headings import field_of
from ..core.numeric import parse_number
from .table_head import unbracketed as _unbracketed
from .table_head import without_preamble as _without_preamble

MAX_TABLE_BYTES = 2**18
"""Largest student file read (256 KiB): a 1,000-row table of a dozen columns is under 60 KiB."""

CELL_LIMIT = 10**24
"""Largest magnitude of a student's number: a decision parameter of a large ellipse passes
10^9 (1,726,200,000 for rx = ry = 1200), far below this."""

MAX_TABLE_ROWS = 5000
"""Most rows of a student table: more than any hand-written table, and enough to mark a long
line's or a large circle's table written by a student's own program."""

FIELDS = ("k", "p", "p_next", "decision", "x", "y", "xy", "px", "py", "pxy", "region")
"""The canonical fields, in the order a table lists them."""

_PIXEL_FIELDS = {"x", "xy", "px", "pxy"}


class Cell(NamedTuple):
    """One number as the student wrote it: its exact value and how many decimals it had."""

    value: Fraction
    places: int


Value = Cell | tuple[Cell, Cell] | str | None
"""A cell: a number, a coordinate pair, a move (a decision: ``NE``), or nothing (an empty
cell or a dash)."""


class Row(NamedTuple):
    """One row of the student's table: where it is in the file, and its cells by field."""

    where: str
    """``line 4`` (CSV, Markdown) or ``row 3`` (JSON), for messages."""
    cells: dict[str, Value]


class StudentTable(NamedTuple):
    """A student's table with its columns mapped to :data:`FIELDS`."""

    name: str
    """The file's name, for messages."""
    fields: tuple[str, ...]
    """The fields the table has, in its column order."""
    after: bool
    """A heading says ``k+1`` next to the coordinates: each row plots ``(x_{k+1}, y_{k+1})``."""
    rows: tuple[Row, ...]
    ignored: tuple[str, ...] = ()
    """Headings that map to no field (``2ry²x``): read, never marked."""


def read_table(path: Path) -> StudentTable:
    """Read and parse the student file at ``path`` (see :func:`parse_text`)."""
    return parse_bytes(_read(path), path.name, path.suffix.lower())


def read_raw(path: Path) -> tuple[list[str], list[tuple[str, list[Any]]]]:
    """The student file's headings and rows as written (cells unread), for a table marked by
    its own columns (:mod:`scanconv.marking.tables`); the same checks as
    :func:`read_table`."""
    name = path.name
    return raw_text(_decode(_read(path), name), name, path.suffix.lower())


def read_text(path: Path) -> str:
    """The student file at ``path`` as text, with the checks of :func:`read_table` (its size,
    a binary file, UTF-8)."""
    return _decode(_read(path), path.name)


def checked_text(text: str, name: str) -> str:
    """A table given as text (not read from a file), with the checks a file's text gets: its
    size in UTF-8 and no NUL (a binary file pasted as text).

    >>> checked_text("k,p\\n0,1\\n", "the table")
    'k,p\\n0,1\\n'
    >>> checked_text("x" * (MAX_TABLE_BYTES + 1), "the table")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: the table: larger than 262144 bytes
    """
    if len(text) > MAX_TABLE_BYTES:  # before encoding it: a 1 GB string is refused at once
        raise InputError(f"{name}: larger than {MAX_TABLE_BYTES} bytes", "answer")
    return _decode(text.encode("utf-8", "surrogatepass"), name)


def _read(path: Path) -> bytes:
    name = path.name
    try:
        size = os.stat(path).st_size
        if not path.is_file():
            raise InputError(f"{name}: not a regular file", "answer")
        if size > MAX_TABLE_BYTES:
            raise InputError(
                f"{name}: {size} bytes, larger than a student table can be "
                f"(at most {MAX_TABLE_BYTES} bytes)",
                "answer",
            )
        with open(path, "rb") as f:
            return f.read(MAX_TABLE_BYTES + 1)
    except OSError as err:
        raise InputError(f"{name}: cannot read: {err.strerror or err}", "answer") from None


def parse_bytes(data: bytes, name: str, suffix: str = "") -> StudentTable:
    """Decode a student file (UTF-8, with or without a byte-order mark) and parse it.

    >>> parse_bytes(b"\\x00\\x01", "a.csv")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: a.csv: a binary file, not a table
    """
    return parse_text(_decode(data, name), name, suffix)


def _decode(data: bytes, name: str) -> str:
    if len(data) > MAX_TABLE_BYTES:
        raise InputError(f"{name}: larger than {MAX_TABLE_BYTES} bytes", "answer")
    if b"\x00" in data[:8192]:
        raise InputError(f"{name}: a binary file, not a table", "answer")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as err:
        line = data[: err.start].count(b"\n") + 1
        byte = data[err.start]
        raise InputError(
            f"{name}, line {line}: not UTF-8 text (byte 0x{byte:02x}); save the file as UTF-8",
            "answer",
        ) from None


def parse_text(text: str, name: str, suffix: str = "") -> StudentTable:
    """Parse a table: JSON, a Markdown pipe table or CSV (by ``suffix``, else by its look)."""
    return _build(name, *raw_text(text, name, suffix))


def raw_text(text: str, name: str, suffix: str = "") -> tuple[list[str], list[RawRow]]:
    """The headings and rows of a table in any of the formats (see :func:`parse_text`)."""
    if not text.strip():
        raise InputError(f"{name}: the file is empty", "answer")
    start = text.lstrip()[:1]
    if suffix == ".json" or (suffix not in (".csv", ".md", ".markdown") and start in "[{"):
        return _json_rows(text, name)
    if suffix in (".md", ".markdown") or (
        suffix not in (".csv", ".tsv", ".txt") and _SEPARATOR.search(text)
    ):
        return _markdown_rows(text, name)
    if suffix not in (".csv", ".tsv") and _RULE.search(text):
        return _plain_rows(text, name)
    if suffix not in (".csv", ".tsv", ".txt") and _PIPE_LINE.search(text):
        return _markdown_rows(text, name)
    return _csv_rows(text, name)


# --- the three formats ------------------------------------------------------------------------


RawRow = tuple[str, list[Any]]


def _csv_rows(text: str, name: str) -> tuple[list[str], list[RawRow]]:
    lines = _without_preamble(text.splitlines())
    first = next((ln for ln in lines if ln.strip() and not ln.lstrip().startswith("#")), "")
    # a tab first: the notes' tables are tab-separated with commas inside "(x, y)"
    bare = _unbracketed(first)  # the commas of "(x, y)" part nothing
    delimiter = "\t" if "\t" in bare else "," if "," in bare else ";" if ";" in bare else " "
    headers: list[str] | None = None
    rows: list[RawRow] = []
    try:
        reader = csv.reader(lines, delimiter=delimiter) if delimiter != " " else _spaced(lines)
        for number, cells in enumerate(reader, 1):
            if not any(c.strip() for c in cells) or cells[0].lstrip().startswith("#"):
                continue
            cells = _rejoin(cells, delimiter)
            if headers is None:
                headers = cells
                continue
            rows.append((f"line {number}", cells))
            _check_rows(rows, name)
    except csv.Error as err:
        raise InputError(f"{name}: not a CSV table ({err})", "answer") from None
    return headers or [], rows


def _spaced(lines: list[str]) -> list[list[str]]:
    """Columns lined up with spaces (a table typed in a text file): two or more spaces part
    the cells if the heading has them, else any space does.

    >>> _spaced(["k  p_k  (x, y)", "0    0  (2, 2)"])
    [['k', 'p_k', '(x, y)'], ['0', '0', '(2, 2)']]
    """
    first = next((ln for ln in lines if ln.strip()), "")
    wide = re.search(r"\S {2,}\S", first.strip()) is not None
    return [
        re.split(r" {2,}" if wide else r"\s+", ln.strip()) if ln.strip() else [] for ln in lines
    ]


def _rejoin(cells: list[str], delimiter: str) -> list[str]:
    """Join the cells an unquoted pair was split into: ``(3``, `` 3)`` is ``(3, 3)``.

    >>> _rejoin(["0", "(x_{k+1}", " y_{k+1})", "(3", "3)"], ",")
    ['0', '(x_{k+1}, y_{k+1})', '(3,3)']
    """
    out: list[str] = []
    open_ = False
    for c in cells:
        if open_:
            out[-1] += delimiter + c
        else:
            out.append(c)
        s = out[-1]
        open_ = s.count("(") + s.count("[") > s.count(")") + s.count("]")
    return out


def _markdown_rows(text: str, name: str) -> tuple[list[str], list[RawRow]]:
    """The pipe tables of a Markdown text (fenced code skipped), as :func:`_choose` picks."""
    tables: list[tuple[list[str], list[RawRow]]] = []
    block: list[tuple[int, list[str]]] = []
    bad: list[int] = []

    def flush() -> None:
        if not block:
            return
        if len(block) >= 2 and all(re.fullmatch(r":?-+:?", c.strip()) for c in block[1][1]):
            tables.append((block[0][1], [(f"line {n}", cells) for n, cells in block[2:]]))
        else:
            bad.append(block[0][0])
        block.clear()

    fence = False
    for number, line in enumerate(text.splitlines(), 1):
        s = line.strip()
        if s.startswith(("```", "~~~")):
            flush()
            fence = not fence
        elif s.startswith("|") and not fence:
            body = s[1:-1] if s.endswith("|") and len(s) > 1 else s[1:]
            block.append((number, [c.strip() for c in re.split(r"(?<!\\)\|", body)]))
        else:
            flush()
    flush()
    if not tables and bad:
        raise InputError(
            f"{name}, line {bad[0]}: a pipe table needs a heading row and a |---| separator row",
            "answer",
        )
    if not tables:
        raise InputError(f"{name}: no pipe table found", "answer")
    return _choose(tables, name)


def _choose(
    tables: list[tuple[list[str], list[RawRow]]], name: str
) -> tuple[list[str], list[RawRow]]:
    """The step table among a document's tables: the one with pixels that names the most
    known columns (the first on a tie), and the rows of the later tables with the same columns
    (an ellipse's region 2); tables of other columns (a symmetry table) are left out."""
    known = [[field_of(str(h))[0] for h in heads] for heads, _ in tables]
    steps = [i for i, f in enumerate(known) if _PIXEL_FIELDS & set(f)]
    if not steps:
        return tables[0]
    best = max(steps, key=lambda i: (len({f for f in known[i] if f}), -i))
    headers, rows = tables[best][0], list(tables[best][1])
    for i in range(best + 1, len(tables)):
        if known[i] == known[best]:
            rows += tables[i][1]
            _check_rows(rows, name)
    return headers, rows


_RULE = re.compile(r"^ *-+(?: {2,}-+)+ *$", re.MULTILINE)
"""The rule under a plain-text table's heading: runs of dashes, one per column."""
_SEPARATOR = re.compile(r"^[^\S\n]*(?:\|[^\S\n]*)?:?-+:?\s*\|", re.MULTILINE)
r"""A Markdown table's separator row (``|---|:--:|``). Its spaces before the dashes are the
line's own, one run before the ``|`` and one after (``^\s*\|?\s*`` tried every split of every
run of blank lines: 3,000 blank lines took over a minute)."""
_PIPE_LINE = re.compile(r"^[^\S\n]*\|", re.MULTILINE)
"""A line starting with ``|`` (after its own spaces)."""
_TOKEN = re.compile(r"\S+(?: \S+)*")


def _plain_rows(text: str, name: str) -> tuple[list[str], list[RawRow]]:
    """scanconv's plain text (``-f plain``): the first table under a dash rule whose heading
    names the pixels; each cell goes to the column its text overlaps most.

    >>> _plain_rows("k  (x, y)\\n-  ------\\n0  (2, 2)\\n1  (3, 3)\\n\\nend\\n", "a.txt")
    (['k', '(x, y)'], [('line 3', ['0', '(2, 2)']), ('line 4', ['1', '(3, 3)'])])
    """
    lines = text.splitlines()
    tables: list[tuple[list[str], list[RawRow]]] = []
    for i, line in enumerate(lines):
        if i == 0 or not _RULE.fullmatch(line):
            continue
        spans = [(m.start(), m.end()) for m in re.finditer(r"-+", line)]
        rows: list[RawRow] = []
        for n in range(i + 1, len(lines)):
            if not lines[n].strip():
                break
            rows.append((f"line {n + 1}", _spread(lines[n], spans)))
            _check_rows(rows, name)
        tables.append((_spread(lines[i - 1], spans), rows))
    assert tables  # the caller found a rule
    return _choose(tables, name)


def _spread(line: str, spans: list[tuple[int, int]]) -> list[str]:
    """The cells of a plain-text row: each run of text to the column it overlaps most."""
    cells = [""] * len(spans)
    for m in _TOKEN.finditer(line):
        a, b = m.span()
        overlap = [min(b, e) - max(a, s) for s, e in spans]
        best = max(range(len(spans)), key=lambda j: (overlap[j], -abs(spans[j][0] - a)))
        cells[best] = (cells[best] + " " + m.group(0)).strip()
    return cells


_JSON_DIGITS = 4300
"""Most digits of a JSON number a table may hold (Python's own limit on turning text into an
integer; no cell of a step table comes near it)."""


class _LongNumber(Exception):
    """A JSON number longer than :data:`_JSON_DIGITS` digits (its length in ``args[0]``)."""


def _json_int(text: str) -> int:
    """A JSON integer, or :class:`_LongNumber` for one too long to be a table's cell.

    >>> _json_int("-12")
    -12
    >>> _json_int("9" * 5000)
    Traceback (most recent call last):
    ...
    scanconv.marking.student_table._LongNumber: 5000
    """
    digits = len(text.lstrip("-"))
    if digits > _JSON_DIGITS:
        raise _LongNumber(digits)
    return int(text)


def _json_rows(text: str, name: str) -> tuple[list[str], list[RawRow]]:
    try:
        data = json.loads(text, parse_int=_json_int)
    except _LongNumber as err:
        raise InputError(
            f"{name}: a number of {err.args[0]:,} digits (a table's cell has at most "
            f"{_JSON_DIGITS:,})",
            "answer",
        ) from None
    except json.JSONDecodeError as err:
        raise InputError(
            f"{name}, line {err.lineno}: not valid JSON ({err.msg})", "answer"
        ) from None
    except RecursionError:
        raise InputError(f"{name}: JSON nested too deeply", "answer") from None
    except ValueError as err:  # an integer of more than 4,300 digits, for one
        raise InputError(f"{name}: not valid JSON ({_short(str(err))})", "answer") from None
    if isinstance(data, dict):
        data = data.get("steps", data.get("rows"))
    if not isinstance(data, list) or not all(isinstance(r, dict) for r in data):
        raise InputError(
            f'{name}: JSON must be a list of row objects, or scanconv\'s own JSON with "steps"',
            "answer",
        )
    headers: list[str] = []
    for r in data:
        headers.extend(k for k in r if k not in headers)
    rows: list[RawRow] = []
    for i, r in enumerate(data, 1):
        rows.append((f"row {i}", [r.get(h) for h in headers]))
        _check_rows(rows, name)
    return headers, rows


def _check_rows(rows: list[RawRow], name: str) -> None:
    if len(rows) > MAX_TABLE_ROWS:
        raise InputError(
            f"{name}: more than {MAX_TABLE_ROWS} rows (at most {MAX_TABLE_ROWS})", "answer"
        )


# --- columns and cells ------------------------------------------------------------------------


class _Heading(NamedTuple):
    """What a table's heading row says: each column's field (``None``: not read), whether a
    heading says ``k+1``, the headings read as nothing, and where each field is."""

    mapped: list[str | None]
    after: bool
    ignored: list[str]
    seen: dict[str, int]


def _read_heading(name: str, headers: list[str], raw: list[RawRow]) -> _Heading:
    """Each column's field; two columns read as one field must hold the same values."""
    out = _Heading([], False, [], {})
    after = False
    for i, h in enumerate(headers):
        heading = str(h)
        field, says_after = field_of(heading)
        after = after or says_after
        if field is not None and field in out.seen:
            j = out.seen[field]
            if any(_text(c, i) != _text(c, j) for _, c in raw):
                raise InputError(
                    f"{name}: two columns are both read as {field}: "
                    f"{str(headers[j])!r} and {heading!r}",
                    "answer",
                )
            field = None  # the same values twice (a pixel and its rounding): read once
        if field is None:
            if heading.strip():
                out.ignored.append(heading.strip())
        else:
            out.seen[field] = i
        out.mapped.append(field)
    return out._replace(after=after)


def _check_fields(name: str, headers: list[str], fields: set[str], seen: dict[str, int]) -> None:
    """A coordinate needs the other one; some column must hold the pixels."""
    if not {"xy", "pxy"} & fields:
        for a, b in (("x", "y"), ("px", "py"), ("y", "x"), ("py", "px")):
            # a coordinate needs the other one, plain or rounded (x next to round(y))
            if a in fields and not {b, "p" + b[-1], b[-1]} & fields:
                raise InputError(
                    f"{name}: a column {str(headers[seen[a]])!r} but no column for {b[-1]}",
                    "answer",
                )
    if not _PIXEL_FIELDS & fields:
        named = [repr(_short(str(h).strip())) for h in headers if str(h).strip()]
        found = ", ".join(named[:8]) + (f" and {len(named) - 8} more" if len(named) > 8 else "")
        raise InputError(
            f"{name}: no column for the pixels among the columns {found}; it needs one like "
            "'(x, y)', 'Pixel Plotted (x, y)' or two columns 'x' and 'y' "
            "(p_k, Decision and p_{k+1} are read too)",
            "answer",
        )


def _short(text: str, most: int = 60) -> str:
    """A text cut to ``most`` characters for a message (one line stays readable).

    >>> _short("x" * 100, 10)
    'xxxxxxxxx…'
    """
    return text if len(text) <= most else text[: most - 1] + "…"


def _row(name: str, where: str, cells: list[Any], mapped: list[str | None]) -> Row:
    """One row's values by field (the row as long as the heading)."""
    width = len(mapped)
    extra = cells[width:]
    if len(cells) < width or any(str(c).strip() for c in extra if c is not None):
        raise InputError(
            f"{name}, {where}: {len(cells)} cells where the heading has {width} columns", "answer"
        )
    values: dict[str, Value] = {}
    for field, text in zip(mapped, cells, strict=False):
        if field == "decision":
            values[field] = move_of(text)
        elif field is not None and field != "k":
            values[field] = _value(text, field, name, where)
    return Row(where, values)


def _build(name: str, headers: list[str], raw: list[RawRow]) -> StudentTable:
    if not headers or not any(str(h).strip() for h in headers):
        raise InputError(f"{name}: no heading row", "answer")
    head = _read_heading(name, headers, raw)
    fields = tuple(f for f in head.mapped if f is not None)
    _check_fields(name, headers, set(fields), head.seen)
    if not raw:
        raise InputError(f"{name}: the table has a heading but no rows", "answer")
    rows = tuple(_row(name, where, cells, head.mapped) for where, cells in raw)
    return StudentTable(name, fields, head.after, rows, tuple(head.ignored))


def _text(cells: list[Any], i: int) -> str:
    return " ".join(str(cells[i]).split()) if i < len(cells) and cells[i] is not None else ""


_PAIR = re.compile(r"[(\[]?\s*([^,;\s()\[\]]+)(?:\s+(?:[,;]\s*)?|[,;]\s*)([^,;\s()\[\]]+)\s*[)\]]?")
r"""A pixel ``(3, 4)``, ``[3; 4]`` or ``3 4``: two numbers parted by a comma, a semicolon or
spaces, each space of the parting in one place (``\s*[,;\s]\s*`` tried every split of a run
of spaces: a cell with 100,000 took minutes)."""


def _value(raw: Any, field: str, name: str, where: str) -> Value:
    """One cell as a :data:`Value`.

    >>> _value("(3,3)", "xy", "a", "line 2") == _value("3, 3", "xy", "a", "line 2")
    True
    >>> _value("2.500", "p", "a", "line 2"), _value("\\u22125/2", "p", "a", "line 2").value
    (Cell(value=Fraction(5, 2), places=3), Fraction(-5, 2))
    """
    pair = field in ("xy", "pxy")
    if raw is None:
        return None
    if isinstance(raw, bool):
        raise InputError(f"{name}, {where}: {raw!r} is not a number", "answer")
    if isinstance(raw, list):
        if not pair or len(raw) != 2:
            raise InputError(f"{name}, {where}: {raw!r} is not a number", "answer")
        return (_number(raw[0], name, where), _number(raw[1], name, where))
    text = str(raw).strip().strip("$*`").strip()
    if text.lower() in _EMPTY:
        return None
    if pair:
        m = _PAIR.fullmatch(text)
        if m is None:
            raise InputError(f"{name}, {where}: {text[:40]!r} is not a pixel like (3, 4)", "answer")
        return (_number(m.group(1), name, where), _number(m.group(2), name, where))
    return _number(text, name, where)


def cell_of(text: str, field: str, name: str, where: str) -> Value:
    """One cell as a student wrote it, read as a table's cell of ``field`` is (``decision``:
    a move, ``xy``: a pixel, else a number); ``name`` and ``where`` name it in messages.

    >>> cell_of("East", "decision", "a", "step 1"), cell_of("\u22128", "p", "a", "step 1")
    ('E', Cell(value=Fraction(-8, 1), places=0))
    """
    return move_of(text) if field == "decision" else _value(text, field, name, where)


def _number(raw: Any, name: str, where: str) -> Cell:
    if isinstance(raw, (int, float)) and not isinstance(raw, bool):
        raw = repr(raw)
    text = str(raw).strip().strip("$*`").strip().replace("\u2212", "-")
    try:
        value = parse_number(text, CELL_LIMIT)
    except ValueError as err:
        raise InputError(f"{name}, {where}: {err}", "answer") from None
    places = len(text.split(".", 1)[1]) if "." in text and "e" not in text.lower() else 0
    return Cell(value, places)
